#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <numbers>

#include <nlohmann/json.hpp>
#include <openvdb/openvdb.h>
#include <openvdb/tools/MeshToVolume.h>
#include <tbb/global_control.h>

#include "common/pipeline.h"
#include "common/io/output_file.h"
#include "common/scene_io/scene_load.h"
#include "cpu/backend.h"
#include "gpu/backend.h"
#include "tools/bench.h"

namespace voxgi::tools {
namespace {

// A closed, bumpy sphere with about `triangles` triangles (UV sphere, 2 * slices * (stacks - 1)).
Mesh bumpySphere(int triangles) {
  const int stacks = std::max(3, int(std::sqrt(triangles / 4.0)));
  const int slices = std::max(3, triangles / (2 * (stacks - 1)));
  Mesh mesh;
  mesh.name = "generated sphere";
  mesh.positions.push_back({0.0, 0.0, 1.0});
  for (int i = 1; i < stacks; ++i)
    for (int j = 0; j < slices; ++j) {
      const double theta = std::numbers::pi * i / stacks, phi = 2.0 * std::numbers::pi * j / slices;
      const double r = 1.0 + 0.05 * std::sin(7.0 * theta) * std::sin(5.0 * phi);
      mesh.positions.push_back(r * glm::dvec3(std::sin(theta) * std::cos(phi),
                                              std::sin(theta) * std::sin(phi), std::cos(theta)));
    }
  mesh.positions.push_back({0.0, 0.0, -1.0});
  auto ring = [&](int i, int j) { return 1u + unsigned((i - 1) * slices + (j % slices)); };
  const auto last = unsigned(mesh.positions.size() - 1);
  for (int j = 0; j < slices; ++j) {
    mesh.triangles.emplace_back(0u, ring(1, j), ring(1, j + 1));
    mesh.triangles.emplace_back(last, ring(stacks - 1, j + 1), ring(stacks - 1, j));
  }
  for (int i = 1; i + 1 < stacks; ++i)
    for (int j = 0; j < slices; ++j) {
      mesh.triangles.emplace_back(ring(i, j), ring(i + 1, j), ring(i + 1, j + 1));
      mesh.triangles.emplace_back(ring(i, j), ring(i + 1, j + 1), ring(i, j + 1));
    }
  return mesh;
}

// The median seconds of meshToVolume at the band width, and the bytes its grid holds.
struct PeerRun {
  double seconds;
  uint64_t bytes = 0;
};
PeerRun meshToVolumeRun(const Scene& scene, int repeats, float bandWidth) {
  std::vector<openvdb::Vec3s> points;
  std::vector<openvdb::Vec3I> tris;
  for (const Mesh& m : scene.meshes) {
    const auto base = static_cast<unsigned>(points.size());
    // The adapter's points are in the grid's index space (MeshDataAdapter::getIndexSpacePoint), not
    // in world space: voxgi's voxel coordinates, so that both voxelize the mesh at the same size.
    for (const auto& p : m.positions) {
      const glm::dvec3 v = scene.grid.toVoxel(p);
      points.emplace_back(float(v.x), float(v.y), float(v.z));
    }
    for (const auto& t : m.triangles) tris.emplace_back(base + t.x, base + t.y, base + t.z);
  }
  const auto transform = openvdb::math::Transform::createLinearTransform(scene.grid.voxelSize());
  openvdb::tools::QuadAndTriangleDataAdapter<openvdb::Vec3s, openvdb::Vec3I> mesh(points, tris);
  PeerRun run;
  run.seconds = medianSeconds(repeats, [&] {
    auto grid =
        openvdb::tools::meshToVolume<openvdb::FloatGrid>(mesh, *transform, bandWidth, bandWidth);
    if (grid->activeVoxelCount() == 0) throw std::runtime_error("meshToVolume produced nothing");
    run.bytes = grid->memUsage();
  });
  return run;
}

}  // namespace

void addBenchOptions(CLI::App& cmd, BenchOptions& o) {
  cmd.add_option("--resolutions", o.resolutions, "grid resolutions")->delimiter(',');
  cmd.add_option("--bunny", o.bunny, "first mesh (default scenes/bunny.obj)");
  cmd.add_option("--triangles", o.generatedTriangles, "triangles of the generated mesh (0: skip)");
  cmd.add_option("--repeat", o.repeats, "runs per measurement (the median is reported)")
      ->check(CLI::Range(1, 100));
  addGpuColumnOptions(cmd, o.gpu, o.gl);
  cmd.add_option("--json", o.json, "also write the figures as JSON");
}

int runBenchVoxelize(const BenchOptions& o) {
  openvdb::initialize();
  std::vector<Scene> meshes;
  meshes.push_back(loadScene(o.bunny));
  if (o.generatedTriangles > 0) {
    Scene s;
    s.file = "generated";
    s.materials.push_back(Material{});
    s.meshes.push_back(bumpySphere(o.generatedTriangles));
    addDefaultLights(s);  // an unlit scene's plan leaves voxelize out (EffectPlan::dark)
    meshes.push_back(std::move(s));
  }
  std::unique_ptr<gpu::GlContext> context;
  if (o.gpu) {
    try {
      context = gpu::GlContext::create(gpu::parseGlPlatform(o.gl));
    } catch (const std::exception& e) {
      std::cerr << "bench: no GPU column: " << e.what() << "\n";
    }
  }
  nlohmann::json rows = nlohmann::json::array();
  std::cout << "| mesh | triangles | N | cpu 1 thread s | cpu 2 threads s | speed-up | gpu ("
            << (context ? context->renderer() : "none") << ") s | meshToVolume band 3, 2 threads s"
            << " | meshToVolume band 1, 2 threads s | cpu 2 threads / meshToVolume band 3"
            << " | cpu volumes MB | meshToVolume band 3 MB |\n"
            << "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  Settings settings;
  const Technique& vct = findTechnique("vct");  // any technique runs the shared voxelize stage
  const StageSpec& voxelize = stageSpec(StageId::common_voxelize);
  cpu::CpuBackend cpuBackend;
  std::unique_ptr<gpu::GpuBackend> gpuBackend;
  if (context) gpuBackend = std::make_unique<gpu::GpuBackend>(*context);
  for (Scene& scene : meshes) {
    for (int n : o.resolutions) {
      scene.grid = fitGrid(scene.bounds(), n);
      // The bytes of the buffers the stage hands on, as a render plans them.
      uint64_t volumeBytes = 0;
      auto runCpu = [&](size_t threads) {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
        return medianSeconds(o.repeats, [&] {
          const VoxelTriangles tris = prepareVoxelTriangles(scene, scene.grid);
          BufferSet out;
          const StageContext ctx{vct, scene, settings, tris};
          if (!ctx.plan.runs(StageId::common_voxelize))
            throw std::runtime_error("bench: the plan leaves voxelize out for " + scene.file);
          runStage(cpuBackend, voxelize, ctx, out);
          volumeBytes = 0;
          for (const auto& [id, b] : out) volumeBytes += b.words.size() * sizeof(uint32_t);
        });
      };
      const double cpu1 = runCpu(1), cpu2 = runCpu(2);
      double gpuSeconds = std::nan("");
      if (context) {
        try {
          gpuSeconds = medianSeconds(o.repeats, [&] {
            const VoxelTriangles tris = prepareVoxelTriangles(scene, scene.grid);
            BufferSet out;
            runStage(*gpuBackend, voxelize, StageContext{vct, scene, settings, tris}, out);
          });
        } catch (const std::exception& e) {
          std::cerr << "bench: gpu at " << n << "^3 skipped: " << e.what() << "\n";
        }
      }
      tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
      const PeerRun band3 = meshToVolumeRun(scene, o.repeats, 3.0f);
      const double peer3 = band3.seconds;
      const double peer1 = meshToVolumeRun(scene, o.repeats, 1.0f).seconds;
      const double mb = 1e-6;
      const std::string name = scene.file == "generated" ? "generated sphere" : scene.file;
      std::cout << std::fixed << std::setprecision(3) << "| " << name << " | "
                << scene.triangleCount() << " | " << n << " | " << cpu1 << " | " << cpu2 << " | "
                << std::setprecision(2) << cpu1 / cpu2 << "x | " << std::setprecision(3)
                << gpuSeconds << " | " << peer3 << " | " << peer1 << " | " << std::setprecision(2)
                << cpu2 / peer3 << " | " << std::setprecision(1) << double(volumeBytes) * mb
                << " | " << double(band3.bytes) * mb << " |\n"
                << std::flush;
      rows.push_back(
          {{"mesh", name},
           {"triangles", scene.triangleCount()},
           {"resolution", n},
           {"cpu_1_thread_s", cpu1},
           {"cpu_2_threads_s", cpu2},
           {"gpu_s", std::isnan(gpuSeconds) ? nlohmann::json() : nlohmann::json(gpuSeconds)},
           {"mesh_to_volume_band3_s", peer3},
           {"mesh_to_volume_band1_s", peer1},
           {"cpu_volumes_bytes", volumeBytes},
           {"mesh_to_volume_band3_bytes", band3.bytes}});
    }
  }
  if (!o.json.empty()) writeFileAtomically(o.json, rows.dump(2) + "\n");
  return 0;
}

}  // namespace voxgi::tools

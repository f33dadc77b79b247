// voxgi bench svo (docs/benchmarks.md): the point cloud's way into the octree on the CPU — PLY
// load, samples, structure, leaf sums — at each depth and thread count, side by side with
// OpenVDB's point rasterisation (createPointDataGrid, then rasterizeTrilinear of the colour) at
// the same voxel size, and the octree's memory against [Salm 2015, Table 5.1]'s Cornell box; then
// every stage of the technique through the runner on the CPU and the GPU (OSMesa), the Cornell
// box's walls being the cloud.
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>

#include <nlohmann/json.hpp>
#include <tbb/global_control.h>

#include "common/io/output_file.h"
#include "common/scene_io/scene_load.h"
#include "common/scene_io/point_cloud_ply.h"
#include "common/surface_sampling.h"
#include "common/svo/samples.h"
#include "common/voxel_triangles.h"
#include "cpu/backend.h"
#include "cpu/svo/octree.h"
#include "gpu/backend.h"
#include "gpu/svo/octree.h"
#include "shaders/shared/svo/svo_layout.h"
#include "tools/bench.h"
#include "tools/openvdb_points.h"

namespace voxgi::tools {
namespace {

// Bytes an element of buffer `id` takes as declared (common/svo/stages.inc).
uint64_t elementBytes(BufferId id) {
  const BufferSpec& b = bufferSpec(id);
  return uint64_t(b.components) * (b.type == ScalarType::f16 ? 2u : 4u);
}

// Bytes of the technique's tree buffers at this tree, as a run holds them without what voxgi diff
// and dump keep besides (the leaf sums, the per-leaf direct and gathered light): the structure's
// words; per leaf (8 a leaf tile) the decoded leaves and the radiance; per leaf tile the gathered
// light's 3^3 brick; per node (8 a node tile) six RGBA faces.
uint64_t octreeBytes(const cpu::svo::Octree& o) {
  const uint64_t structure = (o.nodes.size() + o.tiles.size() + o.leafTiles.size()) * 4;
  uint64_t perLeaf = 0;
  for (const BufferId id : {BufferId::svo_build_leaves, BufferId::svo_propagate_radiance})
    perLeaf += elementBytes(id);
  const uint64_t perLeafTile =
      8 * perLeaf +
      uint64_t(shared::kBrickTexels) * elementBytes(BufferId::svo_propagate_gathered_bricks);
  const uint64_t perNodeTile = 8 * elementBytes(BufferId::svo_mip_node_faces);
  return structure + o.leafTileCount() * perLeafTile + o.tileCount() * perNodeTile;
}

}  // namespace

void addBenchSvoOptions(CLI::App& cmd, BenchSvoOptions& o) {
  cmd.add_option("--cloud", o.cloud,
                 "point-cloud PLY (default: scenes/cornell_box.json sampled with voxgi sample's "
                 "noise and density gradient)");
  cmd.add_option("--points", o.points, "points of the generated cloud")
      ->check(CLI::Range(int64_t(1000), int64_t(1) << 28));
  cmd.add_option("--depths", o.depths, "octree depths (leaves 2^depth per side)")
      ->delimiter(',')
      ->check(CLI::Range(2, 10));
  cmd.add_option("--threads-list", o.threads, "CPU thread counts")->delimiter(',');
  cmd.add_option("--stage-depths", o.stageDepths,
                 "octree depths at which every stage of the technique is timed")
      ->delimiter(',')
      ->check(CLI::Range(2, 10));
  addGpuColumnOptions(cmd, o.gpu, o.gl);
  cmd.add_option("--repeat", o.repeats, "runs per measurement (the median is reported)")
      ->check(CLI::Range(1, 100));
  cmd.add_option("--json", o.json, "also write the figures as JSON");
}

namespace {

// Every stage of svo on the Cornell box whose walls and blocks are `cloud` (its light a mesh), at
// 2^depth leaves and 256^2 pixels: stage -> seconds per backend (the GPU's with a context).
nlohmann::json timeTechnique(const PointCloud& cloud, const std::vector<int>& depths,
                             gpu::GlContext* context, int repeats) {
  std::cout << "\n| depth | backend | stage | seconds |\n|---|---|---|---|\n";
  nlohmann::json rows = nlohmann::json::array();
  const Technique& svo = findTechnique("svo");
  for (const int depth : depths) {
    Scene scene = loadScene("scenes/cornell_box.json");
    std::erase_if(scene.meshes,
                  [&](const Mesh& m) { return !scene.materials[m.material].emissive(); });
    scene.pointClouds = {cloud};
    scene.pointClouds.front().material = uint32_t(scene.materials.size());
    scene.materials.push_back(Material{"cloud"});
    scene.grid.resolution = 1 << depth;
    const Settings settings = techniqueDefaults(svo);
    const VoxelTriangles tris = prepareVoxelTriangles(scene, scene.grid);
    const StageContext ctx{svo, scene, settings, tris};
    cpu::CpuBackend cpuBackend;
    std::vector<std::pair<std::string, std::vector<std::pair<std::string, double>>>> runs;
    runs.emplace_back("cpu", timeStages(ctx, repeats, cpuBackend));
    if (context) {
      gpu::GpuBackend gpuBackend(*context);
      runs.emplace_back("gpu " + std::string(gpu::glPlatformName(context->platform())),
                        timeStages(ctx, repeats, gpuBackend));
    }
    for (const auto& [backend, stages] : runs)
      for (const auto& [stage, seconds] : stages) {
        std::cout << "| " << depth << " | " << backend << " | " << stage << " | " << std::fixed
                  << std::setprecision(3) << seconds << " |\n"
                  << std::flush;
        rows.push_back({{"depth", depth}, {"backend", backend}, {"stage", stage}, {"s", seconds}});
      }
  }
  return rows;
}

}  // namespace

int runBenchSvo(const BenchSvoOptions& o) {
  std::string cloudFile = o.cloud;
  if (cloudFile.empty()) {
    const Scene box = loadScene("scenes/cornell_box.json");
    SurfaceSampling sampling;
    sampling.points = size_t(o.points);
    sampling.noise = 0.5;  // mm: a scanner's
    sampling.gradientAxis = 1;
    sampling.gradientRatio = 0.5;
    cloudFile = (std::filesystem::temp_directory_path() / "voxgi_bench_svo.ply").string();
    writePointCloudPly(sampleSurfaces(box, sampling), cloudFile);
  }
  Scene scene;
  const double loadSeconds = medianSeconds(o.repeats, [&] { scene = loadScene(cloudFile); });
  const double millions = double(scene.pointCount()) / 1e6;
  std::cout << "PLY load: " << scene.pointCount() << " points from " << cloudFile << " in "
            << std::fixed << std::setprecision(3) << loadSeconds << " s, " << loadSeconds / millions
            << " s per million points\n\n";
  std::cout << "| depth | threads | samples s | structure s | leaf sums s | build s | OpenVDB "
               "points s | build / OpenVDB | node tiles | leaf tiles | octree MB | / Salm's "
               "Cornell box |\n"
            << "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  nlohmann::json rows = nlohmann::json::array();
  std::unique_ptr<gpu::GlContext> context;
  if (o.gpu) context = gpu::GlContext::create(gpu::parseGlPlatform(o.gl));
  for (const int depth : o.depths) {
    scene.grid = fitGrid(scene.bounds(), 1 << depth);
    const double leaf = scene.grid.size / double(1 << depth);
    for (const int threads : o.threads) {
      tbb::global_control limit(tbb::global_control::max_allowed_parallelism, size_t(threads));
      svo::SampleSet set;
      const double samplesSeconds = medianSeconds(o.repeats, [&] {
        set = svo::prepareSamples(scene, depth, 4.0, 1, EmitterLighting::voxels);
      });
      std::vector<double> structure, sums;
      cpu::svo::Octree octree;
      for (int r = 0; r < o.repeats; ++r) {
        cpu::svo::SampleHomes homes;
        structure.push_back(elapsedSeconds(
            [&] { octree = cpu::svo::buildOctree(set.samples, depth, cloudFile, &homes); }));
        sums.push_back(elapsedSeconds([&] {
          cpu::svo::accumulateLeaves(octree, set.samples, set.weightScale, cloudFile, &homes);
        }));
      }
      const double build = median(structure) + median(sums);
      const double peer = openVdbPointsSeconds(scene.pointClouds.front(), leaf, o.repeats);
      const double megabytes = double(octreeBytes(octree)) / 1e6;
      // [Salm 2015, Table 5.1]: the Cornell box's whole SVO at 800x600 (the default cloud is the
      // Cornell box too).
      const double salm = depth == 7 ? 68.3 : depth == 8 ? 273.2 : std::nan("");
      std::cout << std::setprecision(3) << "| " << depth << " | " << threads << " | "
                << samplesSeconds << " | " << median(structure) << " | " << median(sums) << " | "
                << build << " | " << peer << " | " << std::setprecision(2) << build / peer << " | "
                << octree.tileCount() << " | " << octree.leafTileCount() << " | "
                << std::setprecision(1) << megabytes << " | " << std::setprecision(2)
                << megabytes / salm << " |\n"
                << std::flush;
      rows.push_back(
          {{"depth", depth},
           {"threads", threads},
           {"points", scene.pointCount()},
           {"samples_s", samplesSeconds},
           {"structure_s", median(structure)},
           {"leaf_sums_s", median(sums)},
           {"openvdb_points_s", std::isnan(peer) ? nlohmann::json() : nlohmann::json(peer)},
           {"node_tiles", octree.tileCount()},
           {"leaf_tiles", octree.leafTileCount()},
           {"octree_bytes", octreeBytes(octree)}});
    }
    if (context) {  // the GPU's build: upload, atomics, read-back in the canonical form
      const svo::SampleSet set = svo::prepareSamples(scene, depth, 4.0, 1, EmitterLighting::voxels);
      const double gpuBuild = medianSeconds(o.repeats, [&] {
        gpu::svo::buildOctree(*context, set.samples, depth, set.weightScale, cloudFile);
      });
      std::cout << std::setprecision(3) << "| " << depth << " | gpu " << o.gl << " |  |  |  | "
                << gpuBuild << " |  |  |  |  |  |  |\n"
                << std::flush;
      rows.push_back({{"depth", depth}, {"threads", "gpu " + o.gl}, {"build_s", gpuBuild}});
    }
  }
  const nlohmann::json stages =
      timeTechnique(scene.pointClouds.front(), o.stageDepths, context.get(), o.repeats);
  if (!o.json.empty())
    writeFileAtomically(o.json, nlohmann::json({{"ply_load_s", loadSeconds},
                                                {"points", scene.pointCount()},
                                                {"rows", rows},
                                                {"stages", stages}})
                                        .dump(2) +
                                    "\n");
  return 0;
}

}  // namespace voxgi::tools

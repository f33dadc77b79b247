// The rsm stage and what inject and shade make of it (docs/stages/lpv/rsm.md): a texel's
// flux carries the surface's cosine once (T14), a point light's six faces catch all its flux, a
// spot's map its cone's, the RSM's VPLs reach the volume, depth is the distance along the view's
// axis, and the depth as shadow map darkens exactly what an occluder hides.
#include <cmath>

#include <gtest/gtest.h>

#include "common/lpv/inject.h"
#include "common/lpv/rsm.h"
#include "common/lpv/sh_buffers.h"
#include "common/voxel_triangles.h"
#include "shaders/shared/lpv/rsm_kernel.h"
#include "tests/test_scenes.h"

namespace voxgi::test {
namespace {

const Technique& lpvTechnique() {
  return findTechnique("lpv");
}

// Per colour, the sum of an rsm stage buffer's components.
glm::dvec3 fluxSum(const Buffer& flux) {
  glm::dvec3 sum(0.0);
  for (size_t e = 0; e < flux.elementCount(); ++e) sum += glm::dvec3(flux.vec3At(e));
  return sum;
}

// The six faces of the cube [lo, hi]^3.
std::vector<Triangle> closedBox(double lo, double hi) {
  std::vector<Triangle> out;
  for (int axis = 0; axis < 3; ++axis)
    for (double at : {lo, hi})
      for (const Triangle& t : quad(axis, at, {lo, lo}, {hi, hi})) out.push_back(t);
  return out;
}

Material grey(glm::vec3 albedo) {
  Material m;
  m.albedo = albedo;
  return m;
}

Light pointLight(glm::dvec3 at, glm::vec3 intensity) {
  Light l;
  l.type = Light::Type::point;
  l.position = at;
  l.intensity = intensity;
  return l;
}

// Adds `triangles` as a mesh of their own, of an emissive material (albedo 0).
void addEmitter(Scene& scene, const std::vector<Triangle>& triangles, glm::vec3 radiance) {
  Material emitter;
  emitter.albedo = glm::vec3(0.0f);
  emitter.emission = radiance;
  scene.materials.push_back(emitter);
  Mesh mesh;
  for (const Triangle& t : triangles) {
    const auto first = uint32_t(mesh.positions.size());
    mesh.positions.insert(mesh.positions.end(), t.begin(), t.end());
    mesh.triangles.emplace_back(first, first + 1, first + 2);
  }
  mesh.material = uint32_t(scene.materials.size() - 1);
  scene.meshes.push_back(mesh);
}

// A square [lo, hi]^2 of the plane y = at, wound to face -y.
std::vector<Triangle> downwardSquare(double at, double lo, double hi) {
  std::vector<Triangle> out = quad(1, at, {lo, lo}, {hi, hi});
  for (Triangle& t : out) std::swap(t[1], t[2]);
  return out;
}

// Direct light on a floor at y = 0.1 under a blocker, seen from between them looking down (the
// whole shadow in view), with a 128^2 RSM.
BufferSet shadeFloor(Scene scene) {
  scene.camera.position = {0.5, 0.45, 0.5};
  scene.camera.lookAt = {0.5, 0.0, 0.5};
  scene.camera.up = {0, 0, -1};
  scene.camera.fovYDeg = 100.0;
  scene.camera.width = scene.camera.height = 64;
  Settings settings;
  settings.lpv.rsmResolution = 128;
  settings.lpv.steps = 1;
  return runCpuUntil(lpvTechnique(), scene, settings, "shade");
}

// T14, the tilt at which Martin's Φ = A_s I_s Ω_s (n_s·l)+ counts the cosine twice (specs A4):
// a plane that fills a directional light's whole box reflects albedo x irradiance x the box's
// cross-section at any tilt. With the cosine counted twice the sum would fall as cos(theta).
TEST(Rsm, TiltedPlaneReflectsTheCosineOnce) {
  const glm::vec3 albedo(0.5f, 0.25f, 1.0f);
  for (double degrees : {0.0, 30.0, 60.0, 75.0}) {
    const double t = degrees * M_PI / 180.0, c = std::cos(t), s = std::sin(t);
    // Through the grid's centre, tilted about x, 8 units square (the box is 1.7 units wide).
    const auto at = [&](double u, double v) {
      return glm::dvec3(0.5 + u, 0.5 + v * s, 0.5 + v * c);
    };
    const std::vector<Triangle> plane{{at(-4, -4), at(4, -4), at(4, 4)},
                                      {at(-4, -4), at(4, 4), at(-4, 4)}};
    Scene scene = makeScene(plane, unitGrid(16), grey(albedo));
    Light sun;
    sun.type = Light::Type::directional;
    sun.direction = {0.0, -1.0, 0.0};  // at cosine cos(theta) to the plane's normal
    sun.intensity = {2.0f, 2.0f, 2.0f};
    scene.lights.push_back(sun);
    Settings settings;
    settings.lpv.rsmResolution = 64;
    const BufferSet out = runCpuUntil(lpvTechnique(), scene, settings, "rsm");
    const lpv::RsmSetup rsm = lpv::prepareRsm(scene, settings);
    const double side = 2.0 * rsm.views[0].forward.w * scene.grid.voxelSize();
    const glm::dvec3 expected = glm::dvec3(albedo) * 2.0 * side * side;
    const glm::dvec3 sum = fluxSum(out.at(BufferId::lpv_rsm_flux));
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(sum[k], expected[k], 1e-5 * expected[k]) << degrees << " degrees, colour " << k;
  }
}

// A point light inside a closed box: the six faces' texels together reflect albedo x 4 pi I. The
// midpoint rule's solid angles of a 64^2 face sum to 2 pi / 3 x (1 + 6.0e-5) (summed in double
// independently of the stage), so 2e-4 bounds float rounding on top.
TEST(Rsm, PointLightCubeMapCatchesAllItsFlux) {
  const glm::vec3 albedo(0.7f, 0.5f, 0.3f), intensity(3.0f, 1.0f, 2.0f);
  Scene scene = makeScene(closedBox(0.2, 0.8), unitGrid(16), grey(albedo));
  scene.lights.push_back(pointLight({0.43, 0.55, 0.61}, intensity));
  Settings settings;
  settings.lpv.rsmResolution = 64;
  const BufferSet out = runCpuUntil(lpvTechnique(), scene, settings, "inject");
  const glm::dvec3 sum = fluxSum(out.at(BufferId::lpv_rsm_flux));
  for (int k = 0; k < 3; ++k) {
    const double expected = albedo[k] * 4.0 * M_PI * intensity[k];
    EXPECT_NEAR(sum[k], expected, 2e-4 * expected) << "colour " << k;
  }
  // Every texel saw a wall, at a depth inside the box.
  const Buffer& depth = out.at(BufferId::lpv_rsm_depth);
  for (size_t e = 0; e < depth.elementCount(); ++e) {
    ASSERT_GT(depth.get<float>(e, 0), 0.0f) << "texel " << e;
    ASSERT_LT(depth.get<float>(e, 0), 0.6f * 16.0f * 1.0001f) << "texel " << e;
  }

  // T14: the RSM's VPLs reach the volume, sum c0 = sum of their flux x K0 (the lobe emits its
  // flux), up to the fixed point's rounding.
  const lpv::ShBuffers sh = lpv::shBuffers(settings.lpv);
  const Buffer& sums = out.at(sh.intensitySum);
  const VoxelTriangles tris = prepareVoxelTriangles(scene, scene.grid);
  const glm::vec4 scale = lpv::injectionScale(StageContext{lpvTechnique(), scene, settings, tris});
  for (int k = 0; k < 3; ++k) {
    double c0 = 0.0;
    for (size_t e = 0; e < sums.elementCount(); ++e)
      c0 += sums.get<int32_t>(e, k * 4) / double(scale[k]);
    EXPECT_NEAR(c0, sum[k] * 0.282094791773878, 1e-5 * sum[k]) << "colour " << k;
  }
}

// A spot's single frustum (or, past 120 degrees, six faces) holds its cone: the flux reflected is
// albedo x I x 2 pi (1 - cos half), up to the texels the cone's rim cuts. Each counts whole on the
// side its hit point lies, so the ~800 rim texels of a 256^2 map err by about sqrt(800) x 0.3
// texels together, 2e-4 of the cone's ~50 000 (measured: 3e-5 to 7e-5); 1e-3 bounds that.
TEST(Rsm, SpotMapCatchesItsCone) {
  const glm::vec3 albedo(0.6f, 0.6f, 0.6f), intensity(5.0f, 5.0f, 5.0f);
  for (double angle : {40.0, 100.0, 150.0}) {
    Scene scene = makeScene(closedBox(0.1, 0.9), unitGrid(16), grey(albedo));
    Light spot = pointLight({0.5, 0.5, 0.5}, intensity);
    spot.type = Light::Type::spot;
    spot.direction = glm::normalize(glm::dvec3(0.2, -1.0, 0.1));
    spot.spotAngleDeg = float(angle);
    scene.lights.push_back(spot);
    Settings settings;
    settings.lpv.rsmResolution = 256;
    const BufferSet out = runCpuUntil(lpvTechnique(), scene, settings, "rsm");
    EXPECT_EQ(lpv::rsmViewCount(scene, Settings{}), angle > 120.0 ? 6 : 1) << angle;
    const double cone = 2.0 * M_PI * (1.0 - std::cos(0.5 * angle * M_PI / 180.0));
    const double expected = albedo[0] * intensity[0] * cone;
    EXPECT_NEAR(fluxSum(out.at(BufferId::lpv_rsm_flux)).x, expected, 1e-3 * expected) << angle;
  }
}

// An emissive square (radiance L, side a) facing down inside a closed box of albedo rho, as area
// lights (emitters.mode=auto: two triangles): everything it emits, pi L a^2, lands on the walls,
// so its maps' texels reflect rho pi L a^2. Each texel's flux is E_perp at its hit, facing the
// triangle's centroid, times its cross-section seen from there, which is exact for a point light;
// for a triangle a tenth of the box's size it errs by the spread of its points' directions,
// measured +0.48 % here (against 6e-5 for a point light), so 1 % bounds it. The emitters inject no
// VPLs of their own: the volume holds the texels' flux alone.
TEST(Rsm, EmissiveTrianglesMapsCatchTheirFlux) {
  const glm::vec3 albedo(0.7f, 0.5f, 0.3f), radiance(4.0f, 2.0f, 1.0f);
  Scene scene = makeScene(closedBox(0.2, 0.8), unitGrid(16), grey(albedo));
  addEmitter(scene, downwardSquare(0.7, 0.45, 0.55), radiance);
  Settings settings;
  settings.lpv.rsmResolution = 64;
  EXPECT_EQ(lpv::rsmViewCount(scene, settings), 12) << "six faces per triangle";
  const BufferSet out = runCpuUntil(lpvTechnique(), scene, settings, "inject");
  const glm::dvec3 sum = fluxSum(out.at(BufferId::lpv_rsm_flux));
  const double area = 0.1 * 0.1;
  for (int k = 0; k < 3; ++k) {
    const double expected = albedo[k] * M_PI * radiance[k] * area;
    EXPECT_NEAR(sum[k], expected, 1e-2 * expected) << "colour " << k;
  }
  const lpv::ShBuffers sh = lpv::shBuffers(settings.lpv);
  const Buffer& sums = out.at(sh.intensitySum);
  const VoxelTriangles vt = prepareVoxelTriangles(scene, scene.grid);
  const glm::vec4 scale = lpv::injectionScale(StageContext{lpvTechnique(), scene, settings, vt});
  double c0 = 0.0;
  for (size_t e = 0; e < sums.elementCount(); ++e) c0 += sums.get<int32_t>(e, 0) / double(scale[0]);
  EXPECT_NEAR(c0, sum[0] * 0.282094791773878, 1e-4 * sum[0]) << "the texels' flux alone";
}

// Depth is the distance along the view's axis, and the normal faces the light.
TEST(Rsm, DepthIsAlongTheViewAxisAndNormalsFaceTheLight) {
  Scene scene = makeScene(quad(1, 0.2, {-2, -2}, {3, 3}), unitGrid(16), grey(glm::vec3(1.0f)));
  scene.lights.push_back(pointLight({0.4, 0.7, 0.55}, glm::vec3(1.0f)));
  Settings settings;
  settings.lpv.rsmResolution = 32;
  const BufferSet out = runCpuUntil(lpvTechnique(), scene, settings, "rsm");
  const Buffer &depth = out.at(BufferId::lpv_rsm_depth), &normal = out.at(BufferId::lpv_rsm_normal);
  const lpv::RsmSetup rsm = lpv::prepareRsm(scene, settings);
  const int r = 32;
  int seen = 0;
  for (size_t v = 0; v < rsm.views.size(); ++v) {
    const bool down = rsm.views[v].forward.y < -0.5f;
    for (int y = 0; y < r; ++y)
      for (int x = 0; x < r; ++x) {
        const size_t e = (v * r + size_t(y)) * r + size_t(x);
        const float d = depth.get<float>(e, 0);
        if (down) {
          EXPECT_NEAR(d, 0.5f * 16.0f, 1e-4f) << "the floor lies 8 cells down the axis";
        }
        if (d == 0.0f) continue;
        ++seen;
        glm::vec3 origin, dir;
        shared::rsmTexelRay(rsm.views[v], {x, y}, r, origin, dir);
        EXPECT_NEAR((origin + dir * d).y, 0.2f * 16.0f, 1e-4f) << "view " << v << " texel " << e;
        EXPECT_EQ(normal.vec3At(e), glm::vec3(0, 1, 0));
      }
  }
  EXPECT_GT(seen, r * r);
}

// Direct light with the RSM depth as shadow map: a floor under a point light, a small square
// blocker between them. Beneath the blocker the floor is dark; elsewhere it gets E cos / pi
// exactly as the light delivers it.
TEST(ShadeLpv, ShadowMapDarkensWhatAnOccluderHides) {
  std::vector<Triangle> tris = quad(1, 0.1, {-1, -1}, {2, 2});
  for (const Triangle& t : quad(1, 0.5, {0.4, 0.4}, {0.6, 0.6})) tris.push_back(t);
  Scene scene = makeScene(tris, unitGrid(32), grey(glm::vec3(0.5f)));
  const glm::dvec3 light(0.5, 0.9, 0.5);
  scene.lights.push_back(pointLight(light, glm::vec3(1.0f)));
  const BufferSet out = shadeFloor(scene);
  const Buffer &direct = out.at(BufferId::lpv_shade_direct_diffuse),
               &position = out.at(BufferId::common_gbuffer_pixel_position),
               &primitive = out.at(BufferId::common_gbuffer_primitive_id);
  const double s = scene.grid.voxelSize();
  int shadowed = 0, lit = 0;
  for (size_t e = 0; e < direct.elementCount(); ++e) {
    if (primitive.get<uint32_t>(e, 0) > 2) continue;  // the blocker itself
    const glm::dvec3 p = scene.grid.min + glm::dvec3(position.vec3At(e)) * s;
    const glm::dvec3 d = light - p;
    const double r = glm::length(d);
    // The blocker's shadow on the floor: the light's rays through [0.4, 0.6]^2 at y = 0.5 reach
    // y = 0.1 at twice the distance from the axis; stay a few texels clear of its edge.
    const glm::dvec2 offset = glm::dvec2(p.x - 0.5, p.z - 0.5) / 2.0;
    const double inside = std::max(std::abs(offset.x), std::abs(offset.y));
    if (inside < 0.1 - 0.01) {
      EXPECT_EQ(direct.vec3At(e), glm::vec3(0.0f)) << "pixel " << e << " is in the shadow";
      ++shadowed;
    } else if (inside > 0.1 + 0.01) {
      const double expected = 1.0 / (r * r) * (d.y / r) / M_PI;
      EXPECT_NEAR(direct.get<float>(e, 0), expected, 1e-4 * expected) << "pixel " << e;
      ++lit;
    }
  }
  EXPECT_GT(shadowed, 100);
  EXPECT_GT(lit, 1000);
}

// inject_geometry.blockers=rsm: the texels' surfaces as blockers. Inside a closed box every wall is
// seen by a point light at its centre at cosines of at least 1/sqrt(3), so the blocker areas sum to
// the walls' area (6 x 9.6^2 cells^2), up to the midpoint rule's 6e-5 at 64^2 per face; the area-
// weighted normals, turned toward the light, cancel. A second light sees the same walls: each cell
// keeps one light's surfaces, so the total stays near that area instead of doubling (above it by
// what the larger of two samplings of a cell adds: measured +6.6 %).
TEST(InjectGeometry, RsmBlockersAreTheSurfacesTheLightsSee) {
  Scene scene = makeScene(closedBox(0.2, 0.8), unitGrid(16), grey(glm::vec3(0.5f)));
  scene.lights.push_back(pointLight({0.5, 0.5, 0.5}, glm::vec3(1.0f)));
  Settings settings;
  settings.lpv.rsmResolution = 64;
  settings.lpv.geometry = LpvGeometry::rsm;
  const double walls = 6.0 * 9.6 * 9.6;
  const auto areas = [](const Buffer& sums) {
    glm::dvec4 total(0.0);
    for (size_t e = 0; e < sums.elementCount(); ++e)
      for (int c = 0; c < 4; ++c) total[c] += sums.get<int32_t>(e, c) / 4194304.0;
    return total;
  };
  const glm::dvec4 one = areas(runCpuUntil(lpvTechnique(), scene, settings, "inject_geometry")
                                   .at(BufferId::lpv_inject_geometry_blocker_sum));
  EXPECT_NEAR(one.x, walls, 2e-4 * walls);
  for (int c = 1; c < 4; ++c) EXPECT_NEAR(one[c], 0.0, 1e-3) << "component " << c;
  scene.lights.push_back(pointLight({0.35, 0.6, 0.45}, glm::vec3(1.0f)));
  const glm::dvec4 two = areas(runCpuUntil(lpvTechnique(), scene, settings, "inject_geometry")
                                   .at(BufferId::lpv_inject_geometry_blocker_sum));
  EXPECT_GT(two.x, walls * (1.0 - 2e-4));
  EXPECT_LT(two.x, walls * 1.1) << "one light's surfaces per cell, not both";
}

// An emissive square over a floor, a small blocker between them: as an area light, the floor's
// direct light is Lambert's formula where the blocker does not hide the square's centroid (an
// independent 64 x 64 midpoint quadrature of cos cos / (pi r^2) over the square here) and 0
// beneath the blocker, whose shadow is the centroid's: a hard shadow.
TEST(ShadeLpv, AreaLightDirectLightIsLambertsFormulaOutsideTheShadow) {
  std::vector<Triangle> tris = quad(1, 0.1, {-1, -1}, {2, 2});
  for (const Triangle& t : quad(1, 0.5, {0.45, 0.45}, {0.55, 0.55})) tris.push_back(t);
  Scene scene = makeScene(tris, unitGrid(32), grey(glm::vec3(0.5f)));
  addEmitter(scene, downwardSquare(0.9, 0.4, 0.6), glm::vec3(1.0f));
  const BufferSet out = shadeFloor(scene);
  const Buffer &direct = out.at(BufferId::lpv_shade_direct_diffuse),
               &position = out.at(BufferId::common_gbuffer_pixel_position),
               &primitive = out.at(BufferId::common_gbuffer_primitive_id);
  const double s = scene.grid.voxelSize();
  int shadowed = 0, lit = 0;
  for (size_t e = 0; e < direct.elementCount(); ++e) {
    if (primitive.get<uint32_t>(e, 0) != 1 && primitive.get<uint32_t>(e, 0) != 2) continue;
    const glm::dvec3 p = scene.grid.min + glm::dvec3(position.vec3At(e)) * s;
    // The blocker [0.45, 0.55]^2 at y = 0.5 seen from the triangles' centroids (1/15 from the
    // square's centre along a diagonal): its shadow on y = 0.1 is the blocker scaled by 2 about
    // each, and both hide |x - 0.5|, |z - 0.5| < 0.067; stay clear of that edge and of the
    // penumbra the two shadows leave between them.
    const double reach = std::max(std::abs(p.x - 0.5), std::abs(p.z - 0.5));
    double f = 0.0;  // the form factor by quadrature
    const int k = 64;
    for (int i = 0; i < k; ++i)
      for (int j = 0; j < k; ++j) {
        const glm::dvec3 q(0.4 + 0.2 * (i + 0.5) / k, 0.9, 0.4 + 0.2 * (j + 0.5) / k);
        const glm::dvec3 d = q - p;
        const double r2 = glm::dot(d, d);
        f += (d.y / std::sqrt(r2)) * (d.y / std::sqrt(r2)) / (M_PI * r2) * (0.04 / (k * k));
      }
    if (reach < 0.05) {
      EXPECT_EQ(direct.vec3At(e), glm::vec3(0.0f)) << "pixel " << e << " is in the shadow";
      ++shadowed;
    } else if (reach > 0.3) {
      // E / pi = L F; the quadrature's own error is below 1e-4 at these distances.
      EXPECT_NEAR(direct.get<float>(e, 0), f, 2e-4 * f) << "pixel " << e;
      ++lit;
    }
  }
  EXPECT_GT(shadowed, 40);  // measured 64 and 1980
  EXPECT_GT(lit, 1000);
}

TEST(LpvPlan, RsmRunsForAnalyticLightsAndAreaLights) {
  Scene scene = makeScene(closedBox(0.2, 0.8), unitGrid(16), grey(glm::vec3(0.5f)));
  const Technique& t = lpvTechnique();
  Settings settings = techniqueDefaults(t);
  EffectPlan plan = t.plan(scene, settings);
  EXPECT_FALSE(plan.runs(StageId::lpv_rsm));
  EXPECT_EQ(plan.whySkipped(StageId::lpv_rsm), "no analytic lights");
  EXPECT_FALSE(plan.on(Effect::direct_light));
  scene.lights.push_back(pointLight({0.5, 0.5, 0.5}, glm::vec3(1.0f)));
  Light sun;
  sun.type = Light::Type::directional;
  scene.lights.push_back(sun);
  plan = t.plan(scene, settings);
  EXPECT_TRUE(plan.runs(StageId::lpv_rsm));
  EXPECT_TRUE(plan.on(Effect::direct_light));
  EXPECT_EQ(plan.maps, glm::ivec2(256, 7)) << "six faces and one box";
  // An emissive quad: two area lights of six faces each (emitters.mode=auto), or VPLs of its own.
  scene.lights.clear();
  addEmitter(scene, downwardSquare(0.7, 0.4, 0.6), glm::vec3(1.0f));
  plan = t.plan(scene, settings);
  EXPECT_TRUE(plan.runs(StageId::lpv_rsm));
  EXPECT_EQ(plan.maps, glm::ivec2(256, 12));
  settings.vct.emitters = EmitterLighting::voxels;
  plan = t.plan(scene, settings);
  EXPECT_FALSE(plan.runs(StageId::lpv_rsm));
  EXPECT_EQ(plan.whySkipped(StageId::lpv_rsm), "no analytic lights and emitters.mode=voxels");
}

}  // namespace
}  // namespace voxgi::test

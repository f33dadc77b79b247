// The rsm stage (docs/stages/lpv/rsm.md): a texel's flux carries the surface's cosine once (T14),
// a point light's six faces catch all its flux, a spot's map its cone's, an emissive triangle's
// maps its emitted flux, and depth is the distance along the view's axis.
#include <cmath>

#include <gtest/gtest.h>

#include "common/lpv/inject.h"
#include "common/lpv/rsm.h"
#include "common/lpv/sh_buffers.h"
#include "common/voxel_triangles.h"
#include "shaders/shared/lpv/rsm_kernel.h"
#include "tests/lpv/light_scenes.h"

namespace voxgi::test {
namespace {

// Per colour, the sum of an rsm stage buffer's components.
glm::dvec3 fluxSum(const Buffer& flux) {
  glm::dvec3 sum(0.0);
  for (size_t e = 0; e < flux.elementCount(); ++e) sum += glm::dvec3(flux.vec3At(e));
  return sum;
}

// T14, the tilt at which Martin's Φ = A_s I_s Ω_s (n_s·l)+ counts the cosine twice (A4 of
// docs/lpv.md): a plane that fills a directional light's whole box reflects albedo x irradiance x
// the box's cross-section at any tilt. With the cosine counted twice the sum would fall as
// cos(theta).
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
    const double side = 2.0 * rsm.views[0].extent * scene.grid.voxelSize();
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
  Scene scene = makeScene(cubeFaces(0.2, 0.8), unitGrid(16), grey(albedo));
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
    Scene scene = makeScene(cubeFaces(0.1, 0.9), unitGrid(16), grey(albedo));
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
  Scene scene = makeScene(cubeFaces(0.2, 0.8), unitGrid(16), grey(albedo));
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
}  // namespace
}  // namespace voxgi::test

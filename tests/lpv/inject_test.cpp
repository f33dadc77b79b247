// inject, inject_geometry and the planner of light propagation volumes: the emitters' flux
// reaches the volume (T14: sum c0 = total flux x K0), VPLs land in their cells, the fixed-point
// scale cannot overflow, and the geometry volume's lobe of a surfel (T13). The emitters' own VPLs
// are the thesis's form (emitters.mode=voxels); by default an emissive triangle is an area light
// whose RSM texels are the VPLs (tests/lpv/rsm_test.cpp).
#include <cmath>

#include <gtest/gtest.h>

#include "common/lpv/inject.h"
#include "common/lpv/sh_buffers.h"
#include "common/voxel_triangles.h"
#include "shaders/shared/lpv/inject_geometry_kernel.h"
#include "shaders/shared/lpv/inject_kernel.h"
#include "shaders/shared/lpv/sh.h"
#include "tests/test_scenes.h"

namespace voxgi::test {
namespace {

const Technique& lpvTechnique() {
  return findTechnique("lpv");
}

// Emitters as VPLs of their own [Martin 2012]: emitters.mode=voxels.
Settings emitterVpls() {
  Settings settings;
  settings.vct.emitters = EmitterLighting::voxels;
  return settings;
}

// An emissive quad of emission (2, 1, 0.5) facing -y at y = 0.6, 0.3 x 0.4, in a unit 16^3 grid.
Scene emitterScene() {
  Material light;
  light.emission = {2.0f, 1.0f, 0.5f};
  auto tris = quad(1, 0.6, {0.2, 0.3}, {0.5, 0.7});  // (z, x) = (u, v) for axis y
  for (Triangle& t : tris) std::swap(t[1], t[2]);    // wind toward -y
  return makeScene(tris, unitGrid(16), light);
}

TEST(InjectLpv, TotalFluxReachesTheVolume) {
  const Scene scene = emitterScene();
  for (int bands : {2, 3}) {
    Settings settings = emitterVpls();
    settings.lpv.bands = bands;
    const BufferSet out = runCpuUntil(lpvTechnique(), scene, settings, "inject");
    const lpv::ShBuffers sh = lpv::shBuffers(settings.lpv);
    const Buffer& sums = out.at(sh.intensitySum);
    const VoxelTriangles tris = prepareVoxelTriangles(scene, scene.grid);
    const StageContext ctx{lpvTechnique(), scene, settings, tris};
    const glm::vec4 scale = lpv::injectionScale(ctx);
    const int coefficients = settings.lpv.coefficients();
    const double area = 0.3 * 0.4;
    for (int c = 0; c < 3; ++c) {
      double c0 = 0.0, c2 = 0.0;
      for (size_t e = 0; e < sums.elementCount(); ++e) {
        c0 += sums.get<int32_t>(e, c * coefficients) / double(scale[c]);
        c2 += sums.get<int32_t>(e, c * coefficients + 1) / double(scale[c]);  // Y_1-1 = -K1 y
      }
      const double flux = M_PI * scene.materials[0].emission[c] * area;
      EXPECT_NEAR(c0, flux * 0.282094791773878, 1e-6 * flux) << "colour " << c;
      // The lobe points down (-y): its Y_1,-1 coefficient is (2/3) K1 x flux.
      EXPECT_NEAR(c2, flux * 2.0 / 3.0 * 0.488602511902920, 1e-6 * flux) << "colour " << c;
    }
  }
}

TEST(InjectLpv, VplsLandInTheirCellsAndShiftAlongTheirNormal) {
  const Scene scene = emitterScene();
  Settings settings = emitterVpls();
  const VoxelTriangles tris = prepareVoxelTriangles(scene, scene.grid);
  const lpv::Injection plain =
      lpv::prepareInjection(StageContext{lpvTechnique(), scene, settings, tris});
  settings.lpv.vplShift = LpvToggle::on;
  const lpv::Injection shifted =
      lpv::prepareInjection(StageContext{lpvTechnique(), scene, settings, tris});
  ASSERT_EQ(plain.vpls.size(), shifted.vpls.size());
  // 0.4 x 16 = 6.4 cells on the longest edge (the diagonal 8 cells), 1/4 cell apart: m = 32.
  EXPECT_EQ(plain.vpls.size(), 2u * 32u * 32u);
  for (size_t v = 0; v < plain.vpls.size(); ++v) {
    const glm::vec3 p(plain.vpls[v].position), q(shifted.vpls[v].position);
    EXPECT_FLOAT_EQ(p.y, 9.6f);
    EXPECT_NEAR(q.y - p.y, -0.5f, 1e-5f);  // half a cell along the normal, -y
    EXPECT_EQ(shared::vplCell(plain.vpls[v]).y, 9);
    EXPECT_EQ(shared::vplCell(shifted.vpls[v]).y, 9);
    EXPECT_EQ(glm::ivec3(glm::floor(p)), shared::vplCell(plain.vpls[v]));
  }
}

// The scale is a power of two with scale x total flux <= 2^30, and a lobe coefficient is at most a
// third of its flux, so no sum of any number of VPLs can leave int32.
TEST(InjectLpv, FixedPointScaleCannotOverflow) {
  Scene scene = emitterScene();
  scene.materials[0].emission = {1e30f, 1e-30f, 0.0f};
  Settings settings = emitterVpls();
  const VoxelTriangles tris = prepareVoxelTriangles(scene, scene.grid);
  const lpv::Injection in =
      lpv::prepareInjection(StageContext{lpvTechnique(), scene, settings, tris});
  double total[3] = {0, 0, 0};
  for (const shared::Vpl& v : in.vpls)
    for (int c = 0; c < 3; ++c) total[c] += v.flux[c];
  for (int c = 0; c < 3; ++c) {
    int exponent = 0;
    EXPECT_EQ(std::frexp(double(in.params.scale[c]), &exponent), 0.5) << "a power of two";
    EXPECT_LE(total[c] * in.params.scale[c], std::ldexp(1.0, 30) * (1 + 1e-6));
  }
  EXPECT_EQ(in.vpls.size(), 2u * 32u * 32u);
  EXPECT_EQ(in.params.scale[2], 1.0f) << "no light: unit scale";
  double largest = 0.0;
  for (int i = 0; i < 9; ++i)
    for (const glm::vec3 n : {glm::vec3(0, 0, 1), glm::normalize(glm::vec3(1, 1, 1)),
                              glm::normalize(glm::vec3(1, -2, 0.5))})
      largest =
          std::max(largest, std::abs(double(shared::shLobeOverPi(i) * shared::shBasis(i, n))));
  EXPECT_LT(largest, 1.0 / 3.0);
}

// T13: a voxel holding one surface of area h^2 and normal n lends each of its 8 corners an eighth
// of the lobe (pi K0, 2 pi / 3 Y_1(n)); evaluated toward n, the 8 together block 0.75.
TEST(InjectGeometry, SurfelLobe) {
  struct OneVoxel {
    glm::ivec3 at;
    glm::vec3 n;
    glm::vec4 surfaceAt(glm::ivec3 v) const {
      return v == at ? glm::vec4(65536.0f, 65536.0f * n.x, 65536.0f * n.y, 65536.0f * n.z)
                     : glm::vec4(0.0f);
    }
  };
  const glm::vec3 n = glm::normalize(glm::vec3(0.3f, -0.5f, 0.8f));
  const OneVoxel voxel{glm::ivec3(2, 2, 2), n};
  double total = 0.0;
  for (int corner = 0; corner < 8; ++corner) {
    const glm::ivec3 g = glm::ivec3(2) - glm::ivec3(corner & 1, (corner >> 1) & 1, corner >> 2);
    const glm::vec4 b = shared::cornerBlocking(voxel, g);
    double towardN = 0.0;
    for (int i = 0; i < 4; ++i) towardN += double(b[i]) * shared::shBasis(i, n);
    total += towardN;
  }
  EXPECT_NEAR(total, 0.75, 1e-6);
  EXPECT_EQ(shared::cornerBlocking(voxel, glm::ivec3(0)), glm::vec4(0.0f)) << "not a corner of it";
}

TEST(LpvPlan, DecidesEveryStepAndKeepsStepsOnlyWhenAsked) {
  const Scene scene = emitterScene();
  for (const char* name : {"lpv", "holpv"}) {
    const Technique& t = findTechnique(name);
    Settings settings = techniqueDefaults(t);
    EffectPlan plan = t.plan(scene, settings);
    for (const StageSpec* s : t.steps()) EXPECT_TRUE(plan.decides(s->id)) << s->qualifiedName();
    const lpv::ShBuffers sh = lpv::shBuffers(settings.lpv);
    EXPECT_TRUE(plan.on(sh.coefficients));
    EXPECT_FALSE(plan.on(sh.history));
    EXPECT_EQ(plan.seriesLength, 16 / 2 + 1) << "propagate.steps=0: half the grid";
    settings.inspect = true;
    EXPECT_TRUE(t.plan(scene, settings).on(sh.history));
    settings.lpv.occlusion = LpvOcclusion::off;
    EXPECT_FALSE(t.plan(scene, settings).runs(StageId::lpv_inject_geometry));
  }
  EXPECT_EQ(techniqueDefaults(findTechnique("holpv")).lpv.coefficients(), 9);
  EXPECT_EQ(techniqueDefaults(findTechnique("holpv")).lpv.directionCount(), 26);
  EXPECT_EQ(techniqueDefaults(findTechnique("lpv")).lpv.coefficients(), 4);
}

}  // namespace
}  // namespace voxgi::test

// The light terms (common/light_terms.h) of the path tracer and of the staged techniques: each
// renderer's terms add up to its image, and on scenes with a known answer each term holds what
// that answer puts in it.
#include <gtest/gtest.h>

#include "common/light_terms.h"
#include "common/scene_io/scene_load.h"
#include "common/technique.h"
#include "common/io/buffer_io.h"
#include "tests/test_scenes.h"
#include "validation/reference/path_trace.h"

namespace voxgi::test {
namespace {

using reference::pathTrace;
using reference::PathTraceOptions;

// Mean over pixels and channels.
double channelMean(const Image& image) {
  const glm::dvec3 m = meanOf(image);
  return (m.x + m.y + m.z) / 3.0;
}

// The Cornell box with every kind of light: its ceiling emitter, a point light, and glossy walls.
Scene everyKindOfLight(int size) {
  Scene scene = loadScene(sourcePath("scenes/cornell_box.json"));
  scene.camera.width = scene.camera.height = size;
  scene.grid.resolution = 32;
  Light light;
  light.position = 0.5 * (scene.bounds().first + scene.bounds().second);
  light.intensity = glm::vec3(0.05f);
  scene.lights.push_back(light);
  for (Material& m : scene.materials)
    if (!m.emissive()) {
      m.specular = glm::vec3(0.3f);
      m.shininess = 20.0f;
    }
  return scene;
}

// Sum of the terms against the image, per pixel and channel, relative to the pixel's size.
void expectTermsAddUp(const TermImages& terms, const Image& image, float tolerance) {
  for (size_t e = 0; e < image.pixels.size(); ++e) {
    glm::vec3 sum(0.0f);
    for (const Image& t : terms) sum += t.pixels[e];
    for (int c = 0; c < 3; ++c)
      ASSERT_NEAR(sum[c], image.pixels[e][c], tolerance * (1.0f + std::abs(image.pixels[e][c])))
          << "pixel " << e << " channel " << c;
  }
}

TEST(LightTerms, PathTracedTermsAddUpToTheImage) {
  const Scene scene = everyKindOfLight(16);
  for (const int bounces : {0, 1, -1}) {
    PathTraceOptions o;
    o.spp = 8;
    o.bounces = bounces;
    const auto r = pathTrace(scene, o);
    expectTermsAddUp(r.terms, r.image, 1e-5f);
    // The camera sees the emitter, and every surface sees a light; with no bounce after the first
    // hit (and a black background) nothing is indirect.
    for (const LightTerm t : kLightTerms) {
      const bool indirect = t == LightTerm::indirect_diffuse || t == LightTerm::indirect_specular;
      if (bounces == 0 && indirect)
        EXPECT_EQ(channelMean(termImage(r.terms, t)), 0.0) << termName(t);
      else
        EXPECT_GT(channelMean(termImage(r.terms, t)), 0.0) << termName(t) << " bounces " << bounces;
    }
  }
}

// A plane under a uniform sky L, seen straight down through a narrow camera: the diffuse lobe
// reflects albedo x L and the normalised Phong lobe specular x L (seen along the normal,
// (n+2)/(2 pi) integrated against cos^(n+1) over the hemisphere is 1); nothing is direct or
// emitted.
TEST(LightTerms, PathTracedSkyLitPlaneSplitsByLobe) {
  Material m;
  m.albedo = glm::vec3(0.5f, 0.25f, 0.1f);
  m.specular = glm::vec3(0.2f, 0.3f, 0.4f);
  m.shininess = 10.0f;
  Scene scene = withCamera(makeScene(quad(1, 0.0, {-1e3, -1e3}, {1e3, 1e3}), unitGrid(8), m),
                           {0, 1, 0}, {0, 0, 0}, {0, 0, 1}, 0.01, 8);
  scene.background = {1.0f, 2.0f, 0.5f};
  PathTraceOptions o;
  o.spp = 256;
  o.bounces = 0;
  const auto r = pathTrace(scene, o);
  const glm::dvec3 diffuse = meanOf(termImage(r.terms, LightTerm::indirect_diffuse)),
                   glossy = meanOf(termImage(r.terms, LightTerm::indirect_specular));
  for (int c = 0; c < 3; ++c) {
    const double l = scene.background[c];
    // The Lambertian lobe's estimate is exact per sample where a Phong sample is taken, so only
    // the choice between lobes is noise: 2048 samples hold each to a few percent.
    EXPECT_NEAR(diffuse[c], m.albedo[c] * l, 0.05 * m.albedo[c] * l) << c;
    EXPECT_NEAR(glossy[c], m.specular[c] * l, 0.05 * m.specular[c] * l) << c;
  }
  EXPECT_EQ(channelMean(termImage(r.terms, LightTerm::direct)), 0.0);
  EXPECT_EQ(channelMean(termImage(r.terms, LightTerm::emission)), 0.0);
}

// The staged techniques compose their image from the same terms.
TEST(LightTerms, TechniqueTermsAddUpToItsImage) {
  const Scene scene = everyKindOfLight(32);
  for (const Technique& technique : techniques()) {
    Settings settings = resolveSettings(technique, scene.settings, scene.file, "default", {});
    settings.vct.ambientOcclusion = AmbientOcclusion::on;  // vct darkens its indirect term
    const BufferSet b =
        runCpuUntil(technique, scene, settings, bufferSpec(technique.image).stageSpec().name);
    const auto terms = techniqueTerms(technique, b, settings, scene);
    ASSERT_TRUE(terms.has_value()) << technique.name;
    expectTermsAddUp(*terms, bufferImage(b.at(technique.image)), 1e-5f);
    EXPECT_GT(channelMean(termImage(*terms, LightTerm::direct)), 0.0) << technique.name;
    EXPECT_GT(channelMean(termImage(*terms, LightTerm::indirect_diffuse)), 0.0) << technique.name;
  }
}

// VCT's terms on a black floor under a uniform sky, with the clearance that makes its cones see
// the whole sky (tests/vct/trace_cones_test.cpp): the floor fills the view, and its pixels are all
// indirect diffuse, albedo x sky.
TEST(LightTerms, ConeTracedSkyLitFloorIsIndirectDiffuse) {
  const int n = 64;
  Material m;
  m.albedo = glm::vec3(0.5f);
  Scene scene = withCamera(makeScene(quad(1, 0.25, {0.0, 0.0}, {1.0, 1.0}), unitGrid(n), m),
                           {0.5, 0.75, 0.5}, {0.5, 0.25, 0.5}, {0, 0, 1}, 20.0, 16);
  scene.background = glm::vec3(2.0f, 1.0f, 0.5f);
  Settings settings;
  settings.vct.mip = MipMode::anisotropic;
  settings.vct.coneClearance = 1.0f / 3.0f;
  settings.vct.coneOffset = 1.5f;
  const BufferSet b = runCpuUntil(scene, settings, "compose");
  const auto terms = techniqueTerms(vct(), b, settings, scene);
  ASSERT_TRUE(terms.has_value());
  for (const glm::vec3& p : termImage(*terms, LightTerm::indirect_diffuse).pixels)
    for (int c = 0; c < 3; ++c) ASSERT_NEAR(p[c], 0.5f * scene.background[c], 1e-5f);
  for (const LightTerm t : {LightTerm::emission, LightTerm::direct, LightTerm::indirect_specular})
    EXPECT_EQ(channelMean(termImage(*terms, t)), 0.0) << termName(t);
}

}  // namespace
}  // namespace voxgi::test

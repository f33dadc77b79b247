// propagate.carry (common/svo/propagate.h; docs/svo.md, S15 in a sequence): the progressive bounces
// run across the frames of a sequence [Salm 2015, §4.4.3]. Frame t0 + k after a light came on is
// the still frame with k + 1 gathers, bit for bit (so bounce n of a point light first shows at
// frame t0 + n - 2); the light follows the leaves by key; propagate stops once its light settles.
#include <gtest/gtest.h>

#include "common/frame_plan.h"
#include "common/svo/propagate.h"
#include "cpu/backend.h"
#include "shaders/shared/half_float.h"
#include "shaders/shared/svo/svo_layout.h"
#include "shaders/shared/cone/gather.h"
#include "tests/test_scenes.h"

namespace voxgi::test {
namespace {

const FrameStep& stepOf(const std::vector<FrameStep>& steps, StageId id) {
  for (const FrameStep& s : steps)
    if (s.stage->id == id) return s;
  throw std::logic_error("no such step");
}

// A closed box at 16^3 lit by a point light in its middle of `intensity`, seen from inside.
Scene litBox(float intensity, float albedo) {
  Material walls;
  walls.albedo = glm::vec3(albedo);
  Scene scene = closedBox(16, walls);
  Light light;
  light.position = {0.5, 0.6, 0.5};
  light.intensity = glm::vec3(intensity);
  scene.lights = {light};
  return withCamera(scene, {0.5, 0.5, 0.25}, {0.5, 0.45, 0.9}, {0, 1, 0}, 70.0, 32);
}

Settings carrying(int frames) {
  Settings settings = techniqueDefaults(findTechnique("svo"));
  settings.svo.frames = frames;
  settings.svo.carry = SvoToggle::on;
  return settings;
}

// The light comes on at frame 1 of a box that stays still: frame 1 + k equals the still with k + 1
// gathers (the still's gathers are the explicit sum of S15, SvoLight.*), so each frame of the
// sequence adds exactly one bounce, and the frames before the light carry nothing.
TEST(SvoCarry, EachFrameAfterALightCameOnAddsOneBounce) {
  const Technique& svo = findTechnique("svo");
  cpu::CpuBackend cpu;
  FrameRunner runner(svo, cpu);
  runner.run(litBox(0.0f, 0.6f), carrying(1));  // dark: nothing runs but the black image
  const Scene lit = litBox(4.0f, 0.6f);
  for (int k = 0; k < 4; ++k) {
    const std::vector<FrameStep>& steps = runner.run(lit, carrying(1));
    if (k > 0) {
      EXPECT_FALSE(stepOf(steps, StageId::svo_build).runs) << "frame " << k;
      const FrameStep& propagate = stepOf(steps, StageId::svo_propagate);
      EXPECT_TRUE(propagate.runs) << "frame " << k << ": " << propagate.why;
    }
    Settings still = techniqueDefaults(svo);
    still.svo.frames = k + 1;
    const BufferSet want = runCpuUntil(svo, lit, still, "shade");
    for (const BufferId id : {BufferId::svo_propagate_radiance,
                              BufferId::svo_propagate_gathered_bricks, BufferId::svo_shade_color})
      EXPECT_TRUE(sameWords(runner.buffers(), want, id))
          << "frame " << k + 1 << ": " << bufferSpec(id).qualifiedName();
    // Not yet the still with one gather more: the next bounce is still to come.
    still.svo.frames = k + 2;
    EXPECT_FALSE(sameWords(runCpuUntil(svo, lit, still, "propagate"), runner.buffers(),
                           BufferId::svo_propagate_radiance))
        << "frame " << k + 1;
  }
}

// Black walls reflect nothing, so the light a frame gathers is the same every frame: propagate
// settles after its second frame and the planner reuses it from the third on.
TEST(SvoCarry, PropagateStopsWhenItsLightSettles) {
  cpu::CpuBackend cpu;
  FrameRunner runner(findTechnique("svo"), cpu);
  const Scene scene = litBox(4.0f, 0.0f);
  std::vector<bool> ran;
  for (int f = 0; f < 4; ++f)
    ran.push_back(stepOf(runner.run(scene, carrying(1)), StageId::svo_propagate).runs);
  EXPECT_EQ(ran, (std::vector<bool>{true, true, false, false}));
  EXPECT_EQ(stepOf(runner.steps(), StageId::svo_propagate).why,
            "the light it carries settled: reuse");
  // A frame the scene changes in runs it again.
  Scene moved = scene;
  moved.lights[0].position.x += 0.1;
  EXPECT_TRUE(stepOf(runner.run(moved, carrying(1)), StageId::svo_propagate).runs);
}

// S16 in a sequence: voxgi builds the tree of each frame from that frame's samples, so an object
// that moves away and back leaves the tree, word for word, as it was ([Salm 2015, §4.5] restores
// the bricks it backed up); the carried light is what changes (docs/svo.md, Z17).
TEST(SvoCarry, AnObjectThatMovesAwayAndBackLeavesTheTreeAsItWas) {
  Scene scene = litBox(4.0f, 0.6f);
  scene.meshes.push_back(
      makeScene(quad(1, 0.3, {0.3, 0.3}, {0.5, 0.5}), unitGrid(16)).meshes.at(0));
  Scene away = scene;
  for (glm::dvec3& p : away.meshes.back().positions) p += glm::dvec3(0.25, 0.2, 0.1);
  Settings settings = carrying(1);
  settings.planMode = PlanMode::full;  // the leaf sums too, the build's exact words
  cpu::CpuBackend cpu;
  FrameRunner runner(findTechnique("svo"), cpu);
  runner.run(scene, settings);
  const BufferSet before = runner.buffers();
  EXPECT_TRUE(stepOf(runner.run(away, settings), StageId::svo_build).runs);
  EXPECT_FALSE(sameWords(runner.buffers(), before, BufferId::svo_build_tiles));
  EXPECT_TRUE(stepOf(runner.run(scene, settings), StageId::svo_build).runs);
  for (const BufferSpec* b : stageBuffers(stageSpec(StageId::svo_build)))
    EXPECT_TRUE(sameWords(runner.buffers(), before, b->id)) << b->qualifiedName();
  EXPECT_FALSE(sameWords(runner.buffers(), before, BufferId::svo_propagate_radiance));
}

// The carried light follows the leaves by key: leaves of the same key in both trees start from
// their direct light plus albedo times the light they gathered, leaves new to the tree from their
// direct light, and an empty leaf stays empty.
TEST(SvoCarry, TheLightFollowsTheLeavesByKey) {
  svo::CarriedLight before;
  before.tileKeys = {1, 3, 5};
  for (size_t s = 0; s < 24; ++s) before.gathered.push_back(glm::vec3(float(s + 1), 0.5f, 0.25f));
  const std::vector<uint32_t> keys{3, 4, 5};
  Words leafTiles(keys.size() * shared::kTileWords, 0u);
  for (size_t t = 0; t < keys.size(); ++t)
    leafTiles[t * shared::kTileWords + shared::kTileKey] = keys[t];
  svo::Leaves leaves;
  svo::LeafRadiance direct;
  for (size_t s = 0; s < 24; ++s) {
    const float opacity = s % 8 == 7 ? 0.0f : 0.5f;  // each tile's last leaf is empty
    leaves.albedo.push_back(glm::vec4(0.25f, 0.125f, 0.0625f, 1.0f) * opacity);
    direct.push_back(opacity > 0.0f ? glm::vec4(0.1f, 0.2f, 0.3f, opacity) : glm::vec4(0.0f));
  }
  const svo::LeafRadiance source = svo::carriedSource(before, leafTiles, leaves, direct);
  ASSERT_EQ(source.size(), direct.size());
  for (size_t s = 0; s < 24; ++s) {
    const size_t tile = s / 8, local = s % 8;
    glm::vec4 want = direct[s];
    if (local != 7 && tile != 1) {
      const size_t from = (tile == 0 ? 1 : 2) * 8 + local;  // key 3 was tile 1, key 5 tile 2
      const glm::vec3 albedo(0.25f, 0.125f, 0.0625f);
      // Rounded to the halves the radiance pool stores.
      want = shared::roundToHalf4(
          glm::vec4(glm::vec3(direct[s]) + albedo * before.gathered[from] * 0.5f, 0.5f));
    }
    EXPECT_EQ(source[s], want) << "leaf slot " << s;
  }
}

}  // namespace
}  // namespace voxgi::test

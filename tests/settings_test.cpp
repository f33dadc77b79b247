// --set key=value and --preset: values parse exactly, bad ones name the key, presets apply.
#include <set>
#include <string_view>

#include <gtest/gtest.h>

#include "common/error.h"
#include "common/settings.h"
#include "common/technique.h"

namespace voxgi {
namespace {

void expectRejected(const std::string& assignment, const std::string& mention) {
  Settings s;
  try {
    applySetting(s, assignment, "--set");
    FAIL() << assignment << " accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(mention), std::string::npos) << e.what();
  }
}

TEST(Settings, AssignmentsParseAndRangesHold) {
  Settings s;
  applySetting(s, "voxel_shadow.kappa=0.5", "--set");
  applySetting(s, "mip.mode=isotropic", "--set");
  applySetting(s, "voxel_shadow.mode=soft", "--set");
  EXPECT_EQ(s.vct.voxelShadowKappa, 0.5f);
  EXPECT_EQ(s.vct.mip, MipMode::isotropic);
  EXPECT_EQ(s.vct.voxelShadow, VoxelShadow::soft);
  expectRejected("voxel_shadow.offset=0", "voxel_shadow.offset");   // below the range
  expectRejected("voxel_shadow.kappa=0.5x", "voxel_shadow.kappa");  // trailing junk
  expectRejected("voxel_shadow.kappa=nan", "voxel_shadow.kappa");   // not finite
  expectRejected("mip.mode=fancy", "isotropic|anisotropic");
  expectRejected("no.such=1", "unknown parameter");
  expectRejected("voxel_shadow.kappa", "key=value");
}

TEST(Settings, PresetsSetTheirKeysAndListEveryKey) {
  Settings s;
  const Technique& vct = findTechnique("vct");
  applyPreset(s, vct, "kahl2019");
  EXPECT_EQ(s.vct.voxelShadow, VoxelShadow::none);
  EXPECT_EQ(s.vct.mip, MipMode::isotropic);
  EXPECT_EQ(s.vct.coneOffsetUnit, ConeOffsetUnit::voxel);  // the papers' offsets are in voxels
  Settings v;
  applyPreset(v, vct, "villegas2017");
  EXPECT_EQ(v.vct.attenuation, LightAttenuation::normal_weighted);
  EXPECT_EQ(v.vct.coneOffsetUnit, ConeOffsetUnit::voxel);
  EXPECT_EQ(Settings{}.vct.coneOffsetUnit, ConeOffsetUnit::grid64);
  EXPECT_THROW(applyPreset(v, vct, "nobody2020"), InputError);
  const std::string help = describeSettings(vct);
  for (const std::string& kv : settingValues(Settings{}, vct))
    EXPECT_NE(help.find(kv.substr(0, kv.find('='))), std::string::npos) << kv;
}

// svo lists voxel cone tracing's cone keys as its own (the same fields): --set takes them with
// --technique svo, and still refuses a key that only another technique has.
TEST(Settings, ATechniqueTakesTheKeysItSharesAndRefusesOthers) {
  const Technique& svo = findTechnique("svo");
  const Settings s =
      resolveSettings(svo, {}, "scene.json", "default", {"cones.offset=2", "cones.clearance=0.25"});
  EXPECT_EQ(s.vct.coneOffset, 2.0f);
  EXPECT_EQ(s.vct.coneClearance, 0.25f);
  try {
    resolveSettings(svo, {}, "scene.json", "default", {"mip.mode=isotropic"});
    FAIL() << "svo took vct's mip.mode";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("is a parameter of vct, not of svo"), std::string::npos)
        << e.what();
  }
  try {
    resolveSettings(svo, {}, "scene.json", "default", {"voxelize.mode=antialiased"});
    FAIL() << "svo took voxelize.mode, though it does not voxelize";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("a stage svo does not run"), std::string::npos)
        << e.what();
  }
}

// Every key of every technique follows the one scheme of common/technique.h: named after a stage
// the technique runs, after the owner of its stages, the planner (plan), the planner in time
// (update), or a shared kernel.
TEST(Settings, EveryKeyNamesTheStageOrKernelThatReadsIt) {
  for (const Technique& t : techniques()) {
    std::set<std::string_view> allowed{"plan", "update"};
    for (const std::string_view group : kKernelKeyGroups) allowed.insert(group);
    for (const StageSpec* s : t.steps()) {
      allowed.insert(s->name);
      if (s->owner != std::string_view("common")) allowed.insert(s->owner);
    }
    for (const Param* p : techniqueParams(t)) {
      const std::string_view prefix = std::string_view(p->key).substr(0, p->key.find('.'));
      EXPECT_TRUE(allowed.count(prefix)) << t.name << ": " << p->key;
    }
  }
}

}  // namespace
}  // namespace voxgi

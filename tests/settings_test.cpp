// --set key=value and --preset: values parse exactly, bad ones name the key, presets apply.
#include <gtest/gtest.h>

#include "common/error.h"
#include "common/settings.h"

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
  applySetting(s, "cone.beta=0.5", "--set");
  applySetting(s, "bounce.count=2", "--set");
  applySetting(s, "mip.mode=isotropic", "--set");
  applySetting(s, "ao.enabled=true", "--set");
  EXPECT_EQ(s.beta, 0.5f);
  EXPECT_EQ(s.bounces, 2);
  EXPECT_EQ(s.mip, MipMode::isotropic);
  EXPECT_TRUE(s.ambientOcclusion);
  expectRejected("cone.beta=0", "cone.beta");     // below the range
  expectRejected("cone.beta=0.5x", "cone.beta");  // trailing junk
  expectRejected("cone.beta=nan", "cone.beta");   // not finite
  expectRejected("bounce.count=1.5", "bounce.count");
  expectRejected("mip.mode=fancy", "isotropic|anisotropic");
  expectRejected("no.such=1", "unknown parameter");
  expectRejected("cone.beta", "key=value");
}

TEST(Settings, PresetsSetTheirKeysAndListEveryKey) {
  Settings s;
  applyPreset(s, "kahl2019");
  EXPECT_EQ(s.diffuseCones, DiffuseCones::kahl5);
  EXPECT_EQ(s.diffuseMode, DiffuseMode::first_hit);
  EXPECT_EQ(s.mip, MipMode::isotropic);
  Settings v;
  applyPreset(v, "villegas2017");
  EXPECT_EQ(v.attenuation, LightAttenuation::normal_weighted);
  EXPECT_THROW(applyPreset(v, "nobody2020"), InputError);
  const std::string help = describeSettings();
  for (const std::string& kv : settingValues(Settings{}))
    EXPECT_NE(help.find(kv.substr(0, kv.find('='))), std::string::npos) << kv;
}

}  // namespace
}  // namespace voxgi

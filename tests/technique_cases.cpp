#include "tests/technique_cases.h"

#include <filesystem>
#include <fstream>
#include <set>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "common/scene_io/scene_load.h"
#include "tests/test_scenes.h"

namespace voxgi::test {
namespace {
const std::set<std::string> kKeys{"scene",  "cloud_points", "glossy_cloud", "resolution", "image",
                                  "preset", "set",          "inspect",      "platform",   "why"};
}  // namespace

std::vector<TechniqueCase> techniqueCases(const Technique& technique, const std::string& kind) {
  const std::string file = "tests/cases/" + std::string(technique.name) + ".json";
  TechniqueCase failed;
  failed.technique = technique.name;
  failed.label = std::string(technique.name) + "_declares_no_" + kind + "_case";
  std::vector<TechniqueCase> cases;
  try {
    std::ifstream in(sourcePath(file));
    if (!in) throw std::runtime_error("cannot be read");
    const nlohmann::json json = nlohmann::json::parse(in);
    for (const auto& entry : json.at(kind)) {
      for (const auto& [key, value] : entry.items())
        if (!kKeys.contains(key)) throw std::runtime_error("unknown key \"" + key + "\"");
      TechniqueCase c;
      c.technique = technique.name;
      c.scene = entry.at("scene").get<std::string>();
      c.cloudPoints = entry.value("cloud_points", size_t(0));
      c.glossyCloud = entry.value("glossy_cloud", false);
      c.resolution = entry.value("resolution", c.resolution);
      c.image = entry.value("image", c.image);
      c.preset = entry.value("preset", c.preset);
      c.sets = entry.value("set", c.sets);
      c.inspect = entry.value("inspect", c.inspect);
      c.platform = entry.value("platform", c.platform);
      const std::string stem = std::filesystem::path(c.scene).stem().string();
      c.label = std::string(technique.name) + "_" + std::to_string(cases.size()) + "_" + stem +
                (c.cloudPoints ? "_cloud" : "");
      cases.push_back(std::move(c));
    }
    if (cases.empty()) throw std::runtime_error("\"" + kind + "\" lists no case");
  } catch (const std::exception& e) {
    failed.error = file + ": " + e.what() + " (docs/architecture.md, \"Adding a technique\")";
    return {failed};
  }
  return cases;
}

void PrintTo(const TechniqueCase& c, std::ostream* os) {
  *os << c.label;
}

std::vector<TechniqueCase> allTechniqueCases(const std::string& kind) {
  std::vector<TechniqueCase> all;
  for (const Technique& t : techniques()) {
    auto cases = techniqueCases(t, kind);
    all.insert(all.end(), cases.begin(), cases.end());
  }
  return all;
}

std::vector<TechniqueCase> requiredCases(std::string_view technique, const std::string& kind) {
  std::vector<TechniqueCase> cases = techniqueCases(findTechnique(technique), kind);
  if (cases.empty() || !cases.front().error.empty()) {
    ADD_FAILURE() << "tests/cases/" << technique << ".json declares no " << kind << " case"
                  << (cases.empty() ? "" : ": " + cases.front().error);
    return {};
  }
  return cases;
}

Scene caseScene(const TechniqueCase& c) {
  Scene scene = c.cloudPoints ? sampledCloudScene(sourcePath(c.scene), c.cloudPoints, c.glossyCloud)
                              : loadScene(sourcePath(c.scene));
  scene.grid.resolution = c.resolution;
  scene.camera.width = scene.camera.height = c.image;
  return scene;
}

Settings caseSettings(const TechniqueCase& c, const Scene& scene) {
  Settings settings =
      resolveSettings(findTechnique(c.technique), scene.settings, scene.file, c.preset, c.sets);
  settings.inspect = c.inspect;
  return settings;
}

}  // namespace voxgi::test

// The scenes and settings each technique declares for the generic tests (tests/cases/<name>.json):
// determinism across thread counts, the GPU stages against the CPU's and the planner's coverage
// run over every technique of the registry with these, so a new technique or stage is covered
// by adding its cases, never by editing those tests.
#pragma once

#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "common/scene.h"
#include "common/settings.h"
#include "common/technique.h"

namespace voxgi::test {

struct TechniqueCase {
  std::string technique;
  std::string label;  // for the test's name: "<technique>_<index>_<scene stem>"
  std::string scene;  // relative to the project root
  // > 0: the scene's non-emitting meshes as a cloud of that many sampled points (cornellBoxCloud),
  // glossy or not.
  size_t cloudPoints = 0;
  bool glossyCloud = false;
  int resolution = 32;  // the grid's (the octree's leaves)
  int image = 64;       // the square image's side
  std::string preset = "default";
  std::vector<std::string> sets;  // --set assignments after the scene's and the preset's
  bool inspect = false;           // keep every step's volume, as voxgi diff does
  std::string platform = "egl";   // the GL platform of the GPU case
  std::string error;              // why the cases could not be read (the test fails with it)
};

// How gtest prints a case: its label.
void PrintTo(const TechniqueCase& c, std::ostream* os);

// The technique's cases of `kind` ("determinism" or "gpu"), or one case carrying the error when
// its file is missing or malformed or declares none.
std::vector<TechniqueCase> techniqueCases(const Technique& technique, const std::string& kind);
// Every technique's, in registry order.
std::vector<TechniqueCase> allTechniqueCases(const std::string& kind);
// The technique's cases of `kind` for a test of that technique alone: none, and the calling test
// fails naming the file, where it declares none or its file has an error, so that such a test
// cannot pass on no case.
std::vector<TechniqueCase> requiredCases(std::string_view technique, const std::string& kind);
// The case's scene at its grid resolution and image size.
Scene caseScene(const TechniqueCase& c);
// The case's settings: the technique's defaults, the scene's, the preset's, then the case's own.
Settings caseSettings(const TechniqueCase& c, const Scene& scene);

}  // namespace voxgi::test

// `voxgi compare TEST REFERENCE`: error metrics of an image against a reference beside what
// trivial answers score on it, with the reference's own noise floor when its variance image lies
// beside it, and a false-colour map.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "common/io/image_io.h"
#include "validation/reference/image_metrics.h"

namespace voxgi::tools {

struct CompareOptions {
  std::string test, reference, mask, errorPng, json;
  int scanline = -1;          // a row whose luminance both images give in the JSON (-1: none)
  bool terms = false;         // also each light term, from the TEST.<term>.exr beside each image
  bool skipEmitters = false;  // leave out the pixels where the reference sees emission
  reference::MetricUnits units = reference::MetricUnits::reference_mean;
  std::string frames;  // --frames A:B[:STEP]: TEST and REFERENCE hold a frame field
};

// --units mean|absolute (reference::kMetricUnitsNames) and --skip-emitters, for compare and study.
void addUnitsOptions(CLI::App& cmd, reference::MetricUnits& units, bool& skipEmitters);

void addCompareOptions(CLI::App& cmd, CompareOptions& options);
int runCompare(const CompareOptions& options);
// --frames: each frame's metrics beside black's, and the flicker of every frame after the first
// against the reference's change (tools/compare_frames.cpp).
int runCompareFrames(const CompareOptions& options);

// The pixels a mask image keeps (non-zero in any channel), checked against the reference's size
// and to keep at least one; empty when `path` is empty.
std::vector<uint8_t> readMask(const std::string& path, const Image& reference);

// With `skip`, `mask` (empty: every pixel) without the pixels where REFERENCE.emission.exr (voxgi
// render --terms) is non-zero: what the camera sees of emitters and the background, which every
// technique copies, so that the metrics and the energy measure reflected light only. Throws
// InputError when the term is missing or the mask keeps nothing.
std::vector<uint8_t> withoutEmitters(bool skip, const std::string& referencePath,
                                     const Image& reference, std::vector<uint8_t> mask);

// An image every pixel of which is finite; throws InputError naming the first pixel that is not.
Image readReference(const std::string& path);

// Throws InputError naming `name` when width x height is not the reference's size.
void checkSameSize(int width, int height, const std::string& name, const Image& reference);

// The variance image beside a path-traced image (reference::variancePath), checked to be the
// reference's size; nothing when there is none.
std::optional<Image> readVarianceImage(const std::string& imagePath, const Image& reference);

}  // namespace voxgi::tools

#include "tools/compare.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>

#include <nlohmann/json.hpp>

#include "common/error.h"
#include "common/image_io.h"
#include "common/light_terms.h"
#include "common/output_file.h"
#include "validation/reference/image_metrics.h"
#include "validation/reference/path_trace.h"

namespace voxgi::tools {
namespace {

bool finite(glm::vec3 p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

}  // namespace

void addCompareOptions(CLI::App& cmd, CompareOptions& o) {
  cmd.add_option("test", o.test, "image to measure (.exr, or .png as sRGB)")->required();
  cmd.add_option("reference", o.reference, "reference image, e.g. a path-traced .exr")->required();
  cmd.add_option("--mask", o.mask, "image of the same size: only pixels non-zero here count");
  cmd.add_option("--error-png", o.errorPng,
                 "false-colour relative error map (default: TEST's name + .error.png)");
  cmd.add_option("--json", o.json, "also write the metrics as JSON");
  cmd.add_option("--scanline", o.scanline,
                 "a row (0: the top) whose linear luminance of both images goes into the JSON, "
                 "for tools/plot_scanline.py")
      ->check(CLI::NonNegativeNumber);
  cmd.add_flag("--terms", o.terms,
               "also measure each light term (voxgi render --terms wrote TEST.<term>.exr and "
               "REFERENCE.<term>.exr), with an error map per term");
}

// The error map of `image`: --error-png's name, else IMAGE's name + .error.png.
std::string errorMapPath(const std::string& image, const std::string& given) {
  if (!given.empty()) return given;
  const std::filesystem::path t(image);
  return (t.parent_path() / (t.stem().string() + ".error.png")).string();
}

// A term's error map: the term image's (TEST.<term>.error.png), or --error-png's name with the
// term before its extension.
std::string termErrorMapPath(const CompareOptions& o, LightTerm term) {
  return o.errorPng.empty() ? errorMapPath(termPath(o.test, term), "") : termPath(o.errorPng, term);
}

nlohmann::json printTermBudget(const CompareOptions& o, const Image& reference,
                               const std::vector<uint8_t>& mask) {
  const std::string &testPath = o.test, &referencePath = o.reference;
  const TermImages test = readTermImages(testPath), expected = readTermImages(referencePath);
  for (const LightTerm term : kLightTerms)
    checkSameSize(termImage(test, term).width, termImage(test, term).height,
                  termPath(testPath, term), termImage(expected, term));
  std::cout << "  per term: relMSE against the reference's term; share: what its error alone adds "
               "to the image's relMSE; brightness against the reference's\n"
            << "    term                relMSE      share       brightness\n";
  nlohmann::json out;
  for (const LightTerm term : kLightTerms) {
    const reference::TermMetrics m =
        reference::compareTerm(termImage(test, term), termImage(expected, term), reference, mask);
    const std::string name(termName(term));
    std::cout << "    " << std::left << std::setw(20) << name << std::setw(12) << m.own.relMse
              << std::setw(12) << m.share << m.meanRatio << std::right << "\n";
    const std::string png = termErrorMapPath(o, term);
    writeRgb8Png(png, reference.width, reference.height,
                 reference::errorColours(termImage(test, term), termImage(expected, term), mask));
    // JSON has no NaN: a term black in the reference has no brightness ratio.
    out[name] = {
        {"rel_mse", m.own.relMse},
        {"rmse", m.own.rmse},
        {"share", m.share},
        {"brightness", std::isnan(m.meanRatio) ? nlohmann::json() : nlohmann::json(m.meanRatio)},
        {"error_png", png}};
  }
  return out;
}

void checkSameSize(int width, int height, const std::string& name, const Image& reference) {
  if (width != reference.width || height != reference.height)
    throw InputError(name, "size",
                     std::to_string(width) + "x" + std::to_string(height) +
                         " differs from the reference's " + std::to_string(reference.width) + "x" +
                         std::to_string(reference.height));
}

std::optional<reference::ImageMetrics> referenceNoiseFloor(const std::string& referencePath,
                                                           const Image& reference,
                                                           const std::vector<uint8_t>& mask) {
  const std::string variance = reference::variancePath(referencePath);
  if (!std::filesystem::exists(variance)) return std::nullopt;
  const Image v = readExr(variance);
  checkSameSize(v.width, v.height, variance, reference);
  return reference::noiseFloor(reference, v, mask);
}

std::vector<uint8_t> readMask(const std::string& path, const Image& reference) {
  if (path.empty()) return {};
  const Image mask = readImage(path);
  checkSameSize(mask.width, mask.height, path, reference);
  std::vector<uint8_t> keep(mask.pixels.size());
  for (size_t e = 0; e < keep.size(); ++e) keep[e] = mask.pixels[e] != glm::vec3(0.0f) ? 1 : 0;
  if (std::find(keep.begin(), keep.end(), 1) == keep.end())
    throw InputError(path, "", "the mask keeps no pixel");
  return keep;
}

Image readReference(const std::string& path) {
  Image reference = readImage(path);
  for (int y = 0; y < reference.height; ++y)
    for (int x = 0; x < reference.width; ++x)
      if (!finite(reference.at(x, y)))
        throw InputError(path, "pixel (" + std::to_string(x) + ", " + std::to_string(y) + ")",
                         "not finite; a reference must be");
  return reference;
}

int runCompare(const CompareOptions& o) {
  const std::string errorPng = errorMapPath(o.test, o.errorPng);
  checkOutputPath(errorPng);
  if (o.terms)
    for (const LightTerm term : kLightTerms) checkOutputPath(termErrorMapPath(o, term));
  if (!o.json.empty()) checkOutputPath(o.json);
  const Image reference = readReference(o.reference);
  const Image test = readImage(o.test);
  checkSameSize(test.width, test.height, o.test, reference);
  const std::vector<uint8_t> mask = readMask(o.mask, reference);
  if (o.scanline >= reference.height)
    throw InputError("--scanline", "",
                     "row " + std::to_string(o.scanline) + " is outside the " +
                         std::to_string(reference.height) + "-row images");
  const reference::ImageMetrics m = reference::compareImages(test, reference, mask);
  std::cout << "compare " << o.test << " against " << o.reference << " (" << reference.width << "x"
            << reference.height << ", " << m.pixels << " pixels)\n"
            << "  RMSE    " << m.rmse << "\n"
            << "  relMSE  " << m.relMse << "\n"
            << "  MARE    " << m.mare << "\n"
            << "  SSIM    " << m.ssim << "\n";
  // NaN or Inf in the image under test is a finding, not bad input: the metrics show it too.
  const size_t nonFinite = size_t(std::count_if(test.pixels.begin(), test.pixels.end(),
                                                [](glm::vec3 p) { return !finite(p); }));
  if (nonFinite > 0) std::cout << "  non-finite pixels in " << o.test << ": " << nonFinite << "\n";
  nlohmann::json out{{"test", o.test}, {"reference", o.reference}, {"pixels", m.pixels},
                     {"rmse", m.rmse}, {"rel_mse", m.relMse},      {"mare", m.mare},
                     {"ssim", m.ssim}};
  // The reference's own error: a perfect image would still measure this far from it.
  if (const auto floor = referenceNoiseFloor(o.reference, reference, mask)) {
    std::cout << "  noise floor of the reference (" << reference::variancePath(o.reference)
              << "): RMSE " << floor->rmse << ", relMSE " << floor->relMse << "\n";
    out["noise_floor"] = {{"rmse", floor->rmse}, {"rel_mse", floor->relMse}};
  }
  writeRgb8Png(errorPng, reference.width, reference.height,
               reference::errorColours(test, reference, mask));
  std::cout << "  error map (|t - r| / (|r| + 0.01), log scale 1e-3 black .. 1 white) -> "
            << errorPng << "\n";
  if (o.terms) out["terms"] = printTermBudget(o, reference, mask);
  if (o.scanline >= 0) {
    // Rec. 709 luminance of the linear images.
    const auto row = [&](const Image& image) {
      std::vector<double> values;
      for (int x = 0; x < image.width; ++x) {
        const glm::vec3 p = image.at(x, o.scanline);
        values.push_back(0.2126 * p.x + 0.7152 * p.y + 0.0722 * p.z);
      }
      return values;
    };
    out["scanline"] = {{"row", o.scanline}, {"test", row(test)}, {"reference", row(reference)}};
  }
  if (!o.json.empty()) writeFileAtomically(o.json, out.dump(2) + "\n");
  return kExitOk;
}

}  // namespace voxgi::tools

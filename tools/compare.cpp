#include "tools/compare.h"
#include "tools/metrics_json.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>

#include <nlohmann/json.hpp>

#include "common/error.h"
#include "common/io/image_io.h"
#include "common/io/term_images.h"
#include "common/light_terms.h"
#include "common/io/output_file.h"
#include "validation/reference/image_metrics.h"
#include "validation/reference/path_trace.h"
#include "tools/command.h"

namespace voxgi::tools {
namespace {

bool finite(glm::vec3 p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

}  // namespace

void addUnitsOptions(CLI::App& cmd, reference::MetricUnits& units, bool& skipEmitters) {
  std::map<std::string, reference::MetricUnits> names;
  for (const auto& [name, value] : reference::kMetricUnitsNames) names.emplace(name, value);
  cmd.add_option("--units", units,
                 "mean: relative metrics and SSIM in units of the reference's mean per channel, "
                 "the same for the scene in any units (default); absolute: eps = 0.01 in the "
                 "images' own units, as published figures")
      ->transform(CLI::CheckedTransformer(names, CLI::ignore_case));
  cmd.add_flag("--skip-emitters", skipEmitters,
               "leave out the pixels where the reference sees an emitter or the background "
               "(REFERENCE.emission.exr, from render --terms, non-zero): reflected light only");
}

std::vector<uint8_t> withoutEmitters(bool skip, const std::string& referencePath,
                                     const Image& reference, std::vector<uint8_t> mask) {
  if (!skip) return mask;
  const std::string path = termPath(referencePath, LightTerm::emission);
  if (!std::filesystem::exists(path))
    throw InputError(path, "", "missing: --skip-emitters reads it (voxgi render --terms)");
  const Image emission = readExr(path);
  checkSameSize(emission.width, emission.height, path, reference);
  if (mask.empty()) mask.assign(reference.pixels.size(), 1);
  for (size_t e = 0; e < mask.size(); ++e)
    if (emission.pixels[e] != glm::vec3(0.0f)) mask[e] = 0;
  if (std::find(mask.begin(), mask.end(), 1) == mask.end())
    throw InputError(path, "", "--skip-emitters leaves no pixel: the reference sees only emission");
  return mask;
}

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
  addUnitsOptions(cmd, o.units, o.skipEmitters);
  cmd.add_option("--frames", o.frames,
                 "compare sequences: TEST and REFERENCE hold a frame field (%04d); per frame the "
                 "metrics, and from the second on the flicker: how the test's change from the "
                 "frame before differs from the reference's (docs/motion.md)");
}

namespace {

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

// One row of the metrics table; NaN prints as "-".
void printRow(const std::string& name, const reference::ImageMetrics& m) {
  const auto cell = [](double v, int width) {
    std::ostringstream out;
    if (std::isnan(v))
      out << "-";
    else
      out << std::setprecision(4) << v;
    return std::string(std::max(0, width - int(out.str().size())), ' ') + out.str();
  };
  std::cout << "  " << std::left << std::setw(14) << name << std::right << cell(m.rmse, 11)
            << cell(m.relMse, 11) << cell(m.mare, 11) << cell(m.ssim, 9) << cell(m.energy.r, 11)
            << cell(m.energy.g, 11) << cell(m.energy.b, 11) << "\n";
}

nlohmann::json printTermBudget(const CompareOptions& o, const Image& reference,
                               const TermImages& test, const std::vector<uint8_t>& mask,
                               const reference::MetricScale& scale) {
  const TermImages expected = readTermImages(o.reference);
  for (const LightTerm term : kLightTerms)
    checkSameSize(termImage(expected, term).width, termImage(expected, term).height,
                  termPath(o.reference, term), reference);
  std::cout << "  per term, in the whole reference's units: relMSE against the reference's term; "
               "share: what its error alone adds to the image's relMSE; brightness against the "
               "reference's; the shares of a black and of a constant term\n"
            << "    term                relMSE      share       brightness  black share "
               "constant share\n";
  nlohmann::json out;
  for (const LightTerm term : kLightTerms) {
    const Image& r = termImage(expected, term);
    const reference::TermMetrics m =
        reference::compareTerm(termImage(test, term), r, reference, mask, scale);
    const reference::TermMetrics black =
        reference::compareTerm(Image(r.width, r.height), r, reference, mask, scale);
    const reference::TermMetrics constant =
        reference::compareTerm(reference::meanImage(r, mask), r, reference, mask, scale);
    const std::string name(termName(term));
    std::cout << "    " << std::left << std::setw(20) << name << std::setw(12) << m.own.relMse
              << std::setw(12) << m.share << std::setw(12) << m.meanRatio << std::setw(12)
              << black.share << constant.share << std::right << "\n";
    const std::string png = termErrorMapPath(o, term);
    writeRgb8Png(png, reference.width, reference.height,
                 reference::errorColours(termImage(test, term), r, mask, scale));
    out[name] = {
        {"rel_mse", numberOrNull(m.own.relMse)},
        {"rmse", m.own.rmse},
        {"share", numberOrNull(m.share)},
        {"brightness", numberOrNull(m.meanRatio)},
        {"baselines",
         {{"black",
           {{"rel_mse", numberOrNull(black.own.relMse)}, {"share", numberOrNull(black.share)}}},
          {"constant",
           {{"rel_mse", numberOrNull(constant.own.relMse)},
            {"share", numberOrNull(constant.share)}}}}},
        {"error_png", png}};
  }
  return out;
}

}  // namespace

void checkSameSize(int width, int height, const std::string& name, const Image& reference) {
  if (width != reference.width || height != reference.height)
    throw InputError(name, "size",
                     std::to_string(width) + "x" + std::to_string(height) +
                         " differs from the reference's " + std::to_string(reference.width) + "x" +
                         std::to_string(reference.height));
}

std::optional<Image> readVarianceImage(const std::string& imagePath, const Image& reference) {
  const std::string path = reference::variancePath(imagePath);
  if (!std::filesystem::exists(path)) return std::nullopt;
  Image variance = readExr(path);
  checkSameSize(variance.width, variance.height, path, reference);
  return variance;
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

// The metrics of `test` against `reference` beside the black and constant baselines (and the
// image's direct light alone where its terms are given), printed and as the report's JSON.
nlohmann::json printMetrics(const CompareOptions& o, const Image& test, const Image& reference,
                            const std::vector<uint8_t>& mask, const reference::MetricScale& scale,
                            const std::optional<TermImages>& terms) {
  const reference::ImageMetrics m = reference::compareImages(test, reference, mask, scale);
  const reference::Baselines baselines = reference::trivialBaselines(reference, mask, scale);
  std::cout << "compare " << o.test << " against " << o.reference << " (" << reference.width << "x"
            << reference.height << ", " << m.pixels << " pixels)\n";
  if (!scale.defined)
    std::cout << "  the reference is black: relative metrics are undefined (-)\n";
  else if (o.units == reference::MetricUnits::reference_mean)
    std::cout << "  relMSE, MARE and SSIM in units of the reference's mean per channel ("
              << scale.unit.r << ", " << scale.unit.g << ", " << scale.unit.b
              << "); --units absolute for the images' own\n";
  else
    std::cout << "  relMSE, MARE and SSIM in the images' own units (--units absolute)\n";
  std::cout << "                       RMSE     relMSE       MARE     SSIM   energy r   energy g   "
               "energy b\n";
  printRow("image", m);
  std::cout << "  baselines on the same reference and mask:\n";
  printRow("black", baselines.black);
  printRow("constant", baselines.constant);
  nlohmann::json out = metricsJson(m);
  out["test"] = o.test;
  out["reference"] = o.reference;
  out["pixels"] = m.pixels;
  out["units"] = o.units == reference::MetricUnits::reference_mean ? "mean" : "absolute";
  out["unit"] = {scale.unit.r, scale.unit.g, scale.unit.b};
  out["baselines"] = {{"black", metricsJson(baselines.black)},
                      {"constant", metricsJson(baselines.constant)}};
  if (terms) {
    const reference::ImageMetrics direct =
        reference::compareImages(directOnly(*terms), reference, mask, scale);
    printRow("direct only", direct);
    std::cout << "  (constant: the reference's mean per channel; direct only: the image's emission "
                 "and direct terms, without its indirect light)\n";
    out["baselines"]["direct_only"] = metricsJson(direct);
  } else {
    std::cout << "  (constant: the reference's mean per channel; render --terms also gives the "
                 "image's direct light alone)\n";
  }
  return out;
}

// The reference's own error where a variance image lies beside it: a perfect image would still
// measure this far from it; and, both images path traced, whether their variance images predict
// their difference.
void printNoiseFloor(const CompareOptions& o, const Image& test, const Image& reference,
                     const std::vector<uint8_t>& mask, const reference::MetricScale& scale,
                     nlohmann::json& out) {
  const std::optional<Image> rv = readVarianceImage(o.reference, reference);
  if (!rv) return;
  const reference::ImageMetrics floor = reference::noiseFloor(reference, *rv, mask, scale);
  std::cout << "  noise floor of the reference (" << reference::variancePath(o.reference)
            << "): RMSE " << floor.rmse << ", relMSE " << floor.relMse << "\n";
  out["noise_floor"] = {{"rmse", floor.rmse}, {"rel_mse", floor.relMse}};
  if (const std::optional<Image> tv = readVarianceImage(o.test, reference)) {
    const reference::ZSpread z = reference::zSpread(test, *tv, reference, *rv, mask);
    std::cout << "  z = (t - r) / sqrt(both variances): mean " << z.mean << ", standard deviation "
              << z.deviation << " over " << z.values
              << " values (1: the variance images predict the error)\n";
    out["z"] = {{"mean", z.mean}, {"deviation", z.deviation}, {"values", z.values}};
  }
}

// Row `row`'s Rec. 709 luminance in both linear images.
nlohmann::json scanlineJson(int row, const Image& test, const Image& reference) {
  const auto luminance = [&](const Image& image) {
    std::vector<double> values;
    for (int x = 0; x < image.width; ++x) {
      const glm::vec3 p = image.at(x, row);
      values.push_back(0.2126 * p.x + 0.7152 * p.y + 0.0722 * p.z);
    }
    return values;
  };
  return {{"row", row}, {"test", luminance(test)}, {"reference", luminance(reference)}};
}

int runCompare(const CompareOptions& o) {
  if (!o.frames.empty()) return runCompareFrames(o);
  const std::string errorPng = errorMapPath(o.test, o.errorPng);
  checkOutputPath(errorPng);
  if (o.terms)
    for (const LightTerm term : kLightTerms) checkOutputPath(termErrorMapPath(o, term));
  if (!o.json.empty()) checkOutputPath(o.json);
  const Image reference = readReference(o.reference);
  const Image test = readImage(o.test);
  checkSameSize(test.width, test.height, o.test, reference);
  const std::vector<uint8_t> mask =
      withoutEmitters(o.skipEmitters, o.reference, reference, readMask(o.mask, reference));
  if (o.scanline >= reference.height)
    throw InputError("--scanline", "",
                     "row " + std::to_string(o.scanline) + " is outside the " +
                         std::to_string(reference.height) + "-row images");
  // The test's light terms: required by --terms, else used when they lie beside it.
  std::optional<TermImages> terms;
  if (o.terms || std::filesystem::exists(termPath(o.test, LightTerm::direct))) {
    terms = readTermImages(o.test);
    for (const LightTerm term : kLightTerms)
      checkSameSize(termImage(*terms, term).width, termImage(*terms, term).height,
                    termPath(o.test, term), reference);
  }
  const reference::MetricScale scale = reference::metricScale(reference, mask, o.units);
  nlohmann::json out = printMetrics(o, test, reference, mask, scale, terms);
  // NaN or Inf in the image under test is a finding, not bad input: the metrics show it too.
  const size_t nonFinite = size_t(std::count_if(test.pixels.begin(), test.pixels.end(),
                                                [](glm::vec3 p) { return !finite(p); }));
  if (nonFinite > 0) std::cout << "  non-finite pixels in " << o.test << ": " << nonFinite << "\n";
  printNoiseFloor(o, test, reference, mask, scale, out);
  writeRgb8Png(errorPng, reference.width, reference.height,
               reference::errorColours(test, reference, mask, scale));
  std::cout << "  error map (|t - r| / (|r| + 0.01 u), log scale 1e-3 black .. 1 white) -> "
            << errorPng << "\n";
  if (o.terms) out["terms"] = printTermBudget(o, reference, *terms, mask, scale);
  if (o.scanline >= 0) out["scanline"] = scanlineJson(o.scanline, test, reference);
  if (!o.json.empty()) writeFileAtomically(o.json, out.dump(2) + "\n");
  return kExitOk;
}

void addCompareCommand(CLI::App& app, Commands& commands) {
  auto o = std::make_shared<CompareOptions>();
  CLI::App* cmd = app.add_subcommand(
      "compare", "RMSE, relative MSE, MARE and SSIM of an image against a reference");
  addCompareOptions(*cmd, *o);
  commands.push_back({cmd, [o] { return runCompare(*o); }});
}

}  // namespace voxgi::tools

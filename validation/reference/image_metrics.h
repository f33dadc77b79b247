// Image error metrics against a reference (docs/accuracy.md): RMSE, relative MSE, mean absolute
// relative error, SSIM and the energy ratio per channel, over the pixels a mask keeps; what
// trivial answers score on the same reference; a false-colour map of the error.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "common/image.h"

namespace voxgi::reference {

// The units the relative metrics and SSIM measure in.
enum class MetricUnits {
  // Each channel in units of the reference's mean over the mask: the same scene in other units,
  // or with every light and emitter scaled, scores the same (the default).
  reference_mean,
  // The images' own units, as published figures use them [Rousselle et al. 2011]: the epsilon is
  // absolute radiance, so the scores depend on the scene's units.
  absolute
};
inline constexpr std::pair<const char*, MetricUnits> kMetricUnitsNames[] = {
    {"mean", MetricUnits::reference_mean}, {"absolute", MetricUnits::absolute}};

// Keeps the relative metrics finite where the reference is black [Rousselle et al. 2011]: the
// denominators are r^2 + eps u^2 and |r| + eps u, u a channel's unit.
constexpr double kRelativeEpsilon = 0.01;
// The display value SSIM puts the reference's mean luminance at under MetricUnits::reference_mean:
// photographic middle grey [Reinhard et al. 2002].
constexpr double kMiddleGrey = 0.18;

// The unit of each channel and the exposure SSIM displays both images at, from a reference.
struct MetricScale {
  glm::dvec3 unit{1.0};
  double exposure = 1.0;
  // False when the reference is black over the mask under MetricUnits::reference_mean: an error
  // relative to nothing is undefined, and the relative metrics are NaN.
  bool defined = true;
};
// reference_mean: u_c = the channel's mean over the mask (a black channel takes the mean of the
// three, so a red scene's blue channel stays finite); exposure = kMiddleGrey / the mean's Rec. 709
// luminance. absolute: u = 1, exposure 1 (SSIM sees the preview PNG's values).
MetricScale metricScale(const Image& reference, const std::vector<uint8_t>& mask,
                        MetricUnits units);

struct ImageMetrics {
  double rmse = 0.0;       // sqrt(mean (t - r)^2), over pixels and channels (the images' units)
  double relMse = 0.0;     // mean (t - r)^2 / (r^2 + eps u^2)
  double mare = 0.0;       // mean |t - r| / (|r| + eps u)
  double ssim = 1.0;       // mean SSIM of the display luminance (11x11 Gaussian window, sigma 1.5)
  glm::dvec3 energy{1.0};  // per channel, sum of t over sum of r: 1 carries the reference's light
                           // (NaN where the reference's channel is black)
  size_t pixels = 0;       // pixels the mask keeps
};

// `mask`: empty (every pixel) or one byte per pixel, non-zero to keep it. The images must have
// the same size (the caller checks and names the file).
ImageMetrics compareImages(const Image& test, const Image& reference,
                           const std::vector<uint8_t>& mask = {},
                           MetricUnits units = MetricUnits::reference_mean);
// With the scale of another image: a light term measured in the units of the whole reference.
ImageMetrics compareImages(const Image& test, const Image& reference,
                           const std::vector<uint8_t>& mask, const MetricScale& scale);

// What trivial answers score against the same reference and mask: an all-black image, and a
// constant image at the reference's mean per channel over the mask.
struct Baselines {
  ImageMetrics black, constant;
};
Baselines trivialBaselines(const Image& reference, const std::vector<uint8_t>& mask,
                           const MetricScale& scale);
// The constant image trivialBaselines scores.
Image meanImage(const Image& reference, const std::vector<uint8_t>& mask);

// The error budget of one light term (common/light_terms.h): `test` and `reference` are the term
// of the image under test and of the reference, `whole` the whole reference image, whose scale
// (metricScale) every term is measured in.
struct TermMetrics {
  ImageMetrics own;        // the term against the reference's term
  double share = 0.0;      // mean (t - r)^2 / (R^2 + eps u^2), R from `whole`: what this term's
                           // error alone adds to the whole image's relMSE
  double meanRatio = 0.0;  // sum of t over sum of r (1: as bright as the reference; NaN where
                           // the reference's term is black)
};
TermMetrics compareTerm(const Image& test, const Image& reference, const Image& whole,
                        const std::vector<uint8_t>& mask, const MetricScale& scale);

// The error a perfect image would still measure against a Monte Carlo reference whose per-pixel
// variance of the mean is `variance`: RMSE = sqrt(mean variance) and relative MSE = mean
// variance / (r^2 + eps u^2); the other fields stay 0.
ImageMetrics noiseFloor(const Image& reference, const Image& variance,
                        const std::vector<uint8_t>& mask, const MetricScale& scale);

// Whether two Monte Carlo images' variance images predict their difference: the mean and standard
// deviation of z = (t - r) / sqrt(var_t + var_r) over the kept values whose variance is not zero
// (1 and 0 when they do; below 1 when the variances overstate the error). `values` counts them.
struct ZSpread {
  double mean = 0.0, deviation = 0.0;
  size_t values = 0;
};
ZSpread zSpread(const Image& test, const Image& testVariance, const Image& reference,
                const Image& referenceVariance, const std::vector<uint8_t>& mask);

// Per pixel |t - r| / (|r| + eps u) averaged over the channels, as sRGB colours on a logarithmic
// scale from 1e-3 (black) through blue, red and yellow to 1 and above (white); pixels outside
// the mask are mid grey. Row-major RGB, 3 bytes a pixel.
std::vector<unsigned char> errorColours(const Image& test, const Image& reference,
                                        const std::vector<uint8_t>& mask, const MetricScale& scale);

}  // namespace voxgi::reference

// Image error metrics against a reference (docs/accuracy.md): RMSE, relative MSE, mean absolute
// relative error and SSIM, over the pixels a mask keeps, plus a false-colour map of the error.
#pragma once

#include <cstdint>
#include <vector>

#include "common/image_io.h"

namespace voxgi::reference {

struct ImageMetrics {
  double rmse = 0.0;    // sqrt(mean (t - r)^2), over pixels and channels
  double relMse = 0.0;  // mean (t - r)^2 / (r^2 + eps)
  double mare = 0.0;    // mean |t - r| / (|r| + eps)
  double ssim = 1.0;    // mean SSIM of the display luminance (11x11 Gaussian window, sigma 1.5)
  size_t pixels = 0;    // pixels the mask keeps
};

// Keeps the relative metrics finite where the reference is black (Rousselle et al. 2011).
constexpr double kRelativeEpsilon = 0.01;

// `mask`: empty (every pixel) or one byte per pixel, non-zero to keep it. The images must have
// the same size (the caller checks and names the file).
ImageMetrics compareImages(const Image& test, const Image& reference,
                           const std::vector<uint8_t>& mask = {});

// The error budget of one light term (common/light_terms.h): `test` and `reference` are the term
// of the image under test and of the reference, `whole` the whole reference image.
struct TermMetrics {
  ImageMetrics own;        // the term against the reference's term
  double share = 0.0;      // mean (t - r)^2 / (R^2 + eps), R from `whole`: what this term's
                           // error alone adds to the whole image's relMSE
  double meanRatio = 0.0;  // sum of t over sum of r (1: as bright as the reference; NaN where
                           // the reference's term is black)
};
TermMetrics compareTerm(const Image& test, const Image& reference, const Image& whole,
                        const std::vector<uint8_t>& mask = {});

// The error a perfect image would still measure against a Monte Carlo reference whose per-pixel
// variance of the mean is `variance`: RMSE = sqrt(mean variance) and relative MSE = mean
// variance / (r^2 + eps); the other fields stay 0.
ImageMetrics noiseFloor(const Image& reference, const Image& variance,
                        const std::vector<uint8_t>& mask = {});

// Per pixel |t - r| / (|r| + eps) averaged over the channels, as sRGB colours on a logarithmic
// scale from 1e-3 (black) through blue, red and yellow to 1 and above (white); pixels outside
// the mask are mid grey. Row-major RGB, 3 bytes a pixel.
std::vector<unsigned char> errorColours(const Image& test, const Image& reference,
                                        const std::vector<uint8_t>& mask = {});

}  // namespace voxgi::reference

#include "validation/reference/image_metrics.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace voxgi::reference {
namespace {

bool kept(const std::vector<uint8_t>& mask, size_t e) {
  return mask.empty() || mask[e] != 0;
}

// The luminance SSIM works on: the preview PNG's value (clamp to [0, 1], sRGB curve) of each
// channel, weighted by Rec. 709.
double displayLuminance(glm::vec3 linear) {
  return 0.2126 * double(linearToSrgb(linear.r)) + 0.7152 * double(linearToSrgb(linear.g)) +
         0.0722 * double(linearToSrgb(linear.b));
}

// SSIM (Wang et al. 2004) with the usual constants for values in [0, 1]: an 11x11 Gaussian window
// of sigma 1.5 (weights sum to 1), C1 = (0.01)^2, C2 = (0.03)^2. Windows are clipped at the image
// border and renormalised, so every pixel has a value and small images work.
double meanSsim(const Image& test, const Image& reference, const std::vector<uint8_t>& mask) {
  constexpr int kRadius = 5;
  constexpr double kSigma = 1.5, kC1 = 0.01 * 0.01, kC2 = 0.03 * 0.03;
  std::array<double, 2 * kRadius + 1> g{};
  for (int k = -kRadius; k <= kRadius; ++k)
    g[size_t(k + kRadius)] = std::exp(-double(k * k) / (2.0 * kSigma * kSigma));
  const int w = reference.width, h = reference.height;
  std::vector<double> x(size_t(w) * size_t(h)), y(x.size());
  for (size_t e = 0; e < x.size(); ++e) {
    x[e] = displayLuminance(test.pixels[e]);
    y[e] = displayLuminance(reference.pixels[e]);
  }
  double sum = 0.0;
  size_t count = 0;
  for (int py = 0; py < h; ++py)
    for (int px = 0; px < w; ++px) {
      if (!kept(mask, size_t(py) * size_t(w) + size_t(px))) continue;
      double weight = 0.0, mx = 0.0, my = 0.0, xx = 0.0, yy = 0.0, xy = 0.0;
      for (int dy = -kRadius; dy <= kRadius; ++dy) {
        const int qy = py + dy;
        if (qy < 0 || qy >= h) continue;
        for (int dx = -kRadius; dx <= kRadius; ++dx) {
          const int qx = px + dx;
          if (qx < 0 || qx >= w) continue;
          const double gw = g[size_t(dx + kRadius)] * g[size_t(dy + kRadius)];
          const size_t q = size_t(qy) * size_t(w) + size_t(qx);
          weight += gw;
          mx += gw * x[q];
          my += gw * y[q];
          xx += gw * x[q] * x[q];
          yy += gw * y[q] * y[q];
          xy += gw * x[q] * y[q];
        }
      }
      mx /= weight;
      my /= weight;
      const double vx = std::max(xx / weight - mx * mx, 0.0);
      const double vy = std::max(yy / weight - my * my, 0.0);
      const double cxy = xy / weight - mx * my;
      sum +=
          (2.0 * mx * my + kC1) * (2.0 * cxy + kC2) / ((mx * mx + my * my + kC1) * (vx + vy + kC2));
      ++count;
    }
  return count == 0 ? 1.0 : sum / double(count);
}

}  // namespace

ImageMetrics compareImages(const Image& test, const Image& reference,
                           const std::vector<uint8_t>& mask) {
  ImageMetrics m;
  double squared = 0.0, relative = 0.0, absolute = 0.0;
  for (size_t e = 0; e < reference.pixels.size(); ++e) {
    if (!kept(mask, e)) continue;
    ++m.pixels;
    for (int c = 0; c < 3; ++c) {
      const double t = test.pixels[e][c], r = reference.pixels[e][c], d = t - r;
      squared += d * d;
      relative += d * d / (r * r + kRelativeEpsilon);
      absolute += std::abs(d) / (std::abs(r) + kRelativeEpsilon);
    }
  }
  if (m.pixels == 0) return m;
  const double values = 3.0 * double(m.pixels);
  m.rmse = std::sqrt(squared / values);
  m.relMse = relative / values;
  m.mare = absolute / values;
  m.ssim = meanSsim(test, reference, mask);
  return m;
}

TermMetrics compareTerm(const Image& test, const Image& reference, const Image& whole,
                        const std::vector<uint8_t>& mask) {
  TermMetrics m;
  m.own = compareImages(test, reference, mask);
  double share = 0.0, sumTest = 0.0, sumReference = 0.0;
  for (size_t e = 0; e < reference.pixels.size(); ++e) {
    if (!kept(mask, e)) continue;
    for (int c = 0; c < 3; ++c) {
      const double t = test.pixels[e][c], r = reference.pixels[e][c], w = whole.pixels[e][c];
      share += (t - r) * (t - r) / (w * w + kRelativeEpsilon);
      sumTest += t;
      sumReference += r;
    }
  }
  if (m.own.pixels == 0) return m;
  m.share = share / (3.0 * double(m.own.pixels));
  m.meanRatio = sumReference != 0.0 ? sumTest / sumReference : std::nan("");
  return m;
}

ImageMetrics noiseFloor(const Image& reference, const Image& variance,
                        const std::vector<uint8_t>& mask) {
  ImageMetrics m;
  m.ssim = 0.0;
  double sum = 0.0, relative = 0.0;
  for (size_t e = 0; e < reference.pixels.size(); ++e) {
    if (!kept(mask, e)) continue;
    ++m.pixels;
    for (int c = 0; c < 3; ++c) {
      const double r = reference.pixels[e][c];
      sum += variance.pixels[e][c];
      relative += variance.pixels[e][c] / (r * r + kRelativeEpsilon);
    }
  }
  if (m.pixels == 0) return m;
  const double values = 3.0 * double(m.pixels);
  m.rmse = std::sqrt(sum / values);
  m.relMse = relative / values;
  return m;
}

std::vector<unsigned char> errorColours(const Image& test, const Image& reference,
                                        const std::vector<uint8_t>& mask) {
  // Keys at log10(error) = -3, -2.25, -1.5, -0.75, 0: black, blue, red, yellow, white.
  constexpr std::array<std::array<float, 3>, 5> kKeys{
      {{0, 0, 0}, {0.1f, 0.2f, 0.9f}, {0.9f, 0.1f, 0.1f}, {1, 0.85f, 0.1f}, {1, 1, 1}}};
  std::vector<unsigned char> out(reference.pixels.size() * 3, 128);
  for (size_t e = 0; e < reference.pixels.size(); ++e) {
    if (!kept(mask, e)) continue;
    double error = 0.0;
    for (int c = 0; c < 3; ++c)
      error += std::abs(double(test.pixels[e][c]) - double(reference.pixels[e][c])) /
               (std::abs(double(reference.pixels[e][c])) + kRelativeEpsilon) / 3.0;
    // NaN maps to the top of the scale, where it is seen.
    const double s = std::isnan(error)
                         ? 4.0
                         : std::clamp((std::log10(std::max(error, 1e-3)) + 3.0) / 0.75, 0.0, 4.0);
    const size_t k = std::min(size_t(s), size_t(3));
    const float f = float(s - double(k));
    for (size_t c = 0; c < 3; ++c)
      out[e * 3 + c] = static_cast<unsigned char>(
          std::lround(255.0f * (kKeys[k][c] + (kKeys[k + 1][c] - kKeys[k][c]) * f)));
  }
  return out;
}

}  // namespace voxgi::reference

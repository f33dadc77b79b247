#include "validation/reference/image_metrics.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace voxgi::reference {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

bool kept(const std::vector<uint8_t>& mask, size_t e) {
  return mask.empty() || mask[e] != 0;
}

double rec709(glm::dvec3 c) {
  return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
}

// The luminance SSIM works on: the preview PNG's value (clamp to [0, 1], sRGB curve) of each
// channel after the exposure, weighted by Rec. 709.
double displayLuminance(glm::vec3 linear, float exposure) {
  const glm::vec3 v = linear * exposure;
  return rec709({linearToSrgb(v.r), linearToSrgb(v.g), linearToSrgb(v.b)});
}

// SSIM (Wang et al. 2004) with the usual constants for values in [0, 1]: an 11x11 Gaussian window
// of sigma 1.5 (weights sum to 1), C1 = (0.01)^2, C2 = (0.03)^2. Windows are clipped at the image
// border and renormalised, so every pixel has a value and small images work.
double meanSsim(const Image& test, const Image& reference, const std::vector<uint8_t>& mask,
                float exposure) {
  constexpr int kRadius = 5;
  constexpr double kSigma = 1.5, kC1 = 0.01 * 0.01, kC2 = 0.03 * 0.03;
  std::array<double, 2 * kRadius + 1> g{};
  for (int k = -kRadius; k <= kRadius; ++k)
    g[size_t(k + kRadius)] = std::exp(-double(k * k) / (2.0 * kSigma * kSigma));
  const int w = reference.width, h = reference.height;
  std::vector<double> x(size_t(w) * size_t(h)), y(x.size());
  for (size_t e = 0; e < x.size(); ++e) {
    x[e] = displayLuminance(test.pixels[e], exposure);
    y[e] = displayLuminance(reference.pixels[e], exposure);
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

// Per channel, the sum over the kept pixels.
glm::dvec3 channelSums(const Image& image, const std::vector<uint8_t>& mask) {
  glm::dvec3 sum(0.0);
  for (size_t e = 0; e < image.pixels.size(); ++e)
    if (kept(mask, e)) sum += glm::dvec3(image.pixels[e]);
  return sum;
}

size_t keptCount(const std::vector<uint8_t>& mask, size_t pixels) {
  return mask.empty()
             ? pixels
             : size_t(std::count_if(mask.begin(), mask.end(), [](uint8_t m) { return m != 0; }));
}

}  // namespace

MetricScale metricScale(const Image& reference, const std::vector<uint8_t>& mask,
                        MetricUnits units) {
  MetricScale s;
  if (units == MetricUnits::absolute) return s;
  const size_t pixels = keptCount(mask, reference.pixels.size());
  const glm::dvec3 mean =
      pixels == 0 ? glm::dvec3(0.0) : channelSums(reference, mask) / double(pixels);
  const double overall = (mean.r + mean.g + mean.b) / 3.0;
  if (!(overall > 0.0)) {
    s.defined = false;
    return s;
  }
  for (int c = 0; c < 3; ++c) s.unit[c] = mean[c] > 0.0 ? mean[c] : overall;
  const double luminance = rec709(mean);
  s.exposure = luminance > 0.0 ? kMiddleGrey / luminance : 1.0;
  return s;
}

ImageMetrics compareImages(const Image& test, const Image& reference,
                           const std::vector<uint8_t>& mask, MetricUnits units) {
  return compareImages(test, reference, mask, metricScale(reference, mask, units));
}

ImageMetrics compareImages(const Image& test, const Image& reference,
                           const std::vector<uint8_t>& mask, const MetricScale& scale) {
  ImageMetrics m;
  double squared = 0.0, relative = 0.0, absolute = 0.0;
  const glm::dvec3 floor = kRelativeEpsilon * scale.unit,
                   floorSquared = kRelativeEpsilon * scale.unit * scale.unit;
  for (size_t e = 0; e < reference.pixels.size(); ++e) {
    if (!kept(mask, e)) continue;
    ++m.pixels;
    for (int c = 0; c < 3; ++c) {
      const double t = test.pixels[e][c], r = reference.pixels[e][c], d = t - r;
      squared += d * d;
      relative += d * d / (r * r + floorSquared[c]);
      absolute += std::abs(d) / (std::abs(r) + floor[c]);
    }
  }
  if (m.pixels == 0) return m;
  const double values = 3.0 * double(m.pixels);
  m.rmse = std::sqrt(squared / values);
  m.relMse = scale.defined ? relative / values : kNaN;
  m.mare = scale.defined ? absolute / values : kNaN;
  m.ssim = meanSsim(test, reference, mask, float(scale.exposure));
  const glm::dvec3 t = channelSums(test, mask), r = channelSums(reference, mask);
  for (int c = 0; c < 3; ++c) m.energy[c] = r[c] != 0.0 ? t[c] / r[c] : kNaN;
  return m;
}

Image meanImage(const Image& reference, const std::vector<uint8_t>& mask) {
  const size_t pixels = keptCount(mask, reference.pixels.size());
  const glm::dvec3 mean =
      pixels == 0 ? glm::dvec3(0.0) : channelSums(reference, mask) / double(pixels);
  Image out(reference.width, reference.height);
  std::fill(out.pixels.begin(), out.pixels.end(), glm::vec3(mean));
  return out;
}

Baselines trivialBaselines(const Image& reference, const std::vector<uint8_t>& mask,
                           const MetricScale& scale) {
  return {compareImages(Image(reference.width, reference.height), reference, mask, scale),
          compareImages(meanImage(reference, mask), reference, mask, scale)};
}

TermMetrics compareTerm(const Image& test, const Image& reference, const Image& whole,
                        const std::vector<uint8_t>& mask, const MetricScale& scale) {
  TermMetrics m;
  m.own = compareImages(test, reference, mask, scale);
  double share = 0.0;
  const glm::dvec3 floorSquared = kRelativeEpsilon * scale.unit * scale.unit;
  for (size_t e = 0; e < reference.pixels.size(); ++e) {
    if (!kept(mask, e)) continue;
    for (int c = 0; c < 3; ++c) {
      const double t = test.pixels[e][c], r = reference.pixels[e][c], w = whole.pixels[e][c];
      share += (t - r) * (t - r) / (w * w + floorSquared[c]);
    }
  }
  if (m.own.pixels == 0) return m;
  m.share = scale.defined ? share / (3.0 * double(m.own.pixels)) : kNaN;
  const glm::dvec3 t = channelSums(test, mask), r = channelSums(reference, mask);
  const double sumReference = r.r + r.g + r.b;
  m.meanRatio = sumReference != 0.0 ? (t.r + t.g + t.b) / sumReference : kNaN;
  return m;
}

ImageMetrics noiseFloor(const Image& reference, const Image& variance,
                        const std::vector<uint8_t>& mask, const MetricScale& scale) {
  ImageMetrics m;
  m.ssim = 0.0;
  m.energy = glm::dvec3(kNaN);
  double sum = 0.0, relative = 0.0;
  const glm::dvec3 floorSquared = kRelativeEpsilon * scale.unit * scale.unit;
  for (size_t e = 0; e < reference.pixels.size(); ++e) {
    if (!kept(mask, e)) continue;
    ++m.pixels;
    for (int c = 0; c < 3; ++c) {
      const double r = reference.pixels[e][c];
      sum += variance.pixels[e][c];
      relative += variance.pixels[e][c] / (r * r + floorSquared[c]);
    }
  }
  if (m.pixels == 0) return m;
  const double values = 3.0 * double(m.pixels);
  m.rmse = std::sqrt(sum / values);
  m.relMse = scale.defined ? relative / values : kNaN;
  return m;
}

ZSpread zSpread(const Image& test, const Image& testVariance, const Image& reference,
                const Image& referenceVariance, const std::vector<uint8_t>& mask) {
  ZSpread z;
  double sum = 0.0, square = 0.0;
  for (size_t e = 0; e < reference.pixels.size(); ++e) {
    if (!kept(mask, e)) continue;
    for (int c = 0; c < 3; ++c) {
      const double v = double(testVariance.pixels[e][c]) + double(referenceVariance.pixels[e][c]);
      if (!(v > 0.0)) continue;
      const double value =
          (double(test.pixels[e][c]) - double(reference.pixels[e][c])) / std::sqrt(v);
      sum += value;
      square += value * value;
      ++z.values;
    }
  }
  if (z.values == 0) return z;
  z.mean = sum / double(z.values);
  z.deviation = std::sqrt(std::max(square / double(z.values) - z.mean * z.mean, 0.0));
  return z;
}

std::vector<unsigned char> errorColours(const Image& test, const Image& reference,
                                        const std::vector<uint8_t>& mask,
                                        const MetricScale& scale) {
  // Keys at log10(error) = -3, -2.25, -1.5, -0.75, 0: black, blue, red, yellow, white.
  constexpr std::array<std::array<float, 3>, 5> kKeys{
      {{0, 0, 0}, {0.1f, 0.2f, 0.9f}, {0.9f, 0.1f, 0.1f}, {1, 0.85f, 0.1f}, {1, 1, 1}}};
  const glm::dvec3 floor = kRelativeEpsilon * scale.unit;
  std::vector<unsigned char> out(reference.pixels.size() * 3, 128);
  for (size_t e = 0; e < reference.pixels.size(); ++e) {
    if (!kept(mask, e)) continue;
    double error = 0.0;
    for (int c = 0; c < 3; ++c)
      error += std::abs(double(test.pixels[e][c]) - double(reference.pixels[e][c])) /
               (std::abs(double(reference.pixels[e][c])) + floor[c]) / 3.0;
    // NaN (an error relative to a black reference, or NaN under test) maps to the top of the
    // scale, where it is seen.
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

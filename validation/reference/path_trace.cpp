#include "validation/reference/path_trace.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <vector>

#include "common/memory.h"
#include "common/parallel.h"
#include "common/scene_io/ray_scene.h"
#include "validation/reference/emitters.h"
#include "validation/reference/sampler.h"

namespace voxgi::reference {
namespace {

using glm::dvec3;
using glm::vec3;

float maxComponent(vec3 c) {
  return std::max({c.x, c.y, c.z});
}

// An orthonormal basis around n (Duff et al. 2017).
void basis(vec3 n, vec3& t, vec3& b) {
  const float s = std::copysign(1.0f, n.z);
  const float a = -1.0f / (s + n.z);
  const float c = n.x * n.y * a;
  t = vec3(1.0f + s * n.x * n.x * a, s * c, -s * n.x);
  b = vec3(c, s + n.y * n.y * a, -n.y);
}

vec3 around(vec3 n, float cosTheta, float phi) {
  vec3 t, b;
  basis(n, t, b);
  const float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
  return sinTheta * std::cos(phi) * t + sinTheta * std::sin(phi) * b + cosTheta * n;
}

// A BSDF value split by lobe: the Lambertian and the Phong part.
struct Lobes {
  vec3 diffuse{0.0f}, specular{0.0f};
  vec3 sum() const { return diffuse + specular; }
};

// What one camera path brings back: the radiance and its split into the light terms
// (common/light_terms.h), indexed by LightTerm.
struct PathSample {
  vec3 radiance{0.0f};
  std::array<vec3, kLightTerms.size()> terms{};
  vec3& term(LightTerm t) { return terms[size_t(t)]; }
};

// The reflectance and emission at a hit: its material's, with a point's own colour as albedo.
struct Shading {
  vec3 albedo, specular, emission;
  float shininess;
  bool emissive() const { return maxComponent(emission) > 0.0f; }
};

Shading shadingOf(const Material& m) {
  return {m.albedo, m.specular, m.emission, m.shininess};
}

// A mesh's texture coordinates at a point of triangle `t` with barycentric weights b of its second
// and third vertices.
glm::vec2 texcoordAt(const Mesh& mesh, uint32_t t, glm::vec2 b) {
  const glm::uvec3& tri = mesh.triangles[t];
  return (1.0f - b.x - b.y) * mesh.texcoord(tri.x) + b.x * mesh.texcoord(tri.y) +
         b.y * mesh.texcoord(tri.z);
}

// A material's albedo and emission at texture coordinates uv, point-sampled (bilinear, level 0):
// the tracer's many paths per pixel do the filtering.
Shading texturedShading(const Scene& scene, const Material& m, glm::vec2 uv) {
  Shading s = shadingOf(m);
  const TextureAccess textures{scene.textures};
  s.albedo = shared::texturedValue(textures, m.albedo, m.albedoTexture, uv, 0.0f);
  s.emission = shared::texturedValue(textures, m.emission, m.emissionTexture, uv, 0.0f);
  return s;
}

// Everything the tracer sees is relative to the centre of the scene's bounds, subtracted in double
// before anything becomes float, so that a scene 1e12 units from the origin renders as it does at
// the origin (float world coordinates would keep a few digits there).
struct Setup {
  dvec3 origin{0.0};
  RayScene rays{RayScene::BuildQuality::high};  // built once, traced millions of times
  std::vector<std::vector<vec3>> normals;       // per mesh, per triangle: unit right-hand normal
  Emitters emitters;
  float sceneScale = 1.0f;           // bounds diagonal, for the ray offset
  std::vector<vec3> lightPositions;  // per light, relative to origin

  // A world position in the tracer's frame.
  vec3 local(const dvec3& p) const { return vec3(p - origin); }

  explicit Setup(const Scene& scene) {
    const auto [lo, hi] = scene.bounds();
    if (lo.x <= hi.x) {
      sceneScale = float(glm::length(hi - lo));
      origin = 0.5 * (lo + hi);
    }
    for (const Light& l : scene.lights) lightPositions.push_back(local(l.position));
    normals.resize(scene.meshes.size());
    for (size_t m = 0; m < scene.meshes.size(); ++m) {
      const Mesh& mesh = scene.meshes[m];
      std::vector<vec3> vertices;
      vertices.reserve(mesh.positions.size());
      for (const dvec3& p : mesh.positions) vertices.push_back(local(p));
      rays.addMesh(unsigned(m), vertices, mesh.triangles);
      for (const glm::uvec3& tri : mesh.triangles) {
        const dvec3 a = mesh.positions[tri.x], b = mesh.positions[tri.y], c = mesh.positions[tri.z];
        const dvec3 n = glm::cross(b - a, c - a);
        const double len = glm::length(n);
        normals[m].push_back(len > 0.0 ? vec3(n / len) : vec3(0.0f));
      }
      const Material& material = scene.materials[mesh.material];
      if (material.emissive())
        emitters.addMesh(uint32_t(m), vertices, mesh.triangles, material.emission,
                         material.emissionTexture != shared::kNoTexture);
    }
    // Point clouds as discs, geometry ids after the meshes'.
    for (size_t c = 0; c < scene.pointClouds.size(); ++c) {
      const PointCloud& cloud = scene.pointClouds[c];
      std::vector<vec3> centres(cloud.size());
      for (size_t i = 0; i < cloud.size(); ++i) centres[i] = local(cloud.positions[i]);
      rays.addDiscs(unsigned(scene.meshes.size() + c), centres, cloud.normals, cloud.radii);
    }
    rays.commit();
  }
};

class Tracer {
 public:
  Tracer(const Scene& scene, const Setup& setup, int bounces, LightSampling lightSampling)
      : scene_(scene), s_(setup), bounces_(bounces), lightSampling_(lightSampling) {}

  uint64_t rays = 0;

  RayScene::Hit intersect(vec3 o, vec3 d) {
    ++rays;
    return s_.rays.intersect(o, d);
  }

  bool visible(vec3 o, vec3 d, float distance) {
    ++rays;
    return !s_.rays.occluded(o, d, distance);
  }

  // Radiance arriving at the camera along (o, d), and its terms. From the second vertex on, what
  // the path brings back reaches the camera through the first vertex's lobes; `lobeThroughput`
  // splits `throughput` by the lobe that the first vertex's BSDF value came from.
  template <class Sampler>
  PathSample radiance(vec3 o, vec3 d, Sampler& rng) {
    PathSample sample;
    vec3& result = sample.radiance;
    vec3 throughput(1.0f);
    Lobes lobeThroughput;
    // Adds `light` at a vertex after the first, times the path's throughput, to the radiance and
    // to the indirect terms through the first vertex's lobes. `weight` scales it after the
    // throughput, in the order that the radiance has always been computed in.
    const auto addIndirect = [&](vec3 light, float weight = 1.0f) {
      result += throughput * light * weight;
      sample.term(LightTerm::indirect_diffuse) += lobeThroughput.diffuse * light * weight;
      sample.term(LightTerm::indirect_specular) += lobeThroughput.specular * light * weight;
    };
    RayScene::Hit hit = intersect(o, d);
    if (!hit.found) {
      result = scene_.background;
      sample.term(LightTerm::emission) = scene_.background;
      return sample;
    }
    bool countEmission = true;  // the camera ray sees emitters directly
    float lastPdf = 0.0f;       // solid-angle pdf of the BSDF sample that found `hit`
    vec3 lastPoint = o;
    for (int depth = 0;; ++depth) {
      vec3 ng;
      const Shading m = shadingAt(hit, ng);
      const vec3 x = o + hit.t * d;
      if (m.emissive() && glm::dot(ng, -d) > 0.0f) {  // emitters are one-sided (front face)
        if (countEmission) {
          result += throughput * m.emission;
          sample.term(LightTerm::emission) += m.emission;
        } else {  // found by BSDF sampling: weigh against light sampling (power heuristic)
          const float d2 = glm::dot(x - lastPoint, x - lastPoint);
          // Emissive points are not light-sampled: BSDF sampling alone finds them.
          const float lightPdf = hit.geometry < scene_.meshes.size()
                                     ? s_.emitters.pdf(lastPoint, hit.geometry, hit.primitive, d2,
                                                       glm::dot(ng, -d), lightSampling_)
                                     : 0.0f;
          const float weight = powerWeight(lastPdf, lightPdf);
          if (depth == 1) {  // found from the first vertex: direct light
            result += throughput * m.emission * weight;
            sample.term(LightTerm::direct) += throughput * m.emission * weight;
          } else {
            addIndirect(m.emission, weight);
          }
        }
      }
      if (bounces_ >= 0 && depth > bounces_) break;  // only the emission of the last hit counted
      const vec3 n = glm::dot(ng, d) < 0.0f ? ng : -ng;  // two-sided reflection
      const vec3 wo = -d;
      const vec3 origin = x + epsilon(x) * n;
      const vec3 direct = directLight(origin, n, wo, m, rng);
      if (depth == 0) {
        result += throughput * direct;
        sample.term(LightTerm::direct) += direct;
      } else {
        addIndirect(direct);
      }

      // Continue by sampling the BSDF.
      vec3 wi;
      float pdf;
      const Lobes lobes = sampleBsdf(m, n, wo, rng, wi, pdf);
      const vec3 f = lobes.sum();
      if (pdf <= 0.0f || maxComponent(f) <= 0.0f) break;
      const vec3 factor = f * glm::dot(n, wi) / pdf;
      throughput *= factor;
      if (depth == 0) {
        lobeThroughput.diffuse = lobes.diffuse * glm::dot(n, wi) / pdf;
        lobeThroughput.specular = lobes.specular * glm::dot(n, wi) / pdf;
      } else {
        lobeThroughput.diffuse *= factor;
        lobeThroughput.specular *= factor;
      }
      if (bounces_ < 0 && depth >= 3) {  // Russian roulette for unlimited bounces
        const float q = std::min(0.95f, maxComponent(throughput));
        if (rng.get1D() >= q) break;
        throughput /= q;
        lobeThroughput.diffuse /= q;
        lobeThroughput.specular /= q;
      }
      const RayScene::Hit next = intersect(origin, wi);
      if (!next.found) {
        addIndirect(scene_.background);  // the background is not light-sampled
        break;
      }
      o = origin;
      d = wi;
      hit = next;
      countEmission = false;
      lastPdf = pdf;
      lastPoint = origin;
      // With a bounce limit, the emission found by the last allowed BSDF ray is still direct
      // light of the vertex before it; the loop head counts it and stops.
    }
    return sample;
  }

 private:
  static float powerWeight(float a, float b) { return a * a / (a * a + b * b); }

  // The shading of a hit and its unit normal: a triangle's right-hand normal, or a point's.
  Shading shadingAt(const RayScene::Hit& hit, vec3& normal) const {
    const size_t meshes = scene_.meshes.size();
    if (hit.geometry < meshes) {
      normal = s_.normals[hit.geometry][hit.primitive];
      const Mesh& mesh = scene_.meshes[hit.geometry];
      const Material& m = scene_.materials[mesh.material];
      if (!m.textured()) return shadingOf(m);
      return texturedShading(scene_, m, texcoordAt(mesh, hit.primitive, hit.barycentric));
    }
    const PointCloud& cloud = scene_.pointClouds[hit.geometry - meshes];
    normal = cloud.normals[hit.primitive];
    Shading s = shadingOf(scene_.materials[cloud.material]);
    if (!cloud.colors.empty()) s.albedo = cloud.colors[hit.primitive];
    return s;
  }

  // The emitted radiance at point q of an emitter: its constant, times its texture at q.
  vec3 emissionAt(const Emitter& e, vec3 q) const {
    const Mesh& mesh = scene_.meshes[e.mesh];
    const Material& m = scene_.materials[mesh.material];
    if (m.emissionTexture == shared::kNoTexture) return e.emission;
    const glm::vec2 b = glm::clamp(emitterBarycentric(e, q), 0.0f, 1.0f);
    return shared::texturedValue(TextureAccess{scene_.textures}, m.emission, m.emissionTexture,
                                 texcoordAt(mesh, e.triangle, b), 0.0f);
  }

  Lobes evalBsdf(const Shading& m, vec3 n, vec3 wo, vec3 wi) const {
    Lobes f;
    if (glm::dot(n, wi) <= 0.0f) return f;
    f.diffuse = m.albedo / std::numbers::pi_v<float>;
    if (m.shininess > 0.0f && maxComponent(m.specular) > 0.0f) {
      const vec3 r = 2.0f * glm::dot(n, wo) * n - wo;
      const float c = std::max(0.0f, glm::dot(r, wi));
      f.specular = m.specular * (m.shininess + 2.0f) /
                   (2.0f * std::numbers::pi_v<float>)*std::pow(c, m.shininess);
    }
    return f;
  }

  float bsdfPdf(const Shading& m, vec3 n, vec3 wo, vec3 wi) const {
    const float cosTheta = glm::dot(n, wi);
    if (cosTheta <= 0.0f) return 0.0f;
    const float ps = specularProbability(m);
    float pdf = (1.0f - ps) * cosTheta / std::numbers::pi_v<float>;
    if (ps > 0.0f) {
      const vec3 r = 2.0f * glm::dot(n, wo) * n - wo;
      const float c = std::max(0.0f, glm::dot(r, wi));
      pdf +=
          ps * (m.shininess + 1.0f) / (2.0f * std::numbers::pi_v<float>)*std::pow(c, m.shininess);
    }
    return pdf;
  }

  static float specularProbability(const Shading& m) {
    if (m.shininess <= 0.0f) return 0.0f;
    const float s = luminance(m.specular), d = luminance(m.albedo);
    return s + d > 0.0f ? s / (s + d) : 0.0f;
  }

  template <class Sampler>
  Lobes sampleBsdf(const Shading& m, vec3 n, vec3 wo, Sampler& rng, vec3& wi, float& pdf) const {
    // One 2D sample picks the lobe with its first coordinate, stretched back to [0, 1) within the
    // lobe's share, and the direction: the direction keeps the sample's stratification.
    const glm::vec2 u = rng.get2D();
    const float ps = specularProbability(m);
    const bool glossy = u.x < ps;
    const float u1 = glossy ? stretch(u.x, 0.0f, ps) : stretch(u.x, ps, 1.0f), u2 = u.y;
    if (glossy) {  // Phong lobe around the mirror direction
      const vec3 r = 2.0f * glm::dot(n, wo) * n - wo;
      wi = around(r, std::pow(u1, 1.0f / (m.shininess + 1.0f)),
                  2.0f * std::numbers::pi_v<float> * u2);
    } else {  // cosine-weighted hemisphere
      wi = around(n, std::sqrt(u1), 2.0f * std::numbers::pi_v<float> * u2);
    }
    pdf = bsdfPdf(m, n, wo, wi);
    return evalBsdf(m, n, wo, wi);
  }

  float falloff(const Light& l, float distance) const {
    if (l.falloff.kind == Falloff::Kind::inverse_square) return 1.0f / (distance * distance);
    return 1.0f / (l.falloff.constant + l.falloff.linear * distance +
                   l.falloff.quadratic * distance * distance);
  }

  // Next-event estimation: one sample of the emissive triangles (MIS-weighted) plus every
  // point, spot and directional light.
  template <class Sampler>
  vec3 directLight(vec3 x, vec3 n, vec3 wo, const Shading& m, Sampler& rng) {
    vec3 sum(0.0f);
    // One 2D sample picks the emitter and the point on it (validation/reference/emitters.h).
    const glm::vec2 u = rng.get2D();
    if (!s_.emitters.empty()) {
      const EmitterSample e = s_.emitters.sample(x, u, lightSampling_);
      if (e.pdf > 0.0f) {
        const vec3 f = evalBsdf(m, n, wo, e.direction).sum();
        if (maxComponent(f) > 0.0f && visible(x, e.direction, e.distance * (1.0f - 1e-4f))) {
          const float w = powerWeight(e.pdf, bsdfPdf(m, n, wo, e.direction));
          sum += f * emissionAt(*e.emitter, x + e.direction * e.distance) *
                 glm::dot(n, e.direction) * w / e.pdf;
        }
      }
    }
    for (size_t li = 0; li < scene_.lights.size(); ++li) {
      const Light& l = scene_.lights[li];
      vec3 wi;
      float dist = INFINITY;
      vec3 irradiance = l.intensity;
      if (l.type == Light::Type::directional) {
        wi = -vec3(l.direction);
      } else {
        wi = s_.lightPositions[li] - x;
        dist = glm::length(wi);
        wi /= dist;
        irradiance *= falloff(l, dist);
        if (l.type == Light::Type::spot &&
            glm::dot(-wi, vec3(l.direction)) < std::cos(glm::radians(0.5f * l.spotAngleDeg)))
          continue;
      }
      const vec3 f = evalBsdf(m, n, wo, wi).sum();
      if (maxComponent(f) <= 0.0f) continue;
      if (l.castsShadows && !visible(x, wi, dist)) continue;
      sum += f * irradiance * glm::dot(n, wi);
    }
    return sum;
  }

  const Scene& scene_;
  // Offset for rays leaving x: float rounding of x grows with |x|; the small scene-relative
  // term covers hits near the origin of a large scene.
  float epsilon(vec3 x) const {
    return 1e-5f * std::max({std::abs(x.x), std::abs(x.y), std::abs(x.z)}) + 1e-7f * s_.sceneScale;
  }

  const Setup& s_;
  int bounces_;
  LightSampling lightSampling_;
};

// The seed of replica r: replica 0 keeps the image's seed.
uint64_t replicaSeed(uint64_t seed, int replica) {
  return replica == 0 ? seed : mix64(seed ^ mix64(uint64_t(replica) * 0xd1b54a32d192ed03ull));
}

// The variance of the image's mean from the spread of its K replicas' means m_r, each an
// independent scrambled sequence [Owen 1997]: sum (m_r - mean)^2 / (K (K - 1)). Replica r holds
// the samples s with s % K = r, spp / K of them (the first spp % K one more: close enough to
// equal for the estimate).
glm::dvec3 replicaVariance(const std::array<glm::dvec3, kMaxReplicas>& sums, int k, int spp) {
  glm::dvec3 mean(0.0), square(0.0);
  for (int r = 0; r < k; ++r) {
    const int count = spp / k + (r < spp % k ? 1 : 0);
    const glm::dvec3 m = sums[size_t(r)] / double(count);
    mean += m;
    square += m * m;
  }
  mean /= double(k);
  return glm::max(square / double(k) - mean * mean, 0.0) * (double(k) / double(k - 1)) / double(k);
}

// Each pixel's mean over the (2 radius + 1)^2 pixels around it, clipped at the border. One
// pixel's estimate from few samples (or from two replicas) is itself noisy, and zero where every
// sample missed a rare contribution; the neighbours' share its variance closely enough that their
// mean predicts the error far better (docs/path-tracer.md, "Variance").
Image neighbourhoodMean(const Image& in, int radius) {
  Image out(in.width, in.height);
  parallelFor(0, in.height, [&](int y) {
    for (int x = 0; x < in.width; ++x) {
      glm::dvec3 sum(0.0);
      int count = 0;
      for (int qy = std::max(0, y - radius); qy <= std::min(in.height - 1, y + radius); ++qy)
        for (int qx = std::max(0, x - radius); qx <= std::min(in.width - 1, x + radius); ++qx) {
          sum += glm::dvec3(in.at(qx, qy));
          ++count;
        }
      out.at(x, y) = vec3(sum / double(count));
    }
  });
  return out;
}

}  // namespace

PathTraceResult pathTrace(const Scene& scene, const PathTraceOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const Setup setup(scene);
  const Camera& cam = scene.camera;
  const int w = cam.width, h = cam.height;
  // The image, its variance and terms, and the encoded file a writer builds from the image.
  requireMemory((3 + kLightTerms.size()) * uint64_t(w) * uint64_t(h) * sizeof(vec3),
                "the path-traced image at " + std::to_string(w) + "x" + std::to_string(h),
                scene.file, "camera.resolution");
  PathTraceResult result;
  result.image = Image(w, h);
  result.variance = Image(w, h);
  Image pixelVariance(w, h);  // each pixel's own estimate, before the neighbourhood average
  for (Image& term : result.terms) term = Image(w, h);
  const vec3 forward = glm::normalize(vec3(cam.lookAt - cam.position));
  const vec3 right = glm::normalize(glm::cross(forward, vec3(cam.up)));
  const vec3 up = glm::cross(right, forward);
  const float tanHalf = std::tan(glm::radians(float(cam.fovYDeg)) * 0.5f);
  const float aspect = float(w) / float(h);
  std::atomic<uint64_t> rays{0};
  std::atomic<int> rowsDone{0};
  // At most one replica per sample, and no more than the per-pixel sums hold.
  const int replicas = options.sampler == SamplerKind::sobol
                           ? std::clamp(std::min(options.replicas, options.spp), 1, kMaxReplicas)
                           : 1;
  parallelFor(0, h, [&](int y) {
    if (options.cancel && options.cancel->load()) return;
    Tracer tracer(scene, setup, options.bounces, options.lightSampling);
    for (int x = 0; x < w; ++x) {
      const uint64_t pixel = uint64_t(y) * uint64_t(w) + uint64_t(x);
      glm::dvec3 sum(0.0), sum2(0.0);
      std::array<glm::dvec3, kMaxReplicas> replicaSum{};
      std::array<glm::dvec3, kLightTerms.size()> terms{};
      for (int s = 0; s < options.spp; ++s) {
        const auto trace = [&](auto rng) {
          const glm::vec2 u = rng.get2D();
          const float px = (2.0f * (float(x) + u.x) / float(w) - 1.0f) * tanHalf * aspect;
          const float py = (1.0f - 2.0f * (float(y) + u.y) / float(h)) * tanHalf;
          const vec3 dir = glm::normalize(forward + px * right + py * up);
          return tracer.radiance(setup.local(cam.position), dir, rng);
        };
        // Sample s is sample s / K of replica s % K, each replica scrambled by a seed of its own.
        const int replica = s % replicas;
        const PathSample path = options.sampler == SamplerKind::sobol
                                    ? trace(SobolSampler(replicaSeed(options.seed, replica), pixel,
                                                         uint32_t(s / replicas)))
                                    : trace(IndependentSampler(options.seed, pixel, uint32_t(s)));
        const glm::dvec3 l(path.radiance);
        sum += l;
        sum2 += l * l;
        replicaSum[size_t(replica)] += l;
        for (size_t t = 0; t < terms.size(); ++t) terms[t] += glm::dvec3(path.terms[t]);
      }
      const double n = options.spp;
      result.image.at(x, y) = vec3(sum / n);
      for (size_t t = 0; t < terms.size(); ++t) result.terms[t].at(x, y) = vec3(terms[t] / n);
      pixelVariance.at(x, y) = replicas > 1
                                   ? vec3(replicaVariance(replicaSum, replicas, options.spp))
                               : n > 1 ? vec3(glm::max(sum2 - sum * sum / n, 0.0) / (n - 1.0) / n)
                                       : vec3(0.0f);
    }
    rays += tracer.rays;
    const int done = ++rowsDone;
    if (options.progress) options.progress(double(done) / h);
  });
  if (options.cancel && options.cancel->load()) throw Cancelled();
  result.variance = neighbourhoodMean(pixelVariance, kVarianceRadius);
  result.rays = rays;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

std::string variancePath(const std::string& image) {
  const std::filesystem::path p(image);
  return (p.parent_path() / (p.stem().string() + ".variance" + p.extension().string())).string();
}

}  // namespace voxgi::reference

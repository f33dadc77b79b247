#include "common/settings.h"

#include <charconv>
#include <cmath>
#include <functional>
#include <sstream>

#include "common/error.h"

namespace voxgi {
namespace {

// One --set key: how to read and write it on Settings, and how to describe it.
struct Param {
  std::string key;
  std::string range;  // "[lo, hi]" or "a|b|c"
  std::string meaning;
  std::function<std::string(const Settings&)> get;
  std::function<bool(Settings&, const std::string&)> set;  // false: value rejected
};

template <class T>
std::string formatNumber(T v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

// Built with a stream: GCC 12 warns falsely (-Wrestrict) on chained std::string operator+.
template <class T>
std::string interval(T lo, T hi) {
  std::ostringstream s;
  s << '[' << lo << ", " << hi << ']';
  return s.str();
}

// A float or int key; the whole text must parse (std::from_chars) to a finite value in range.
template <class T>
Param number(std::string key, T Settings::*field, T lo, T hi, std::string meaning) {
  return {key, interval(lo, hi), std::move(meaning),
          [field](const Settings& s) { return formatNumber(s.*field); },
          [field, lo, hi](Settings& s, const std::string& text) {
            T v{};
            const char* end = text.data() + text.size();
            const auto [ptr, ec] = std::from_chars(text.data(), end, v);
            if (ec != std::errc() || ptr != end || !std::isfinite(double(v)) || v < lo || v > hi)
              return false;
            s.*field = v;
            return true;
          }};
}

template <class E>
Param choice(std::string key, E Settings::*field, std::vector<std::string> names,
             std::string meaning) {
  std::string range;
  for (const auto& n : names) {
    if (!range.empty()) range += '|';
    range += n;
  }
  return {key, range, std::move(meaning),
          [field, names](const Settings& s) { return names[static_cast<size_t>(s.*field)]; },
          [field, names](Settings& s, const std::string& text) {
            for (size_t i = 0; i < names.size(); ++i)
              if (names[i] == text) {
                s.*field = static_cast<E>(i);
                return true;
              }
            return false;
          }};
}

const std::vector<Param>& params() {
  static const std::vector<Param> table{
      choice("voxelize.mode", &Settings::voxelizeMode, {"conservative", "antialiased"},
             "closed triangle/voxel overlap, or trilinear splats continuous under motion"),
      choice("light.attenuation", &Settings::attenuation, {"cosine", "normal_weighted"},
             "per-voxel direct light: max(n.l, 0), or Villegas' per-face weighting"),
      choice("voxel_shadow.mode", &Settings::voxelShadow, {"none", "hard", "soft"},
             "voxel visibility toward each light by marching the opacity volume"),
      number("voxel_shadow.kappa", &Settings::voxelShadowKappa, 0.0f, 64.0f,
             "soft voxel shadows: occlusion added per opaque voxel, divided by the distance"),
      number("voxel_shadow.offset", &Settings::voxelShadowOffset, 0.5f, 8.0f,
             "voxels the shadow ray skips before testing opacity (self-shadowing)"),
      choice("mip.mode", &Settings::mip, {"isotropic", "anisotropic"},
             "one averaged pyramid, or six directional pyramids"),
      choice("cones.set", &Settings::cones, {"equal7", "villegas6", "kahl5", "kahl9"},
             "diffuse cone set (docs/stages/trace_cones.md)"),
      choice("cones.diffuse", &Settings::diffuseCones, {"weighted", "first_hit"},
             "composite each diffuse cone, or take the first surface it hits (Kahl)"),
      number("cones.step", &Settings::coneStep, 0.05f, 4.0f,
             "step along a cone as a fraction of its diameter (beta)"),
      number("cones.offset", &Settings::coneOffset, 0.0f, 8.0f,
             "voxels along the normal before a cone starts (self-intersection)"),
      number("shadow.aperture", &Settings::shadowAperture, 0.1f, 120.0f,
             "aperture of the shadow cone toward each light, degrees"),
      choice("shadow.falloff", &Settings::shadowFalloff, {"plain", "kahl2019"},
             "shadow cone occlusion as sampled, or faded by smoothstep of sqrt(distance)"),
      number("shadow.strength", &Settings::shadowStrength, 0.01f, 1000.0f,
             "kahl2019 shadow falloff: sqrt(distance) multiplier"),
      choice("specular.brdf", &Settings::specularBrdf, {"phong", "light_angle"},
             "indirect specular as traced, or weighted by the angle to each light (Kahl)"),
      number("specular.falloff", &Settings::specularFalloff, 0.0f, 64.0f,
             "light_angle specular: exponent q"),
      choice("ao.mode", &Settings::ambientOcclusion, {"off", "on"},
             "ambient occlusion from the diffuse cones, multiplied into indirect diffuse"),
      number("ao.lambda", &Settings::ambientLambda, 0.0f, 100.0f,
             "ambient occlusion falloff 1 / (1 + lambda r), r the cone radius in voxels"),
      number("bounce.count", &Settings::bounceCount, 0, 8,
             "extra diffuse bounces, each cone-traced from every voxel (docs/stages/bounce.md)"),
      choice("plan.mode", &Settings::planMode, {"planned", "full"},
             "skip effects the scene does not use, or compute all (docs/effect-plan.md)"),
  };
  return table;
}

const std::vector<std::pair<std::string, std::vector<std::string>>>& presets() {
  static const std::vector<std::pair<std::string, std::vector<std::string>>> table{
      {"default", {}},
      // Seed 000: direct light computed while voxelizing (no voxel shadows), glGenerateMipmap, and
      // §5.4.4's cone variants: 5 cones, first hit, smoothstep/sqrt shadows, light-angle specular.
      {"kahl2019",
       {"mip.mode=isotropic", "voxel_shadow.mode=none", "cones.set=kahl5",
        "cones.diffuse=first_hit", "shadow.falloff=kahl2019", "shadow.aperture=30",
        "specular.brdf=light_angle"}},
      // Seed 001: normal-weighted attenuation, soft voxel shadows, directional volumes, 6 cones,
      // AO.
      {"villegas2017",
       {"light.attenuation=normal_weighted", "voxel_shadow.mode=soft", "mip.mode=anisotropic",
        "cones.set=villegas6", "ao.mode=on"}},
  };
  return table;
}

}  // namespace

const char* voxelizeModeName(VoxelizeMode mode) {
  return mode == VoxelizeMode::conservative ? "conservative" : "antialiased";
}

void applySetting(Settings& settings, const std::string& assignment, const std::string& source,
                  const std::string& fieldPrefix) {
  const size_t eq = assignment.find('=');
  if (eq == std::string::npos)
    throw InputError(source, "", "expected key=value, got '" + assignment + "'");
  const std::string key = assignment.substr(0, eq), value = assignment.substr(eq + 1);
  for (const Param& p : params())
    if (p.key == key) {
      if (!p.set(settings, value))
        throw InputError(source, fieldPrefix + key,
                         "must be in " + p.range + ", got '" + value + "'");
      return;
    }
  throw InputError(source, fieldPrefix + key, "unknown parameter (voxgi render --help lists them)");
}

void applyPreset(Settings& settings, const std::string& preset) {
  for (const auto& [name, assignments] : presets())
    if (name == preset) {
      for (const std::string& a : assignments) applySetting(settings, a, "preset " + name);
      return;
    }
  throw InputError("--preset", "",
                   "must be default, kahl2019 or villegas2017, got '" + preset + "'");
}

Settings resolveSettings(const std::vector<std::string>& fileSettings, const std::string& file,
                         const std::string& preset, const std::vector<std::string>& sets) {
  Settings settings;
  for (const std::string& a : fileSettings) applySetting(settings, a, file, "settings.");
  applyPreset(settings, preset);
  for (const std::string& a : sets) applySetting(settings, a, "--set");
  return settings;
}

std::vector<std::string> settingValues(const Settings& settings) {
  std::vector<std::string> out;
  for (const Param& p : params()) out.push_back(p.key + "=" + p.get(settings));
  return out;
}

std::string describeSettings() {
  const Settings defaults;
  std::ostringstream s;
  s << "Parameters (--set key=value):\n";
  for (const Param& p : params())
    s << "  " << p.key << " = " << p.get(defaults) << "  " << p.range << "\n      " << p.meaning
      << "\n";
  s << "Presets (--preset NAME, applied before --set):\n";
  for (const auto& [name, assignments] : presets()) {
    s << "  " << name << ":";
    for (const std::string& a : assignments) s << " " << a;
    s << (assignments.empty() ? " the defaults above\n" : "\n");
  }
  return s.str();
}

}  // namespace voxgi

#include "common/settings.h"

#include <algorithm>
#include <sstream>

#include "common/error.h"
#include "common/technique.h"

namespace voxgi {
namespace {

// The table that holds `key`, and its technique (nullptr for the shared table).
struct Found {
  const Param* param = nullptr;
  const Technique* technique = nullptr;
};
Found findParam(const std::string& key) {
  for (const Param& p : sharedParams())
    if (p.key == key) return {&p, nullptr};
  for (const Technique& t : techniques())
    for (const Param& p : t.params())
      if (p.key == key) return {&p, &t};
  return {};
}

void apply(const Param& p, Settings& settings, const std::string& value, const std::string& source,
           const std::string& field) {
  if (!p.set(settings, value))
    throw InputError(source, field, "must be in " + p.range + ", got '" + value + "'");
}

// key and value of "key=value"
std::pair<std::string, std::string> split(const std::string& assignment,
                                          const std::string& source) {
  const size_t eq = assignment.find('=');
  if (eq == std::string::npos)
    throw InputError(source, "", "expected key=value, got '" + assignment + "'");
  return {assignment.substr(0, eq), assignment.substr(eq + 1)};
}

// Whether the technique reads a shared key: plan.mode and update.interval always, a shared stage's
// keys when it runs the stage (the octree does not voxelize).
bool readsSharedKey(const Technique& technique, const Param& p) {
  const std::string_view prefix = std::string_view(p.key).substr(0, p.key.find('.'));
  if (prefix == "plan" || prefix == "update") return true;
  const auto& steps = technique.steps();
  return std::any_of(steps.begin(), steps.end(), [&](const StageSpec* s) {
    return s->owner == std::string_view("common") && s->name == prefix;
  });
}

}  // namespace

std::vector<const Param*> techniqueParams(const Technique& technique) {
  std::vector<const Param*> out;
  for (const Param& p : sharedParams())
    if (readsSharedKey(technique, p)) out.push_back(&p);
  for (const Param& p : technique.params()) out.push_back(&p);
  return out;
}

const std::vector<Param>& sharedParams() {
  static const std::vector<Param> table{
      choice("voxelize.mode", &Settings::voxelizeMode, {"conservative", "antialiased"},
             "closed triangle/voxel overlap, or trilinear splats continuous under motion"),
      choice("voxelize.emission", &Settings::voxelizeEmission, {"surfaces", "emitters"},
             "a voxel's emission: the mean over all its surfaces (a coplanar wall dilutes a "
             "light), or over its emitting surfaces alone"),
      choice("plan.mode", &Settings::planMode, {"planned", "full"},
             "skip effects the scene does not use, or compute all (docs/effect-plan.md)"),
      number("update.interval", &Settings::updateInterval, 1, 1000,
             "in a sequence, bring the volume stages up to date every N frames rendered; between, "
             "they keep their buffers while the image stages follow the scene (docs/motion.md)"),
  };
  return table;
}

const char* voxelizeModeName(VoxelizeMode mode) {
  return mode == VoxelizeMode::conservative ? "conservative" : "antialiased";
}

void applySetting(Settings& settings, const std::string& assignment, const std::string& source,
                  const std::string& fieldPrefix) {
  const auto [key, value] = split(assignment, source);
  const Found found = findParam(key);
  if (found.param == nullptr)
    throw InputError(source, fieldPrefix + key,
                     "unknown parameter (voxgi render --help lists them)");
  apply(*found.param, settings, value, source, fieldPrefix + key);
}

Settings techniqueDefaults(const Technique& technique) {
  Settings settings;
  if (technique.defaults != nullptr)
    for (const std::string& a : *technique.defaults)
      applySetting(settings, a, "technique " + std::string(technique.name));
  return settings;
}

void applyPreset(Settings& settings, const Technique& technique, const std::string& preset) {
  std::string names;
  for (const Preset& p : technique.presets()) {
    if (p.name == preset) {
      for (const std::string& a : p.assignments)
        applySetting(settings, a, "preset " + std::string(technique.name) + "/" + p.name);
      return;
    }
    names.append(names.empty() ? "" : "|").append(p.name);
  }
  throw InputError("--preset", "",
                   "must be one of " + std::string(technique.name) + "'s presets " + names +
                       ", got '" + preset + "'");
}

Settings resolveSettings(const Technique& technique, const std::vector<std::string>& fileSettings,
                         const std::string& file, const std::string& preset,
                         const std::vector<std::string>& sets) {
  Settings settings = techniqueDefaults(technique);
  for (const std::string& a : fileSettings) applySetting(settings, a, file, "settings.");
  applyPreset(settings, technique, preset);
  for (const std::string& a : sets) {
    const std::string key = split(a, "--set").first;
    // A key is the technique's own when its table lists it (svo lists vct's cone keys, the
    // same fields), else another technique's is refused by name.
    const std::vector<Param>& own = technique.params();
    const bool listed =
        std::any_of(own.begin(), own.end(), [&](const Param& p) { return p.key == key; });
    const Found found = findParam(key);
    if (!listed && found.param != nullptr && found.technique != nullptr)
      throw InputError("--set", key,
                       "is a parameter of " + std::string(found.technique->name) + ", not of " +
                           std::string(technique.name));
    if (found.param != nullptr && found.technique == nullptr &&
        !readsSharedKey(technique, *found.param))
      throw InputError("--set", key,
                       "is a parameter of a stage " + std::string(technique.name) +
                           " does not run (voxgi plan lists its stages)");
    applySetting(settings, a, "--set");
  }
  return settings;
}

std::vector<std::string> settingValues(const Settings& settings, const Technique& technique) {
  std::vector<std::string> out;
  for (const Param* p : techniqueParams(technique)) out.push_back(p->key + "=" + p->get(settings));
  return out;
}

std::string settingValue(const Settings& settings, const std::string& key) {
  const Found found = findParam(key);
  return found.param == nullptr ? std::string() : found.param->get(settings);
}

std::string describeSettings(const Technique& technique) {
  const Settings defaults = techniqueDefaults(technique);
  std::ostringstream s;
  s << "Parameters of " << technique.name << " (--set key=value):\n";
  for (const Param* p : techniqueParams(technique))
    s << "  " << p->key << " = " << p->get(defaults) << "  " << p->range << "\n      " << p->meaning
      << "\n";
  s << "Presets of " << technique.name << " (--preset NAME, applied before --set):\n";
  for (const Preset& p : technique.presets()) {
    s << "  " << p.name << ":";
    for (const std::string& a : p.assignments) s << " " << a;
    s << (p.assignments.empty() ? " the defaults above\n" : "\n");
  }
  return s.str();
}

}  // namespace voxgi

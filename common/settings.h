// Every technique parameter a stage reads, with its default: the shared stages' here, each
// technique's in its own section (Settings::vct: common/vct/settings.h), one per technique of
// common/stages.inc. Keys, ranges and
// meanings are tables (common/settings_table.h): the shared one in common/settings.cpp, each
// technique's next to its settings; presets belong to a technique.
#pragma once

#include <string>
#include <vector>

// Generated (cmake/VoxgiStages.cmake): each technique's common/<technique>/settings.h and
// VOXGI_TECHNIQUE_SETTINGS.
#include "common/technique_settings.h"

namespace voxgi {

struct Param;
struct Technique;

enum class VoxelizeMode { conservative, antialiased };
// A voxel's emission: the mean over all its surfaces, or over its emitting surfaces alone
// (docs/stages/voxelize.md).
enum class VoxelizeEmission { surfaces, emitters };
enum class PlanMode { planned, full };  // common/effect_plan.h

struct Settings {
  VoxelizeMode voxelizeMode = VoxelizeMode::conservative;
  VoxelizeEmission voxelizeEmission = VoxelizeEmission::surfaces;
  // full: every optional effect is computed even where the plan shows it contributes nothing
  PlanMode planMode = PlanMode::planned;
  // In a sequence the volume stages (those before the first that reads the camera) are brought up
  // to date every `updateInterval` frames rendered and keep their buffers between
  // (docs/motion.md, [Villegas 2017, §1.2]).
  int updateInterval = 1;
  // Not a key: voxgi diff and dump set it, and planners then keep intermediate volumes a render
  // drops (lpv: every propagation step).
  bool inspect = false;
  // Not a key: FrameRunner sets it for the frames of a sequence it does not run from scratch, and
  // planners then keep what the next frame's update in part starts from (voxelize's sums).
  bool sequence = false;
  // One section per technique of common/stages.inc, Settings::<technique>, of the type its
  // common/<technique>/settings.h declares (Settings::vct: VctSettings).
#define VOXGI_SECTION(technique, type) type technique;
  VOXGI_TECHNIQUE_SETTINGS(VOXGI_SECTION)
#undef VOXGI_SECTION
};

const char* voxelizeModeName(VoxelizeMode mode);

// Applies "key=value" for a key of any technique (a scene file may hold several techniques'
// settings); throws InputError naming `source` and the key after `fieldPrefix` for an unknown
// key, a malformed value or one outside the key's range.
void applySetting(Settings& settings, const std::string& assignment, const std::string& source,
                  const std::string& fieldPrefix = "");
// The defaults of every key, with a variant's own (holpv: 3 bands, 26 directions) applied.
Settings techniqueDefaults(const Technique& technique);
// Applies one of the technique's presets ("default" for every technique).
void applyPreset(Settings& settings, const Technique& technique, const std::string& preset);
// Defaults, then a scene file's "settings" (`file` names it in errors), the preset and the --set
// assignments: the later choice wins. A --set key must be a shared one or the technique's.
Settings resolveSettings(const Technique& technique, const std::vector<std::string>& fileSettings,
                         const std::string& file, const std::string& preset,
                         const std::vector<std::string>& sets);
// The keys the technique reads: the shared ones of the stages it runs, then its own.
std::vector<const Param*> techniqueParams(const Technique& technique);
// The current value of every key the technique reads, "key=value".
std::vector<std::string> settingValues(const Settings& settings, const Technique& technique);
// The value of one key as settingValues prints it ("cones.set" -> "equal7").
std::string settingValue(const Settings& settings, const std::string& key);
// One line per shared and technique key (key, default, range and meaning), and the presets.
std::string describeSettings(const Technique& technique);

}  // namespace voxgi

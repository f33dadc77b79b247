// `voxgi study --shard I/N` and `--merge N`: a study as the N tasks of a batch scheduler's job
// array (Slurm's --array, a Kubernetes indexed Job) and one task after them. Each shard runs every
// job k with k % N == I (round robin, so that each shard gets a share of every technique and
// resolution) and writes their records; the merge checks that the shards come from this study's
// command line and hold every job exactly once, then writes what one run writes.
#include <iostream>

#include "common/error.h"
#include "common/io/input_file.h"
#include "common/io/output_file.h"
#include "tools/frames.h"
#include "tools/study.h"

namespace voxgi::tools {
namespace {

std::string shardPath(const std::string& csv, size_t index, size_t count) {
  return csv + ".shard-" + std::to_string(index) + "-of-" + std::to_string(count) + ".json";
}

// What makes two study command lines the same study: everything but where the outputs go.
nlohmann::json studyFingerprint(const StudyOptions& o) {
  return {{"scene", o.scene},
          {"techniques", o.techniques},
          {"sweeps", o.sweeps},
          {"preset", o.preset},
          {"sets", o.sets},
          {"reference", o.reference},
          {"mask", o.mask},
          {"image", o.image},
          {"resolution", o.resolution},
          {"repeats", o.repeats},
          {"terms", o.terms},
          {"skip_emitters", o.skipEmitters},
          {"units", int(o.units)},
          {"gl", o.gl}};
}

}  // namespace

int runStudyShard(const StudyOptions& o) {
  if (o.merge > 0) throw InputError("--shard", "", "give either --shard or --merge");
  const Shard shard = parseShard(o.shard, "--shard");
  const std::string path = shardPath(o.csv, shard.index, shard.count);
  checkOutputPath(path);
  const std::vector<nlohmann::json> records = runStudyJobs(o, shard);
  const nlohmann::json out{{"study", studyFingerprint(o)},
                           {"shard", shard.index},
                           {"shards", shard.count},
                           {"records", records}};
  writeFileAtomically(path, out.dump(1) + "\n");
  std::cout << "wrote " << path << " (" << records.size() << " jobs)\n";
  return kExitOk;
}

int runStudyMerge(const StudyOptions& o) {
  const nlohmann::json study = studyFingerprint(o);
  std::vector<nlohmann::json> records;
  const auto count = static_cast<size_t>(o.merge);
  for (size_t i = 0; i < count; ++i) {
    const std::string path = shardPath(o.csv, i, count);
    nlohmann::json shard;
    try {
      shard = nlohmann::json::parse(readInputFile(path, "", "shard"));
    } catch (const nlohmann::json::exception& e) {
      throw InputError(path, "", std::string("malformed shard: ") + e.what());
    }
    if (!shard.is_object() || shard.value("study", nlohmann::json()) != study)
      throw InputError(path, "study",
                       "written by a study with other options: merge with the shards' own "
                       "command line");
    if (shard.value("shards", size_t(0)) != count || shard.value("shard", count) != i)
      throw InputError(path, "shards",
                       "not shard " + std::to_string(i) + " of " + std::to_string(count));
    for (const nlohmann::json& r : shard.at("records")) records.push_back(r);
  }
  return writeStudy(o, records);
}

}  // namespace voxgi::tools

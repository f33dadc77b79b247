// `voxgi study`: every combination of the swept parameters, rendered and timed (median of
// repeats, per stage), measured against a reference image beside what trivial answers score on
// it, written as CSV with the Pareto front of error against time, and plotted by
// tools/plot_study.py (docs/accuracy.md).
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "common/scene.h"
#include "tools/frames.h"
#include "validation/reference/image_metrics.h"

namespace voxgi::tools {

struct StudyOptions {
  std::string scene;
  std::vector<std::string> techniques{"vct"};  // vct and/or path
  std::vector<std::string> sweeps;             // "key=v1,v2,..."
  std::string preset = "default";
  std::vector<std::string> sets;  // fixed vct parameters, applied before the swept ones
  std::string reference, mask, csv, plot;
  std::string metric = "rel_mse";  // the error the Pareto front and the plot use
  std::string gl = "egl";          // for backend=gpu
  int image = 0;                   // image width (height keeps the camera's aspect); 0: the scene's
  int resolution = 0;              // grid resolution before the sweeps; 0: the scene's
  int repeats = 3;
  bool terms = false;  // also each light term against REFERENCE.<term>.exr (common/light_terms.h)
  bool skipEmitters = false;  // leave out the pixels where the reference sees emission
  reference::MetricUnits units = reference::MetricUnits::reference_mean;
  // --frames A:B[:STEP]: a study in time of an animated scene, --reference a pattern with a frame
  // field (tools/study_frames.cpp).
  std::string frames;
  double fps = 24.0;
  // A study spread over batch jobs (tools/study_shards.cpp): --shard I/N runs every job k with
  // k % N == I and writes their records beside --csv; --merge N writes the CSV and plot from the
  // N shards' records.
  std::string shard;
  int merge = 0;
};

void addStudyOptions(CLI::App& cmd, StudyOptions& options);
int runStudy(const StudyOptions& options);
int runStudyFrames(const StudyOptions& options);

// A study in pieces, on other processes or machines (docs/accuracy.md, "Studies on a cluster"):
// its jobs are every combination in the serial order; each runs alone, deterministic but for its
// times, and gives a record (JSON, its doubles exact); the records of all jobs give the CSV and
// plot runStudy writes.
size_t studyJobCount(const StudyOptions& options);
std::vector<nlohmann::json> runStudyJobs(const StudyOptions& options,
                                         const std::vector<size_t>& jobs);
std::vector<nlohmann::json> runStudyJobs(const StudyOptions& options, const Shard& shard);
int writeStudy(const StudyOptions& options, const std::vector<nlohmann::json>& records);
// --shard and --merge (tools/study_shards.cpp).
int runStudyShard(const StudyOptions& options);
int runStudyMerge(const StudyOptions& options);

// The scene file with --image and --resolution applied.
Scene loadStudyScene(const StudyOptions& options);

// The error --metric names (rmse, rel_mse, mare or ssim_loss) of `m`, and its axis label.
double metricError(const reference::ImageMetrics& m, const std::string& metric);
std::string metricLabel(const std::string& metric);

}  // namespace voxgi::tools

// voxgi.study: `voxgi study` from Python, in one piece or as jobs a Dask cluster runs (each job's
// record comes back to the caller, which writes the CSV as one run writes it).
#include <pybind11/stl.h>

#include "common/error.h"
#include "common/io/image_io.h"
#include "common/scene_io/scene_load.h"
#include "common/scene_motion.h"
#include "common/technique.h"
#include "tools/frames.h"
#include "tools/python/bindings.h"
#include "tools/study.h"
#include "validation/reference/path_trace.h"

namespace voxgi::python {
namespace {

// The options of `voxgi study` from the JSON voxgi.study builds (its keyword arguments).
tools::StudyOptions studyOptions(const std::string& text) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    throw InputError("study", "", std::string("malformed options: ") + e.what());
  }
  tools::StudyOptions o;
  try {
    o.scene = j.at("scene").get<std::string>();
    o.techniques = j.at("techniques").get<std::vector<std::string>>();
    o.sweeps = j.at("sweeps").get<std::vector<std::string>>();
    o.preset = j.at("preset").get<std::string>();
    o.sets = j.at("settings").get<std::vector<std::string>>();
    o.reference = j.at("reference").get<std::string>();
    o.mask = j.at("mask").get<std::string>();
    o.csv = j.at("csv").get<std::string>();
    o.plot = j.at("plot").get<std::string>();
    o.metric = j.at("metric").get<std::string>();
    o.gl = j.at("gl").get<std::string>();
    o.image = j.at("image").get<int>();
    o.resolution = j.at("resolution").get<int>();
    o.repeats = j.at("repeats").get<int>();
    o.terms = j.at("terms").get<bool>();
    o.skipEmitters = j.at("skip_emitters").get<bool>();
    const std::string units = j.at("units").get<std::string>();
    bool known = false;
    for (const auto& [name, value] : reference::kMetricUnitsNames)
      if (units == name) o.units = value, known = true;
    if (!known) throw InputError("units", "", "must be mean or absolute, got \"" + units + "\"");
  } catch (const nlohmann::json::exception& e) {
    throw InputError("study", "", std::string("malformed options: ") + e.what());
  }
  for (const std::string& t : o.techniques)
    if (t != "path") findTechnique(t, "techniques");
  if (o.repeats < 1 || o.repeats > 100)
    throw InputError("repeats", "", "must be in [1, 100], got " + std::to_string(o.repeats));
  return o;
}

int study(const std::string& options) {
  const tools::StudyOptions o = studyOptions(options);
  py::gil_scoped_release release;
  return tools::runStudy(o);
}

size_t jobCount(const std::string& options) {
  const tools::StudyOptions o = studyOptions(options);
  py::gil_scoped_release release;
  return tools::studyJobCount(o);
}

std::vector<std::string> runJobs(const std::string& options, const std::vector<size_t>& jobs) {
  const tools::StudyOptions o = studyOptions(options);
  std::vector<std::string> out;
  py::gil_scoped_release release;
  for (const nlohmann::json& r : tools::runStudyJobs(o, jobs)) out.push_back(r.dump());
  return out;
}

int merge(const std::string& options, const std::vector<std::string>& texts) {
  const tools::StudyOptions o = studyOptions(options);
  py::gil_scoped_release release;
  std::vector<nlohmann::json> records;
  for (const std::string& t : texts) {
    try {
      records.push_back(nlohmann::json::parse(t));
    } catch (const nlohmann::json::exception& e) {
      throw InputError("study", "job record", std::string("malformed: ") + e.what());
    }
  }
  return tools::writeStudy(o, records);
}

// One frame of a reference sequence, as `voxgi render --technique path --frames F:F` writes it:
// the image at `pattern` with its frame field filled in, its variance beside it.
std::string pathTraceFrame(const std::string& scenePath, const std::string& camera, int image,
                           double fps, const std::string& pattern, int spp, uint64_t seed,
                           int bounces, int replicas, const std::string& sampler, int frame) {
  if (frame < 0) throw InputError("frames", "", "a frame is >= 0, got " + std::to_string(frame));
  if (!(fps > 0.0)) throw InputError("fps", "", "must be > 0");
  const reference::PathTraceOptions o = pathOptions(spp, seed, bounces, replicas, sampler);
  const std::string out = tools::framePath(pattern, frame, "out");
  py::gil_scoped_release release;
  Scene scene = loadScene(scenePath, {.camera = camera});
  if (image != 0) setImageWidth(scene, image, "image");
  const Scene at = scene.motion.empty() ? scene : sceneAt(scene, frameSeconds(frame, fps));
  const reference::PathTraceResult r = reference::pathTrace(at, o);
  writeExr(out, r.image);
  writeExr(reference::variancePath(out), r.variance);
  return out;
}

}  // namespace

void bindStudies(py::module_& m) {
  m.def("path_trace_frame", &pathTraceFrame, py::arg("scene"), py::arg("camera"), py::arg("image"),
        py::arg("fps"), py::arg("out"), py::arg("spp"), py::arg("seed"), py::arg("bounces"),
        py::arg("replicas"), py::arg("sampler"), py::arg("frame"));
  m.def("study", &study, py::arg("options"));
  m.def("study_job_count", &jobCount, py::arg("options"));
  m.def("study_jobs", &runJobs, py::arg("options"), py::arg("jobs"));
  m.def("study_merge", &merge, py::arg("options"), py::arg("records"));
}

}  // namespace voxgi::python

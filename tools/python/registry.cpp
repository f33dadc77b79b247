// What voxgi declares (common/stages.inc, the settings tables) as plain Python values.
#include <pybind11/stl.h>

#include "common/settings.h"
#include "common/technique.h"
#include "tools/python/arrays.h"
#include "tools/python/bindings.h"

namespace voxgi::python {
namespace {

py::dict bufferDict(const BufferSpec& b) {
  py::dict d;
  d["name"] = b.qualifiedName();
  d["stage"] = b.stageSpec().qualifiedName();
  d["dtype"] = arrayDtype(b.type);
  d["components"] = b.components;
  d["shape"] = bufferShapeName(b.shape);
  d["needs"] = std::string(effectSpec(b.need).name);
  d["meaning"] = std::string(b.meaning);
  return d;
}

py::list techniqueList() {
  py::list out;
  for (const Technique& t : techniques()) {
    py::dict d;
    d["name"] = std::string(t.name);
    d["summary"] = std::string(t.summary);
    d["stages"] = [&] {
      py::list stages;
      for (const StageSpec* s : t.steps()) stages.append(s->qualifiedName());
      return stages;
    }();
    d["image"] = bufferSpec(t.image).qualifiedName();
    d["runs_stages_of"] = std::string(t.stages);
    out.append(d);
  }
  return out;
}

py::list bufferList(const std::string& technique) {
  py::list out;
  if (technique.empty()) {
    for (const BufferSpec& b : bufferSpecs()) out.append(bufferDict(b));
    return out;
  }
  for (const StageSpec* s : findTechnique(technique, "technique").steps())
    for (const BufferSpec* b : stageBuffers(*s)) out.append(bufferDict(*b));
  return out;
}

py::list settingList(const std::string& technique) {
  const Technique& t = findTechnique(technique, "technique");
  const Settings defaults = techniqueDefaults(t);
  py::list out;
  for (const Param* p : techniqueParams(t)) {
    py::dict d;
    d["key"] = p->key;
    d["default"] = p->get(defaults);
    d["range"] = p->range;
    d["meaning"] = p->meaning;
    out.append(d);
  }
  return out;
}

py::dict presetDict(const std::string& technique) {
  py::dict out;
  for (const Preset& p : findTechnique(technique, "technique").presets())
    out[py::str(p.name)] = p.assignments;
  return out;
}

}  // namespace

void bindRegistry(py::module_& m) {
  m.def("techniques", &techniqueList);
  m.def("buffers", &bufferList, py::arg("technique") = "");
  m.def("settings", &settingList, py::arg("technique"));
  m.def("presets", &presetDict, py::arg("technique"));
}

}  // namespace voxgi::python

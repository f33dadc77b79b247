// A value of a JSON scene file with its path ("lights[2].intensity"), read with the checks every
// field of the format gets: types, finite numbers, ranges, unknown keys refused, each error one
// InputError naming the file and the field (common/scene_io/scene_load.cpp, motion_load.cpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <string>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "common/error.h"
#include "common/scene_io/scene_load.h"

namespace voxgi {

// A JSON value together with its path ("lights[2].intensity"), for error messages.
struct Field {
  const std::string& file;
  const nlohmann::json& value;
  std::string path;

  [[noreturn]] void fail(const std::string& reason) const { throw InputError(file, path, reason); }

  // The member `key`; a missing one is an error naming it (required fields are read with at()).
  Field at(const std::string& key) const {
    const std::string child = path.empty() ? key : path + "." + key;
    if (!value.is_object()) fail("must be an object");
    const auto it = value.find(key);
    if (it == value.end()) throw InputError(file, child, "missing (this field is required)");
    return {file, *it, child};
  }
  Field at(size_t i) const { return {file, value.at(i), path + "[" + std::to_string(i) + "]"}; }
  bool has(const std::string& key) const { return value.contains(key); }

  void allowKeys(std::initializer_list<const char*> keys) const {
    if (!value.is_object()) fail("must be an object");
    std::set<std::string> allowed(keys.begin(), keys.end());
    for (const auto& [key, v] : value.items())
      if (!allowed.count(key)) fail("unknown field '" + key + "'");
  }
  double number() const {
    if (!value.is_number()) fail("must be a number");
    const double d = value.get<double>();
    if (!std::isfinite(d)) fail("must be finite");
    return d;
  }
  double number(double lo, double hi) const {
    const double d = number();
    if (d < lo || d > hi) fail("must be in [" + fmt(lo) + ", " + fmt(hi) + "], got " + fmt(d));
    return d;
  }
  int integer(int lo, int hi) const {
    if (!value.is_number_integer()) fail("must be an integer");
    const auto i = value.get<int64_t>();
    if (i < lo || i > hi)
      fail("must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " +
           std::to_string(i));
    return static_cast<int>(i);
  }
  bool boolean() const {
    if (!value.is_boolean()) fail("must be true or false");
    return value.get<bool>();
  }
  std::string string() const {
    if (!value.is_string()) fail("must be a string");
    return value.get<std::string>();
  }
  glm::dvec3 vec3() const {
    if (!value.is_array() || value.size() != 3) fail("must be an array of 3 numbers");
    return {at(0).number(), at(1).number(), at(2).number()};
  }
  // A position: rendering subtracts positions and squares distances in float, so each coordinate
  // must stay well inside float's range (the grid is at most 1e15 from the origin as well).
  glm::dvec3 position() const {
    const glm::dvec3 p = vec3();
    for (int c = 0; c < 3; ++c)
      if (std::abs(p[c]) > kMaxCoordinate)
        fail("must lie within " + fmt(kMaxCoordinate) + " of the origin, got " + fmt(p[c]));
    return p;
  }
  // A direction, normalised in double whatever its length (1e-160 or 1e308): the components are
  // scaled by the largest first, so the length neither underflows nor overflows.
  glm::dvec3 direction() const {
    const glm::dvec3 d = vec3();
    const double big = std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)});
    if (big == 0.0) fail("must be non-zero");
    return glm::normalize(d / big);
  }
  glm::vec3 color(double lo, double hi) const {
    if (!value.is_array() || value.size() != 3) fail("must be an array of 3 numbers");
    return glm::vec3(at(0).number(lo, hi), at(1).number(lo, hi), at(2).number(lo, hi));
  }
  static std::string fmt(double d) {
    std::ostringstream s;
    s << d;
    return s.str();
  }
};

}  // namespace voxgi

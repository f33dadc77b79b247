// The tables behind --set and the scene files' "settings": one Param per key, built with number()
// and choice() from the field it reads and writes. The shared stages' table is in
// common/settings.cpp; each technique's lives with its settings (common/vct/settings.cpp).
#pragma once

#include <charconv>
#include <cmath>
#include <functional>
#include <sstream>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "common/settings.h"

namespace voxgi {

// One --set key: how to read and write it on Settings, and how to describe it.
struct Param {
  std::string key;
  std::string range;  // "[lo, hi]" or "a|b|c"
  std::string meaning;
  std::function<std::string(const Settings&)> get;
  std::function<bool(Settings&, const std::string&)> set;  // false: value rejected
};

// A named set of assignments; "default" (the empty one) comes first in every technique's list.
struct Preset {
  std::string name;
  std::vector<std::string> assignments;
};

namespace settings_table {

// The field `Member` of Settings, or of its section `Section` (nullptr: Settings itself).
template <auto Section, class T, class S>
T& field(Settings& s, T S::*member) {
  if constexpr (std::is_same_v<decltype(Section), std::nullptr_t>)
    return s.*member;
  else
    return (s.*Section).*member;
}
template <auto Section, class T, class S>
const T& field(const Settings& s, T S::*member) {
  return field<Section>(const_cast<Settings&>(s), member);  // reads only
}

template <class T>
std::string format(T v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

}  // namespace settings_table

// A float or int key; the whole text must parse (std::from_chars) to a finite value in [lo, hi].
template <auto Section = nullptr, class T, class S>
Param number(std::string key, T S::*member, T lo, T hi, std::string meaning) {
  std::ostringstream range;  // a stream: GCC 12 warns falsely (-Wrestrict) on chained operator+
  range << '[' << lo << ", " << hi << ']';
  return {std::move(key), range.str(), std::move(meaning),
          [member](const Settings& s) {
            return settings_table::format(settings_table::field<Section>(s, member));
          },
          [member, lo, hi](Settings& s, const std::string& text) {
            T v{};
            const char* end = text.data() + text.size();
            const auto [ptr, ec] = std::from_chars(text.data(), end, v);
            if (ec != std::errc() || ptr != end || !std::isfinite(double(v)) || v < lo || v > hi)
              return false;
            settings_table::field<Section>(s, member) = v;
            return true;
          }};
}

// An enum key whose values are `names`, in the enum's order.
template <auto Section = nullptr, class E, class S>
Param choice(std::string key, E S::*member, std::vector<std::string> names, std::string meaning) {
  std::string range;
  for (const auto& n : names) range.append(range.empty() ? "" : "|").append(n);
  return {std::move(key), range, std::move(meaning),
          [member, names](const Settings& s) {
            return names[static_cast<size_t>(settings_table::field<Section>(s, member))];
          },
          [member, names](Settings& s, const std::string& text) {
            for (size_t i = 0; i < names.size(); ++i)
              if (names[i] == text) {
                settings_table::field<Section>(s, member) = static_cast<E>(i);
                return true;
              }
            return false;
          }};
}

// The shared keys (voxelize.mode, plan.mode, update.interval).
const std::vector<Param>& sharedParams();

}  // namespace voxgi

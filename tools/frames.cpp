#include "tools/frames.h"

#include <charconv>
#include <regex>
#include <string_view>

#include "common/error.h"

namespace voxgi::tools {

namespace {
constexpr int kMaxFrames = 100000;
}

Shard parseShard(const std::string& text, const std::string& option) {
  Shard s;
  const std::string_view all(text);
  const size_t slash = all.find('/');
  const auto number = [](std::string_view part, size_t& out) {
    const auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), out);
    return error == std::errc() && end == part.data() + part.size() && !part.empty();
  };
  if (slash == std::string_view::npos || !number(all.substr(0, slash), s.index) ||
      !number(all.substr(slash + 1), s.count) || s.count < 1 || s.count > 10000 ||
      s.index >= s.count)
    throw InputError(option, "", "expected I/N with 0 <= I < N <= 10000, got '" + text + "'");
  return s;
}

FrameRange parseFrames(const std::string& text, const std::string& option) {
  static const std::regex form(R"((\d{1,9}):(\d{1,9})(?::(\d{1,9}))?)");
  std::smatch m;
  if (!std::regex_match(text, m, form))
    throw InputError(option, "", "must be A:B or A:B:STEP (frame numbers), got '" + text + "'");
  FrameRange r{std::stoi(m[1]), std::stoi(m[2]), m[3].matched ? std::stoi(m[3]) : 1};
  if (r.last < r.first) throw InputError(option, "", "the last frame comes before the first");
  if (r.step < 1) throw InputError(option, "", "the step must be at least 1");
  if (r.count() > kMaxFrames)
    throw InputError(option, "", "more than " + std::to_string(kMaxFrames) + " frames");
  return r;
}

std::string framePath(const std::string& pattern, int frame, const std::string& option) {
  static const std::regex field(R"(%(0[1-9])?d)");
  const auto begin = std::sregex_iterator(pattern.begin(), pattern.end(), field);
  if (std::distance(begin, std::sregex_iterator()) != 1)
    throw InputError(
        option, "",
        "a sequence's file name needs one frame field such as %04d, got '" + pattern + "'");
  const std::smatch& m = *begin;
  std::string number = std::to_string(frame);
  if (m[1].matched) {
    const size_t width = size_t(m[1].str()[1] - '0');
    if (number.size() < width) number.insert(0, width - number.size(), '0');
  }
  return m.prefix().str() + number + m.suffix().str();
}

}  // namespace voxgi::tools

#include "tools/frames.h"

#include <regex>

#include "common/error.h"

namespace voxgi::tools {

namespace {
constexpr int kMaxFrames = 100000;
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

// Frame ranges and per-frame file names for the commands that render sequences (`--frames A:B`,
// `--out out_%04d.exr`; docs/motion.md).
#pragma once

#include <cstddef>
#include <string>

namespace voxgi::tools {

struct FrameRange {
  int first = 0, last = 0, step = 1;
  int count() const { return (last - first) / step + 1; }
};

// "A:B" or "A:B:STEP": frames A to B inclusive, 0 <= A <= B, STEP >= 1, at most 100000 frames;
// throws InputError naming `option` otherwise.
FrameRange parseFrames(const std::string& text, const std::string& option);

// A batch job array's share of the work: items k with k % count == index ("I/N", 0 <= I < N <=
// 10000; throws InputError naming `option` otherwise). Round robin, so that every shard gets a
// share of the expensive and the cheap items alike.
struct Shard {
  size_t index = 0, count = 1;
  bool owns(size_t item) const { return item % count == index; }
};
Shard parseShard(const std::string& text, const std::string& option);

// `pattern` with its one printf-style frame field (%d or %0Nd, N in 1..9) replaced by `frame`;
// throws InputError naming `option` when it has none, or more than one.
std::string framePath(const std::string& pattern, int frame, const std::string& option);

}  // namespace voxgi::tools

#include "common/io/exr_check.h"

#include <cstdint>
#include <fstream>
#include <set>

#include "common/error.h"
#include "common/io/input_file.h"

namespace voxgi {
namespace {

// The layout of the header, from the OpenEXR file-layout document: a magic number, a version
// field (low byte 2, flag bits above), then attributes (name NUL, type NUL, int32 size, value)
// until an empty name.
constexpr uint32_t kMagic = 20000630;
constexpr uint32_t kTiled = 0x200, kLongNames = 0x400, kDeep = 0x800, kMultiPart = 0x1000;

uint32_t le32(const unsigned char* b) {
  return uint32_t(b[0]) | uint32_t(b[1]) << 8 | uint32_t(b[2]) << 16 | uint32_t(b[3]) << 24;
}

// Whether the value of an attribute of `type` at the stream's position takes exactly `bytes`
// bytes as OpenEXR 3.1 reads it; an unknown type is read as `bytes` opaque bytes.
bool contentMatchesSize(std::istream& in, const std::string& type, uint64_t bytes) {
  static const std::pair<const char*, uint64_t> fixed[] = {{"box2i", 16},
                                                           {"box2f", 16},
                                                           {"v2i", 8},
                                                           {"v2f", 8},
                                                           {"v2d", 16},
                                                           {"v3i", 12},
                                                           {"v3f", 12},
                                                           {"v3d", 24},
                                                           {"float", 4},
                                                           {"double", 8},
                                                           {"int", 4},
                                                           {"compression", 1},
                                                           {"lineOrder", 1},
                                                           {"envmap", 1},
                                                           {"deepImageState", 1},
                                                           {"chromaticities", 32},
                                                           {"keycode", 28},
                                                           {"timecode", 8},
                                                           {"rational", 8},
                                                           {"m33f", 36},
                                                           {"m33d", 72},
                                                           {"m44f", 64},
                                                           {"m44d", 128},
                                                           {"tiledesc", 9}};
  for (const auto& [name, size] : fixed)
    if (type == name) return bytes == size;
  if (type == "chlist") {  // channels: name NUL, 16 bytes each, up to an empty name
    uint64_t used = 0;
    for (char c; used < bytes;) {
      uint64_t nameBytes = 0;
      while (in.get(c) && c != '\0') ++nameBytes;
      if (!in) return false;
      used += nameBytes + 1;
      if (nameBytes == 0) return used == bytes;
      in.seekg(16, std::ios::cur);
      used += 16;
    }
    return false;
  }
  if (type == "preview") {  // width, height, then 4 bytes per pixel
    unsigned char wh[8];
    if (bytes < 8 || !in.read(reinterpret_cast<char*>(wh), 8)) return false;
    return 8 + 4 * uint64_t(le32(wh)) * le32(wh + 4) == bytes;
  }
  if (type == "stringvector") {  // int32 length, then the bytes, up to the declared size
    uint64_t used = 0;
    unsigned char n[4];
    while (used < bytes) {
      if (bytes - used < 4 || !in.read(reinterpret_cast<char*>(n), 4)) return false;
      used += 4 + le32(n);
      in.seekg(std::streamoff(le32(n)), std::ios::cur);
    }
    return used == bytes;
  }
  return true;  // string and unknown types: read as the declared bytes
}

}  // namespace

void checkExrHeader(const std::string& path) {
  const uint64_t size = requireInputFile(path, "", "EXR image");
  // Read as a stream, skipping values: a reference image can be gigabytes, its header is small.
  std::ifstream in(path, std::ios::binary);
  unsigned char word[4];
  const auto read4 = [&] { return bool(in.read(reinterpret_cast<char*>(word), 4)); };
  if (!read4() || le32(word) != kMagic)
    throw InputError(path, "", "not an OpenEXR file (no magic number)");
  if (!read4()) throw InputError(path, "version", "the file ends before it");
  const uint32_t version = le32(word);
  if ((version & 0xff) != 2)
    throw InputError(path, "version", "is " + std::to_string(version & 0xff) + ", not 2");
  if (version & (kDeep | kMultiPart))
    throw InputError(path, "version",
                     "deep or multi-part EXR: voxgi reads single-part flat RGB images");
  if (version & ~(0xffu | kTiled | kLongNames))
    throw InputError(path, "version", "unknown flags " + std::to_string(version & ~0xffu));
  const size_t maxName = version & kLongNames ? 255 : 31;
  // A NUL-terminated name of at most maxName characters.
  const auto name = [&](const std::string& field) {
    std::string s;
    for (char c; in.get(c) && c != '\0';) {
      if (s.size() == maxName)
        throw InputError(path, field,
                         "not terminated within " + std::to_string(maxName) + " characters");
      s += c;
    }
    if (!in) throw InputError(path, field, "the file ends inside it");
    return s;
  };
  std::set<std::string> names;
  for (int attribute = 0;; ++attribute) {
    const std::string field = "header attribute " + std::to_string(attribute);
    const std::string attributeName = name(field);
    if (attributeName.empty()) return;  // the end of the header
    const std::string named = field + " (" + attributeName + ")";
    const std::string type = name(named + " type");
    if (!read4()) throw InputError(path, named, "the file ends inside its size");
    const uint64_t valueBytes = le32(word), left = size - uint64_t(in.tellg());
    if (valueBytes > left)
      throw InputError(path, named,
                       "declares " + std::to_string(valueBytes) + " bytes, the file has " +
                           std::to_string(left) + " left");
    // OpenEXR reads a known type by its content, not by the declared size, so the two must agree
    // or OpenEXR reads the rest of the header from another place than this check.
    const uint64_t start = uint64_t(in.tellg());
    if (!contentMatchesSize(in, type, valueBytes))
      throw InputError(
          path, named,
          "declares " + std::to_string(valueBytes) + " bytes, its " + type + " content does not");
    in.seekg(std::streamoff(start));
    if (!names.insert(attributeName).second)
      throw InputError(path, named, "appears twice in the header");
    // OpenEXR sizes its line and tile buffers by these before voxgi can look at the image, so
    // their sizes are checked here: at most 16384 per side, as readImage accepts.
    const bool window = attributeName == "dataWindow", tiles = attributeName == "tiles";
    if ((window && valueBytes != 16) || (tiles && valueBytes != 9))
      throw InputError(path, named, "has " + std::to_string(valueBytes) + " bytes");
    if (!window && !tiles) {
      in.seekg(std::streamoff(valueBytes), std::ios::cur);
      continue;
    }
    unsigned char value[16];
    if (!in.read(reinterpret_cast<char*>(value), std::streamsize(valueBytes)))
      throw InputError(path, named, "the file ends inside it");
    const auto i32 = [&](int k) { return int64_t(int32_t(le32(value + 4 * k))); };
    const int64_t w = window ? i32(2) - i32(0) + 1 : int64_t(le32(value));
    const int64_t h = window ? i32(3) - i32(1) + 1 : int64_t(le32(value + 4));
    if (w < 1 || h < 1 || w > 16384 || h > 16384)
      throw InputError(
          path, named,
          std::to_string(w) + "x" + std::to_string(h) + " is outside 1..16384 per side");
  }
}

}  // namespace voxgi

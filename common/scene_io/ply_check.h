// A complete check of a PLY file before Assimp reads it. Assimp's PLY importer crashes on face
// indices outside the vertex list and on truncated binary bodies, hangs on a header without
// end_header, allocates whatever count a header declares, and reads a face with a list count of
// 255 as a triangle; this walks the header and every element once, in time and memory bounded by
// the file's size, and throws InputError naming the file, the element and the index for the first
// thing wrong.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace voxgi {

struct PlyProperty {
  enum class Type { int8, uint8, int16, uint16, int32, uint32, float32, float64 };
  std::string name;
  Type type = Type::float32;
  bool list = false;
  Type countType = Type::uint8;  // lists only
};

struct PlyElement {
  std::string name;
  uint64_t count = 0;
  std::vector<PlyProperty> properties;
};

struct PlyHeader {
  enum class Format { ascii, binary_little_endian, binary_big_endian };
  Format format = Format::ascii;
  std::vector<PlyElement> elements;
  uint64_t bodyOffset = 0;  // first byte after end_header's line
};

// Bytes a value of `type` takes in a binary body.
size_t plyTypeSize(PlyProperty::Type type);
// Whether `type` is an integer type.
bool plyIntegral(PlyProperty::Type type);
// Parses the whole of `word` as an ASCII value of `type`: an integer for integer types, a number
// within float's range for float (1e39 is no float), any number for double.
bool parsePlyAscii(std::string_view word, PlyProperty::Type type, double& value);

// Reads and checks the header of `bytes` (the file's content): the magic line, the format,
// elements and properties, end_header within the first 64 KiB, and counts that fit in the rest.
PlyHeader readPlyHeader(const std::string& path, const std::string& bytes);
// The same from the first bytes of a file of `fileSize` bytes (at least its first 64 KiB).
PlyHeader readPlyHeader(const std::string& path, std::string_view head, uint64_t fileSize);
// The header of the file at `path`, reading its first 64 KiB only.
PlyHeader readPlyHeaderOfFile(const std::string& path);

// Checks the whole file: the header as above, then every element — one line of the declared
// values each in ASCII, exactly the declared bytes in binary, no data left over — and every vertex
// index of the faces in [0, vertex count), at least 3 per face. Returns the header.
PlyHeader checkPly(const std::string& path);

}  // namespace voxgi

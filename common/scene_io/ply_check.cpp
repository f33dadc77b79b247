#include "common/scene_io/ply_check.h"

#include <algorithm>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>

#include "common/error.h"
#include "common/io/input_file.h"

namespace voxgi {
namespace {

using Type = PlyProperty::Type;

constexpr size_t kMaxHeaderBytes = 64 * 1024;

}  // namespace

bool plyIntegral(Type t) {
  return t != Type::float32 && t != Type::float64;
}

bool parsePlyAscii(std::string_view word, Type type, double& value) {
  const char* end = word.data() + word.size();
  if (plyIntegral(type)) {
    int64_t v = 0;
    const auto [ptr, ec] = std::from_chars(word.data(), end, v);
    if (ec != std::errc() || ptr != end) return false;
    value = double(v);
    return true;
  }
  if (type == Type::float32) {  // out of float's range: from_chars reports it
    float f = 0.0f;
    const auto [ptr, ec] = std::from_chars(word.data(), end, f);
    value = double(f);
    return ec == std::errc() && ptr == end;
  }
  const auto [ptr, ec] = std::from_chars(word.data(), end, value);
  return ec == std::errc() && ptr == end;
}

size_t plyTypeSize(Type t) {
  switch (t) {
    case Type::int8:
    case Type::uint8:
      return 1;
    case Type::int16:
    case Type::uint16:
      return 2;
    case Type::int32:
    case Type::uint32:
    case Type::float32:
      return 4;
    case Type::float64:
      return 8;
  }
  return 0;
}

namespace {

bool parseType(const std::string& s, Type& t) {
  static const std::pair<const char*, Type> names[] = {
      {"char", Type::int8},      {"int8", Type::int8},       {"uchar", Type::uint8},
      {"uint8", Type::uint8},    {"short", Type::int16},     {"int16", Type::int16},
      {"ushort", Type::uint16},  {"uint16", Type::uint16},   {"int", Type::int32},
      {"int32", Type::int32},    {"uint", Type::uint32},     {"uint32", Type::uint32},
      {"float", Type::float32},  {"float32", Type::float32}, {"double", Type::float64},
      {"float64", Type::float64}};
  for (const auto& [name, type] : names)
    if (s == name) {
      t = type;
      return true;
    }
  return false;
}

// Splits a line into whitespace-separated words.
std::vector<std::string_view> words(std::string_view line) {
  std::vector<std::string_view> out;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    const size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
  return out;
}

std::string lower(std::string s) {
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// What Assimp's PLY importer makes of an element, by its name (case-sensitive, as Assimp's).
enum class Semantic { vertex, face, tristrips, other };
Semantic semanticOf(const PlyElement& e) {
  if (e.name == "vertex") return Semantic::vertex;
  if (e.name == "face") return Semantic::face;
  if (e.name == "tristrips") return Semantic::tristrips;
  return Semantic::other;
}

// The lists whose values index the vertices: a face's vertex_indices (or vertex_index), and the
// first list of a tristrips element, which Assimp reads as strips with -1 as the restart.
bool isVertexIndices(const PlyElement& e, const PlyProperty& p) {
  if (!p.list) return false;
  if (semanticOf(e) == Semantic::tristrips)
    for (const PlyProperty& q : e.properties)
      if (q.list) return &q == &p;
  const std::string name = lower(p.name);
  return semanticOf(e) == Semantic::face && (name == "vertex_indices" || name == "vertex_index");
}

// A value of type T from its bytes in native order.
template <class T>
double load(const unsigned char* bytes) {
  T v;
  std::memcpy(&v, bytes, sizeof v);
  return double(v);
}

// Reads one value of `type` from a binary body; false at the end of the data.
struct BinaryReader {
  const std::string& bytes;
  size_t at;
  bool bigEndian;

  bool read(Type type, double& value) {
    const size_t n = plyTypeSize(type);
    if (bytes.size() - at < n) return false;
    unsigned char b[8];
    std::memcpy(b, bytes.data() + at, n);
    at += n;
    if (bigEndian != (std::endian::native == std::endian::big))
      for (size_t i = 0; i < n / 2; ++i) std::swap(b[i], b[n - 1 - i]);
    switch (type) {
      case Type::int8:
        value = load<int8_t>(b);
        break;
      case Type::uint8:
        value = load<uint8_t>(b);
        break;
      case Type::int16:
        value = load<int16_t>(b);
        break;
      case Type::uint16:
        value = load<uint16_t>(b);
        break;
      case Type::int32:
        value = load<int32_t>(b);
        break;
      case Type::uint32:
        value = load<uint32_t>(b);
        break;
      case Type::float32:
        value = load<float>(b);
        break;
      case Type::float64:
        value = load<double>(b);
        break;
    }
    return true;
  }
};

// Assimp's header parser stops at a NUL and treats other control bytes (a carriage return inside
// a line) its own way: a header it could read differently from this check is refused. Carriage
// returns only as CRLF line ends.
void refuseControlCharacters(const std::string& path, const std::string& where,
                             std::string_view line) {
  const std::string_view body =
      !line.empty() && line.back() == '\r' ? line.substr(0, line.size() - 1) : line;
  for (const char c : body)
    if ((static_cast<unsigned char>(c) < 0x20 && c != '\t') || c == 0x7f)
      throw InputError(path, where, "a control character in the header");
}

PlyHeader::Format readFormat(const std::string& path, const std::string& where,
                             const std::vector<std::string_view>& w) {
  if (w.size() != 3 || w[2] != "1.0")
    throw InputError(path, where,
                     "expected 'format ascii|binary_little_endian|"
                     "binary_big_endian 1.0'");
  if (w[1] == "ascii") return PlyHeader::Format::ascii;
  if (w[1] == "binary_little_endian") return PlyHeader::Format::binary_little_endian;
  if (w[1] == "binary_big_endian") return PlyHeader::Format::binary_big_endian;
  throw InputError(path, where, "unknown format '" + std::string(w[1]) + "'");
}

PlyElement readElement(const std::string& path, const std::string& where,
                       const std::vector<std::string_view>& w) {
  uint64_t count = 0;
  if (w.size() != 3 ||
      std::from_chars(w[2].data(), w[2].data() + w[2].size(), count).ec != std::errc())
    throw InputError(path, where, "expected 'element NAME COUNT'");
  // Assimp 5.2 parses the count of an element it does not know from the start of its name (0, or
  // whatever digits the name starts with), so such an element shifts every byte it reads after
  // it; it reads counts as 32 bits.
  static const char* known[] = {"vertex", "face", "tristrips", "edge", "material"};
  if (std::none_of(std::begin(known), std::end(known), [&](const char* k) { return w[1] == k; }))
    throw InputError(path, where,
                     "element '" + std::string(w[1]) +
                         "': voxgi reads vertex, face, tristrips, edge and material elements");
  if (count > 0xffffffffu) throw InputError(path, where, "more than 2^32 - 1 instances");
  return {std::string(w[1]), count, {}};
}

PlyProperty readProperty(const std::string& path, const std::string& where,
                         const std::vector<std::string_view>& w) {
  PlyProperty p;
  const bool ok = w.size() == 5 && w[1] == "list"
                      ? parseType(std::string(w[2]), p.countType) &&
                            parseType(std::string(w[3]), p.type) && plyIntegral(p.countType)
                      : w.size() == 3 && parseType(std::string(w[1]), p.type);
  if (!ok)
    throw InputError(path, where,
                     "expected 'property TYPE NAME' or 'property list COUNT_TYPE TYPE NAME' "
                     "with an integer count type");
  p.list = w.size() == 5;
  p.name = std::string(w.back());
  return p;
}

// The least the declared elements can take, checked before anything is read or allocated; and
// an instance of an element without properties takes no bytes, so its count would not be bounded
// by the file's size (10^18 of them took forever to walk).
void checkDeclaredSize(const std::string& path, const PlyHeader& h, uint64_t fileSize) {
  for (const PlyElement& e : h.elements)
    if (e.properties.empty() && e.count > 0)
      throw InputError(path, "element " + e.name, "declares no properties");
  const uint64_t body = fileSize - h.bodyOffset;
  long double least = 0.0L;
  for (const PlyElement& e : h.elements) {
    uint64_t perItem = 0;
    for (const PlyProperty& p : e.properties)
      perItem +=
          h.format == PlyHeader::Format::ascii ? 2 : plyTypeSize(p.list ? p.countType : p.type);
    least += static_cast<long double>(e.count) * static_cast<long double>(perItem);
  }
  if (least > static_cast<long double>(body))
    throw InputError(path, "header",
                     "the declared elements need at least " +
                         std::to_string(uint64_t(std::min<long double>(least, 1.8e19L))) +
                         " bytes, the file has " + std::to_string(body) + " after the header");
}

}  // namespace

PlyHeader readPlyHeader(const std::string& path, const std::string& bytes) {
  return readPlyHeader(path, std::string_view(bytes), bytes.size());
}

PlyHeader readPlyHeader(const std::string& path, std::string_view bytes, uint64_t fileSize) {
  PlyHeader h;
  size_t at = 0;
  int lineNumber = 0;
  bool sawFormat = false, ended = false;
  while (!ended) {
    const size_t eol = bytes.find('\n', at);
    if (eol == std::string::npos || eol >= kMaxHeaderBytes)
      throw InputError(
          path, "header",
          "no end_header line within the first " + std::to_string(kMaxHeaderBytes / 1024) + " KiB");
    const std::string_view line(bytes.data() + at, eol - at);
    at = eol + 1;
    ++lineNumber;
    const auto w = words(line);
    const std::string where = "header line " + std::to_string(lineNumber);
    refuseControlCharacters(path, where, line);
    if (lineNumber == 1) {
      if (w.size() != 1 || w[0] != "ply")
        throw InputError(path, where, "not a PLY file (no 'ply')");
      continue;
    }
    // Assimp reads an element's properties from the lines right after it, skipping only plain
    // comments, and ignores property lines after anything else; a binary body starts right after
    // the LF of end_header. Headers it would read differently are refused.
    if (w.empty()) throw InputError(path, where, "an empty line in the header");
    if (h.format != PlyHeader::Format::ascii && sawFormat && line.back() == '\r')
      throw InputError(path, where, "a binary PLY header must end its lines with LF, not CRLF");
    const bool inProperties = !h.elements.empty();
    if (inProperties &&
        (w[0] == "obj_info" || (w[0] == "comment" && w.size() > 1 && w[1] == "TextureFile")))
      throw InputError(
          path, where,
          std::string(w[0]) + " between the properties of element " + h.elements.back().name);
    if (w[0] == "comment" || w[0] == "obj_info") continue;
    if (w[0] == "format") {
      if (sawFormat) throw InputError(path, where, "a second format line");
      h.format = readFormat(path, where, w);
      sawFormat = true;
    } else if (w[0] == "element") {
      h.elements.push_back(readElement(path, where, w));
    } else if (w[0] == "property") {
      if (h.elements.empty()) throw InputError(path, where, "property before any element");
      h.elements.back().properties.push_back(readProperty(path, where, w));
    } else if (w[0] == "end_header" && w.size() == 1) {
      ended = true;
    } else {
      throw InputError(path, where, "unexpected '" + std::string(w[0]) + "'");
    }
  }
  if (!sawFormat) throw InputError(path, "header", "no format line");
  h.bodyOffset = at;
  checkDeclaredSize(path, h, fileSize);
  return h;
}

PlyHeader checkPly(const std::string& path) {
  const std::string bytes = readInputFile(path, "", "PLY file");
  const PlyHeader h = readPlyHeader(path, bytes);
  // Assimp sizes its vertex and face arrays by the first element of each kind and writes the
  // instances of a second one past their end: one element of each kind at most.
  uint64_t vertices = 0;
  bool haveVertices = false;
  int faceElements = 0;
  for (const PlyElement& e : h.elements) {
    const Semantic kind = semanticOf(e);
    if (kind == Semantic::vertex && haveVertices)
      throw InputError(path, "element " + e.name, "a second vertex element");
    if (kind == Semantic::vertex) vertices = e.count, haveVertices = true;
    for (const char* axis : {"x", "y", "z"})
      if (kind == Semantic::vertex &&
          std::none_of(e.properties.begin(), e.properties.end(),
                       [&](const PlyProperty& p) { return !p.list && p.name == axis; }))
        throw InputError(path, "element " + e.name,
                         std::string("no property ") + axis + " (positions need x, y and z)");
    if ((kind == Semantic::face || kind == Semantic::tristrips) && ++faceElements > 1)
      throw InputError(path, "element " + e.name, "a second face or tristrips element");
  }
  const bool ascii = h.format == PlyHeader::Format::ascii;
  BinaryReader reader{bytes, h.bodyOffset, h.format == PlyHeader::Format::binary_big_endian};
  size_t at = h.bodyOffset;  // ASCII position
  for (const PlyElement& e : h.elements) {
    for (uint64_t i = 0; i < e.count; ++i) {
      const std::string where = e.name + " " + std::to_string(i);
      std::vector<std::string_view> w;
      size_t next = 0;  // next word of an ASCII line
      if (ascii) {
        const size_t eol = std::min(bytes.find('\n', at), bytes.size());
        if (at >= bytes.size()) throw InputError(path, where, "missing: the file ends early");
        w = words(std::string_view(bytes.data() + at, eol - at));
        at = eol + 1;
      }
      const auto value = [&](Type type, double& v) {
        if (!ascii) {
          if (!reader.read(type, v)) throw InputError(path, where, "missing: the file ends early");
          return;
        }
        if (next >= w.size()) throw InputError(path, where, "the line has too few values");
        if (!parsePlyAscii(w[next], type, v))
          throw InputError(
              path, where,
              "'" + std::string(w[next]).substr(0, 32) + "' is not a valid value of its type");
        ++next;
      };
      // Assimp reads a face's texcoord list as two values per vertex of the face, indexing the
      // face's vertex list with them (past its end, or through null without one).
      uint64_t faceVertices = 0, texcoords = 0;
      for (const PlyProperty& p : e.properties) {
        double v = 0.0;
        if (!p.list) {
          value(p.type, v);
          continue;
        }
        value(p.countType, v);
        if (v < 0.0) throw InputError(path, where, p.name + ": negative list count");
        const auto n = static_cast<uint64_t>(v);
        if (semanticOf(e) == Semantic::face && p.name == "texcoord") texcoords = n;
        if (isVertexIndices(e, p)) faceVertices = n;
        const bool indices = isVertexIndices(e, p);
        const bool strips = indices && semanticOf(e) == Semantic::tristrips;
        if (indices && !haveVertices) throw InputError(path, where, "faces but no vertex element");
        if (indices && !strips && n < 3)
          throw InputError(path, where,
                           p.name + ": a face needs at least 3 vertices, has " + std::to_string(n));
        for (uint64_t k = 0; k < n; ++k) {
          value(p.type, v);
          if (strips && v == -1.0) continue;  // a restart of the strip
          if (indices && !(v >= 0.0 && v < double(vertices) && std::floor(v) == v))
            throw InputError(path, where,
                             p.name + ": vertex index " + std::to_string(int64_t(v)) +
                                 " outside [0, " + std::to_string(vertices) + ")");
        }
      }
      if (texcoords != 0 && texcoords != 2 * faceVertices)
        throw InputError(path, where,
                         "texcoord: " + std::to_string(texcoords) + " values for a face of " +
                             std::to_string(faceVertices) + " vertices (two per vertex)");
      if (ascii && next != w.size())
        throw InputError(path, where,
                         "the line has " + std::to_string(w.size() - next) +
                             " values more than the header declares");
    }
  }
  if (ascii) {
    for (; at < bytes.size(); ++at)
      if (!std::isspace(static_cast<unsigned char>(bytes[at])))
        throw InputError(path, "body", "data after the last declared element");
  } else if (reader.at != bytes.size()) {
    throw InputError(
        path, "body",
        std::to_string(bytes.size() - reader.at) + " bytes after the last declared element");
  }
  return h;
}

PlyHeader readPlyHeaderOfFile(const std::string& path) {
  const uint64_t size = requireInputFile(path, "", "PLY file");
  std::ifstream in(path, std::ios::binary);
  std::string head(std::min<uint64_t>(size, kMaxHeaderBytes), '\0');
  in.read(head.data(), std::streamsize(head.size()));
  head.resize(size_t(in.gcount()));
  return readPlyHeader(path, std::string_view(head), size);
}

}  // namespace voxgi

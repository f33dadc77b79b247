#include "common/scene_io/point_cloud_ply.h"

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>

#include <tbb/blocked_range.h>

#include "common/error.h"
#include "common/io/image_io.h"
#include "common/io/input_file.h"
#include "common/io/output_file.h"
#include "common/parallel.h"

namespace voxgi {
namespace {

using Type = PlyProperty::Type;

// Where each property voxgi reads sits in a vertex: its index among the properties (-1: absent).
struct Layout {
  int position[3] = {-1, -1, -1};
  int normal[3] = {-1, -1, -1};
  int color[3] = {-1, -1, -1};
  int radius = -1;
};

// The largest value of an unsigned integer colour type (0: not one).
double colorMaximum(Type t) {
  return t == Type::uint8 ? 255.0 : t == Type::uint16 ? 65535.0 : 0.0;
}

Layout layoutOf(const std::string& path, const PlyElement& vertex) {
  Layout l;
  const auto find = [&](std::initializer_list<const char*> names) {
    for (size_t i = 0; i < vertex.properties.size(); ++i)
      for (const char* n : names)
        if (vertex.properties[i].name == n) return int(i);
    return -1;
  };
  const char* axes[3] = {"x", "y", "z"};
  const char* normals[3] = {"nx", "ny", "nz"};
  for (int a = 0; a < 3; ++a) {
    l.position[a] = find({axes[a]});
    l.normal[a] = find({normals[a]});
  }
  l.color[0] = find({"red", "diffuse_red"});
  l.color[1] = find({"green", "diffuse_green"});
  l.color[2] = find({"blue", "diffuse_blue"});
  l.radius = find({"radius"});
  const std::string where = "element vertex";
  for (const PlyProperty& p : vertex.properties)
    if (p.list)
      throw InputError(path, where,
                       "a point cloud's vertices have no list property (" + p.name + ")");
  for (int a = 0; a < 3; ++a)
    if (l.position[a] < 0)
      throw InputError(path, where,
                       std::string("no property ") + axes[a] + " (positions need x, y and z)");
  const auto allOrNone = [&](const int(&idx)[3], const char* what) {
    const int present = (idx[0] >= 0) + (idx[1] >= 0) + (idx[2] >= 0);
    if (present != 0 && present != 3)
      throw InputError(path, where,
                       std::string("only some of ") + what + " (give all three or none)");
  };
  allOrNone(l.normal, "nx, ny, nz");
  allOrNone(l.color, "red, green, blue");
  for (const int c : l.color)
    if (c >= 0) {
      const Type t = vertex.properties[size_t(c)].type;
      if (plyIntegral(t) && colorMaximum(t) == 0.0)
        throw InputError(
            path, where,
            vertex.properties[size_t(c)].name + ": a colour is uchar, ushort, float or double");
    }
  return l;
}

// Values of one property for n vertices `stride` bytes apart, in the file's byte order.
template <class T>
void decodeColumn(const unsigned char* at, size_t stride, bool swap, size_t n, double* out) {
  for (size_t j = 0; j < n; ++j) {
    unsigned char b[sizeof(T)];
    std::memcpy(b, at + j * stride, sizeof b);
    if (swap) std::reverse(b, b + sizeof b);
    T v;
    std::memcpy(&v, b, sizeof v);
    out[j] = double(v);
  }
}

void decodeColumn(Type type, const unsigned char* at, size_t stride, bool swap, size_t n,
                  double* out) {
  switch (type) {
    case Type::int8:
      return decodeColumn<int8_t>(at, stride, swap, n, out);
    case Type::uint8:
      return decodeColumn<uint8_t>(at, stride, swap, n, out);
    case Type::int16:
      return decodeColumn<int16_t>(at, stride, swap, n, out);
    case Type::uint16:
      return decodeColumn<uint16_t>(at, stride, swap, n, out);
    case Type::int32:
      return decodeColumn<int32_t>(at, stride, swap, n, out);
    case Type::uint32:
      return decodeColumn<uint32_t>(at, stride, swap, n, out);
    case Type::float32:
      return decodeColumn<float>(at, stride, swap, n, out);
    case Type::float64:
      return decodeColumn<double>(at, stride, swap, n, out);
  }
}

// Fills point i from its property values (in header order) and returns what is wrong with them,
// empty when nothing is.
std::string store(PlyPoints& out, size_t i, const double* v, const Layout& l,
                  const PlyElement& vertex) {
  const glm::dvec3 p(v[l.position[0]], v[l.position[1]], v[l.position[2]]);
  if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
    return "x, y, z: NaN or infinite";
  out.positions[i] = p;
  if (l.normal[0] >= 0) {
    const glm::dvec3 n(v[l.normal[0]], v[l.normal[1]], v[l.normal[2]]);
    if (!std::isfinite(n.x) || !std::isfinite(n.y) || !std::isfinite(n.z))
      return "nx, ny, nz: NaN or infinite";
    if (n == glm::dvec3(0.0)) return "nx, ny, nz: the zero vector";
    out.normals[i] = glm::vec3(glm::normalize(n));
  }
  if (l.color[0] >= 0)
    for (int c = 0; c < 3; ++c) {
      const PlyProperty& prop = vertex.properties[size_t(l.color[c])];
      const double maximum = colorMaximum(prop.type);
      const double value = maximum > 0.0 ? v[l.color[c]] / maximum : v[l.color[c]];
      if (!(value >= 0.0 && value <= 1.0)) return prop.name + ": a float colour must be in [0, 1]";
      out.colors[i][c] = float(value);
    }
  if (l.radius >= 0) {
    const double r = v[l.radius];
    if (!(r > 0.0 && r <= 1e15)) return "radius: must be a positive finite number";
    out.radii[i] = float(r);
  }
  return {};
}

}  // namespace

bool plyIsPointCloud(const PlyHeader& header) {
  bool vertices = false;
  for (const PlyElement& e : header.elements) {
    if (e.name == "vertex")
      vertices = true;
    else if (e.count > 0)
      return false;
  }
  return vertices;
}

namespace {

// The vertex element of a file that is a point cloud (refused otherwise).
const PlyElement& pointElement(const std::string& path, const PlyHeader& h) {
  if (!plyIsPointCloud(h))
    throw InputError(path, "", "not a point cloud (one vertex element, no faces)");
  const auto isVertex = [](const PlyElement& e) { return e.name == "vertex"; };
  if (std::count_if(h.elements.begin(), h.elements.end(), isVertex) > 1)
    throw InputError(path, "element vertex", "a second vertex element");
  return *std::find_if(h.elements.begin(), h.elements.end(), isVertex);
}

// What a vertex element decodes into, and where it throws.
struct PointReader {
  const std::string& path;
  const std::string& bytes;
  const PlyHeader& h;
  const PlyElement& vertex;
  Layout l;
  PlyPoints& out;

  [[noreturn]] void fail(size_t i, const std::string& what) const {
    throw InputError(path, "vertex " + std::to_string(i), what);
  }

  // Binary: decoded a block at a time, one property after another; the first bad vertex is
  // reported, whatever order the threads run in.
  void binary(size_t stride) const {
    const size_t props = vertex.properties.size(), count = vertex.count;
    std::vector<size_t> offset(props);
    for (size_t p = 1; p < props; ++p)
      offset[p] = offset[p - 1] + plyTypeSize(vertex.properties[p - 1].type);
    const bool swap = (h.format == PlyHeader::Format::binary_big_endian) !=
                      (std::endian::native == std::endian::big);
    std::atomic<size_t> firstBad{std::numeric_limits<size_t>::max()};
    const auto* data = reinterpret_cast<const unsigned char*>(bytes.data() + h.bodyOffset);
    parallelFor(
        tbb::blocked_range<size_t>(0, count, 4096), [&](const tbb::blocked_range<size_t>& r) {
          const size_t n = r.size();
          std::vector<double> columns(props * n), v(props);
          for (size_t p = 0; p < props; ++p)
            decodeColumn(vertex.properties[p].type, data + r.begin() * stride + offset[p], stride,
                         swap, n, &columns[p * n]);
          for (size_t j = 0; j < n; ++j) {
            for (size_t p = 0; p < props; ++p) v[p] = columns[p * n + j];
            if (const std::string what = store(out, r.begin() + j, v.data(), l, vertex);
                !what.empty()) {
              size_t seen = firstBad.load();
              while (r.begin() + j < seen && !firstBad.compare_exchange_weak(seen, r.begin() + j)) {
              }
              return;
            }
          }
        });
    if (const size_t bad = firstBad.load(); bad != std::numeric_limits<size_t>::max()) {
      std::vector<double> v(props);
      for (size_t p = 0; p < props; ++p)
        decodeColumn(vertex.properties[p].type, data + bad * stride + offset[p], stride, swap, 1,
                     &v[p]);
      fail(bad, store(out, bad, v.data(), l, vertex));
    }
  }

  // ASCII: one line of exactly the declared values per vertex, whitespace after the last.
  void ascii() const {
    const size_t props = vertex.properties.size();
    size_t at = h.bodyOffset;
    std::vector<double> v(props);
    for (size_t i = 0; i < vertex.count; ++i) {
      if (at >= bytes.size()) fail(i, "missing: the file ends early");
      const size_t eol = std::min(bytes.find('\n', at), bytes.size());
      asciiLine(i, bytes.data() + at, bytes.data() + eol, v);
      at = eol + 1;
      if (const std::string what = store(out, i, v.data(), l, vertex); !what.empty()) fail(i, what);
    }
    for (; at < bytes.size(); ++at)
      if (!std::isspace(static_cast<unsigned char>(bytes[at])))
        throw InputError(path, "body", "data after the last vertex");
  }

  void asciiLine(size_t i, const char* c, const char* end, std::vector<double>& v) const {
    for (size_t p = 0; p < v.size(); ++p) {
      while (c < end && (*c == ' ' || *c == '\t' || *c == '\r')) ++c;
      if (c == end) fail(i, "the line has too few values");
      const char* word = c;
      while (c < end && *c != ' ' && *c != '\t' && *c != '\r') ++c;
      const bool ok =
          parsePlyAscii(std::string_view(word, size_t(c - word)), vertex.properties[p].type, v[p]);
      if (!ok)
        fail(i, vertex.properties[p].name + ": '" +
                    std::string(word, size_t(c - word)).substr(0, 32) +
                    "' is not a valid value of its type");
    }
    while (c < end && (*c == ' ' || *c == '\t' || *c == '\r')) ++c;
    if (c != end) fail(i, "the line has more values than the header declares");
  }
};

}  // namespace

PlyPoints readPlyPoints(const std::string& path) {
  const std::string bytes = readInputFile(path, "", "PLY file");
  const PlyHeader h = readPlyHeader(path, bytes);
  const PlyElement& vertex = pointElement(path, h);
  const Layout l = layoutOf(path, vertex);
  const size_t count = vertex.count;

  // Sizes are checked before anything is allocated: a binary body must be exactly the vertices.
  size_t stride = 0;
  for (const PlyProperty& p : vertex.properties) stride += plyTypeSize(p.type);
  const bool ascii = h.format == PlyHeader::Format::ascii;
  const size_t body = bytes.size() - h.bodyOffset;
  if (!ascii && body != count * stride)
    throw InputError(path, "element vertex",
                     std::to_string(count) + " vertices of " + std::to_string(stride) +
                         " bytes take " + std::to_string(count * stride) + " bytes, the file has " +
                         std::to_string(body) + " after the header");

  PlyPoints out;
  out.positions.resize(count);
  if (l.normal[0] >= 0) out.normals.resize(count);
  if (l.color[0] >= 0) out.colors.resize(count);
  if (l.radius >= 0) out.radii.resize(count);
  const PointReader reader{path, bytes, h, vertex, l, out};
  if (ascii)
    reader.ascii();
  else
    reader.binary(stride);
  return out;
}

void writePointCloudPly(const PointCloud& cloud, const std::string& path) {
  std::ostringstream header;
  header << "ply\nformat binary_little_endian 1.0\ncomment voxgi sample\nelement vertex "
         << cloud.size()
         << "\nproperty double x\nproperty double y\nproperty double z\nproperty float nx\n"
            "property float ny\nproperty float nz\nproperty float red\nproperty float green\n"
            "property float blue\nproperty float radius\nend_header\n";
  constexpr size_t kRecord = 3 * 8 + 7 * 4;
  std::string bytes = header.str();
  const size_t start = bytes.size();
  bytes.resize(start + cloud.size() * kRecord);
  static_assert(std::endian::native == std::endian::little, "writes little-endian PLY natively");
  parallelFor(size_t(0), cloud.size(), [&](size_t i) {
    char* at = bytes.data() + start + i * kRecord;
    const double p[3] = {cloud.positions[i].x, cloud.positions[i].y, cloud.positions[i].z};
    const glm::vec3 l = cloud.colors.empty() ? glm::vec3(0.8f) : cloud.colors[i];
    const glm::vec3 c(linearToSrgb(l.x), linearToSrgb(l.y), linearToSrgb(l.z));
    const float rest[7] = {
        cloud.normals[i].x, cloud.normals[i].y, cloud.normals[i].z, c.x, c.y, c.z, cloud.radii[i]};
    std::memcpy(at, p, sizeof p);
    std::memcpy(at + sizeof p, rest, sizeof rest);
  });
  writeFileAtomically(path, bytes);
}

}  // namespace voxgi

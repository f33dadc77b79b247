#include "shaders/shader_source.h"

#include <regex>

namespace voxgi {

std::string mapShaderLog(const ShaderSource& source, std::string_view log) {
  // Mesa: "0:12(5): error", NVIDIA: "0(12) : error", glslang: "ERROR: 0:12: ...".
  static const std::regex location(R"((\d+)(?::(\d+)|\((\d+)\)))");
  std::string out;
  std::string text(log);
  auto begin = std::sregex_iterator(text.begin(), text.end(), location);
  size_t last = 0;
  for (auto it = begin; it != std::sregex_iterator(); ++it) {
    const std::smatch& m = *it;
    const size_t fileIndex = std::stoul(m[1].str());
    if (fileIndex >= source.files.size()) continue;
    out += text.substr(last, static_cast<size_t>(m.position(0)) - last);
    out += std::string(source.files[fileIndex]) + ":" + (m[2].matched ? m[2].str() : m[3].str());
    last = static_cast<size_t>(m.position(0) + m.length(0));
  }
  out += text.substr(last);
  return out;
}

}  // namespace voxgi

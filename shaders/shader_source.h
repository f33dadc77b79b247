// Embedded GLSL sources: resolved at build time (#include expanded, #line markers inserted).
#pragma once

#include <span>
#include <string>
#include <string_view>

namespace voxgi {

struct ShaderSource {
  std::string_view name;                    // stage file name, e.g. "voxelize.frag"
  std::string_view text;                    // resolved source
  std::span<const std::string_view> files;  // source-string number -> file, for error messages
};

// The embedded shader with this file name; throws std::out_of_range for an unknown name.
const ShaderSource& shaderSource(std::string_view name);

// Rewrites "S:L" / "S(L)" locations in a compiler log to "file:L" using the source's file table.
std::string mapShaderLog(const ShaderSource& source, std::string_view log);

}  // namespace voxgi

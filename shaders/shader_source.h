// Embedded GLSL sources: resolved at build time (#include expanded, #line markers inserted). The
// shaders themselves are declared in the generated shaders/embedded.h.
#pragma once

#include <span>
#include <string>
#include <string_view>

namespace voxgi {

struct ShaderSource {
  std::string_view name;                    // stage file under shaders/, e.g. "vct/mip.comp"
  std::string_view text;                    // resolved source
  std::span<const std::string_view> files;  // source-string number -> file, for error messages
};

// Rewrites "S:L" / "S(L)" locations in a compiler log to "file:L" using the source's file table.
std::string mapShaderLog(const ShaderSource& source, std::string_view log);

}  // namespace voxgi

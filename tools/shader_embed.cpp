// Build-time tool: resolves #include "..." in a GLSL stage file, inserts "#line L S" markers
// (S indexes a file table kept next to the text), validates the result with glslangValidator
// and writes a C++ file defining the ShaderSource. Errors are printed as file:line.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

struct Resolver {
  fs::path includeDir;
  std::vector<std::string> files;
  std::string text;

  void add(const fs::path& path, int depth) {
    if (depth > 16) throw std::runtime_error(path.string() + ": #include nesting deeper than 16");
    std::ifstream in(path);
    if (!in) throw std::runtime_error(path.string() + ": cannot open");
    const int index = static_cast<int>(files.size());
    files.push_back(fs::relative(path, includeDir).string());
    static const std::regex include(R"(^\s*#\s*include\s+"([^"]+)\"\s*$)");
    static const std::regex version(R"(^\s*#\s*version\b)");
    std::string line;
    int number = 0;
    bool needLine = depth > 0;
    while (std::getline(in, line)) {
      ++number;
      std::smatch m;
      if (std::regex_match(line, m, include)) {
        // Like a C preprocessor: next to the including file first, then the include folder.
        const fs::path local = path.parent_path() / m[1].str();
        add(fs::exists(local) ? local : includeDir / m[1].str(), depth + 1);
        needLine = true;
        continue;
      }
      if (needLine) {
        text += "#line " + std::to_string(number) + " " + std::to_string(index) + "\n";
        needLine = false;
      }
      text += line + "\n";
      // After #version the first line marker names file 0 explicitly.
      if (depth == 0 && std::regex_search(line, version)) needLine = true;
    }
  }
};

std::string mapLog(const std::string& log, const std::vector<std::string>& files) {
  static const std::regex location(R"((\d+):(\d+))");
  std::string out;
  size_t last = 0;
  for (auto it = std::sregex_iterator(log.begin(), log.end(), location);
       it != std::sregex_iterator(); ++it) {
    const size_t index = std::stoul((*it)[1].str());
    if (index >= files.size()) continue;
    out += log.substr(last, static_cast<size_t>(it->position(0)) - last);
    out += "shaders/" + files[index] + ":" + (*it)[2].str();
    last = static_cast<size_t>(it->position(0) + it->length(0));
  }
  return out + log.substr(last);
}

std::string cppString(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    if (c == '\n') {
      out += "\\n\"\n\"";
    } else if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

}  // namespace

int main(int argc, char** argv) {
  std::string input, includeDir, output, validator;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i];
    if (key == "--input")
      input = argv[i + 1];
    else if (key == "--include-dir")
      includeDir = argv[i + 1];
    else if (key == "--output")
      output = argv[i + 1];
    else if (key == "--validator")
      validator = argv[i + 1];
  }
  if (input.empty() || includeDir.empty() || output.empty()) {
    std::cerr << "usage: voxgi_shader_embed --input F --include-dir D --output F [--validator V]\n";
    return 2;
  }
  Resolver resolver{fs::path(includeDir), {}, {}};
  try {
    resolver.add(fs::path(input), 0);
  } catch (const std::exception& e) {
    std::cerr << e.what() << "\n";
    return 1;
  }
  // The name is the path under the include folder ("vct/mip.comp"), so stage files of different
  // techniques may share a file name.
  const std::string name = fs::relative(fs::path(input), fs::path(includeDir)).string();
  if (!validator.empty()) {
    // glslangValidator picks the stage from the extension, so keep it on the temporary.
    const fs::path resolved =
        fs::path(output).parent_path() / ("resolved_" + fs::path(input).filename().string());
    fs::create_directories(resolved.parent_path());
    std::ofstream(resolved) << resolver.text;
    const std::string command = validator + " \"" + resolved.string() + "\" 2>&1";
    FILE* pipe = popen(command.c_str(), "r");
    std::string log;
    char buffer[4096];
    while (pipe && fgets(buffer, sizeof buffer, pipe)) log += buffer;
    const int status = pipe ? pclose(pipe) : -1;
    if (status != 0) {
      std::cerr << "glslangValidator rejected " << name << ":\n" << mapLog(log, resolver.files);
      return 1;
    }
  }
  std::string ident = name;
  for (char& c : ident)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  std::ostringstream cpp;
  cpp << "// Generated from shaders/" << name << " by voxgi_shader_embed. Do not edit.\n"
      << "#include \"shaders/shader_source.h\"\n#include <array>\n"
      << "namespace voxgi::shaders {\n"
      << "static const std::array<std::string_view, " << resolver.files.size() << "> " << ident
      << "_files{";
  for (const auto& f : resolver.files) cpp << cppString(f) << ", ";
  cpp << "};\nextern const ShaderSource " << ident << ";\n"
      << "const ShaderSource " << ident << "{" << cppString(name) << ",\n"
      << cppString(resolver.text) << ",\n"
      << ident << "_files};\n}\n";
  fs::create_directories(fs::path(output).parent_path());
  std::ofstream(output) << cpp.str();
  return 0;
}

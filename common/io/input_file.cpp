#include "common/io/input_file.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>

#include "common/error.h"

namespace voxgi {

uint64_t requireInputFile(const std::string& path, const std::string& field,
                          const std::string& what) {
  if (path.empty()) throw InputError("(empty path)", field, "no " + what + " given");
  if (path.find('\0') != std::string::npos)
    throw InputError(path.substr(0, path.find('\0')), field, "the file name contains a NUL byte");
  struct stat st {};
  if (stat(path.c_str(), &st) != 0)
    throw InputError(
        path, field,
        errno == ENOENT ? "no such " + what : "cannot open " + what + ": " + std::strerror(errno));
  if (S_ISDIR(st.st_mode)) throw InputError(path, field, "is a folder, not a " + what);
  if (!S_ISREG(st.st_mode)) throw InputError(path, field, "is not a regular file (" + what + ")");
  if (access(path.c_str(), R_OK) != 0)
    throw InputError(path, field, "cannot open " + what + ": " + std::strerror(errno));
  return static_cast<uint64_t>(st.st_size);
}

std::string readInputFile(const std::string& path, const std::string& field,
                          const std::string& what) {
  const uint64_t size = requireInputFile(path, field, what);
  std::ifstream in(path, std::ios::binary);
  std::string bytes(size, '\0');
  if (!in.read(bytes.data(), std::streamsize(size)) || in.gcount() != std::streamsize(size))
    throw InputError(path, field, "cannot read " + what + " (it changed while being read)");
  return bytes;
}

}  // namespace voxgi

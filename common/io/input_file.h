// Checks on every file voxgi reads, before a loader opens it: one line naming the file that says
// what is wrong with it (absent, a folder, a device, a symbolic-link loop, a name too long, a NUL
// in the name), instead of a library's message or a crash.
#pragma once

#include <cstdint>
#include <string>

namespace voxgi {

// Throws InputError(path, field, reason) unless `path` names a readable regular file; returns its
// size in bytes. `what` says what the file is for ("scene file", "mesh file").
uint64_t requireInputFile(const std::string& path, const std::string& field,
                          const std::string& what);

// requireInputFile, then the whole file in one read.
std::string readInputFile(const std::string& path, const std::string& field,
                          const std::string& what);

}  // namespace voxgi

// Every file voxgi writes goes through here, so that an output is either complete or absent: the
// bytes go to a unique temporary file next to the target, every write, the fsync and the close are
// checked, and only then is the temporary renamed over the target. A failure (a full disk, a
// missing folder) throws InputError naming the file and removes the temporary; the previous file,
// if any, is untouched. A target that is a symbolic link or not a regular file is refused. SIGINT
// and SIGTERM during a write are held until the temporary is renamed or removed.
#pragma once

#include <string>
#include <string_view>

namespace voxgi {

// Checks that `path` can be written: its folder exists and is writable, and the path is absent or
// a regular file (not a symbolic link, folder or device). Commands call it for every output before
// their heavy work; writeFileAtomically checks again. Throws InputError naming `path`.
void checkOutputPath(const std::string& path);

// Writes `bytes` to `path` as described above.
void writeFileAtomically(const std::string& path, std::string_view bytes);

// Checks that `dir` is a folder voxgi can write into, creating it (and its parents) if absent;
// throws InputError naming it otherwise.
void prepareOutputFolder(const std::string& dir);

}  // namespace voxgi

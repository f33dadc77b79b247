// A check of an OpenEXR file's header before OpenEXR reads it: OpenEXR allocates the size each
// header attribute declares before it reads the value, so a 100-byte file can make it allocate
// 2 GB. Every attribute must fit in the file, names must be terminated within the format's limit,
// and only single-part flat images (scanline or tiled) are accepted, which is what voxgi reads
// (references, masks, compare's inputs). Throws InputError naming the file and the field.
#pragma once

#include <string>

namespace voxgi {

void checkExrHeader(const std::string& path);

}  // namespace voxgi

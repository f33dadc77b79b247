// tinygltf (Debian's libtinygltf-dev) as voxgi builds it: its implementation is compiled into
// voxgi (common/scene_io/tinygltf.cpp) rather than linked from Debian's shared library, whose
// structures are laid out for other build settings than a program including the header gets
// (reading a model through it corrupted the heap). No stb_image and no external images (voxgi
// reads no textures yet), and no default file access (voxgi's own, which never expands a path).
// Include this, never <tiny_gltf.h>, so that every user sees the same settings.
#pragma once

#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_FS
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>

// Must not compile (tests/CMakeLists.txt): the GL entry point list without VOXGI_GL.
#include "gpu/gl_functions.inc"

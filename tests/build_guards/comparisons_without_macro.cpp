// Must not compile (tests/CMakeLists.txt): the comparison list without VOXGI_COMPARISON.
#include "validation/comparisons.inc"

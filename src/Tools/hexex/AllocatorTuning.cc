/// @file AllocatorTuning.cc
/// glibc mallopt() call behind HexExTool::keepLargeBlocksOnHeap().

#include "AllocatorTuning.hh"

#include <cstdlib> // defines __GLIBC__ on glibc

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace HexExTool {

void keepLargeBlocksOnHeap() {
#if defined(__GLIBC__)
    // 1 GiB: blocks above it (beyond any stage's array on the maps we measure) still get
    // their own mapping. Setting the threshold also stops glibc's own adaptation of it.
    mallopt(M_MMAP_THRESHOLD, 1 << 30);
#endif
}

} // namespace HexExTool

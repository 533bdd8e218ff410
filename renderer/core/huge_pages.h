// Large host allocations on 2 MiB pages (Linux transparent huge pages, asked for per range). Reading, building and
// uploading a million-triangle OBJ scene took 116 000 page faults on 4 KiB pages and 22 000 with its large arrays on
// 2 MiB pages, 1.7 s against 1.0 s on this 2-core VM (README). Embree asks the same for its BVH memory.
#pragma once

#include <cstddef>

namespace trazo {

constexpr std::size_t kHugePageBytes = std::size_t(2) << 20;

// The replaced global operator new (huge_pages.cpp) advises every allocation of at least this many bytes: the
// arrays of large meshes, their BVHs and the OBJ reader's, wherever they are made. Smaller ones hold no whole
// 2 MiB page often enough to matter.
constexpr std::size_t kHugePageAdviceBytes = 2 * kHugePageBytes;

// Asks the kernel to back the whole 2 MiB pages inside [data, data + bytes) with huge pages when they are first
// touched (madvise MADV_HUGEPAGE; memory already touched keeps its pages). Returns whether it asked: false off
// Linux, for a range that holds no whole 2 MiB page, or where the kernel refused. Where THP is off system-wide
// the kernel accepts the advice and ignores it.
bool adviseHugePages(void* data, std::size_t bytes);

// What a fresh allocation gets (operator new, the OBJ reader's mmap'd arrays): the advice where it holds at least
// kHugePageAdviceBytes, before anything touches it.
inline void adviseLargeAllocation(void* data, std::size_t bytes) {
    if (bytes >= kHugePageAdviceBytes) adviseHugePages(data, bytes);
}

}  // namespace trazo

#include "core/huge_pages.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace trazo {

bool adviseHugePages(void* data, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    constexpr std::uintptr_t kHugePage = kHugePageBytes;
    const std::uintptr_t begin = reinterpret_cast<std::uintptr_t>(data);
    const std::uintptr_t first = (begin + kHugePage - 1) & ~(kHugePage - 1);
    const std::uintptr_t last = (begin + bytes) & ~(kHugePage - 1);
    if (bytes < kHugePage || begin + bytes < begin || last <= first) return false;
    return madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE) == 0;
#else
    (void)data, (void)bytes;
    return false;
#endif
}

}  // namespace trazo

// Every program linking the renderer takes these two operator new (the library member defining them is linked
// where new is used, ahead of libstdc++'s): malloc or aligned_alloc, as libstdc++'s, and then the advice for large
// blocks, before anything touches them. libstdc++'s array and nothrow forms call these, and its deletes free. Not
// under AddressSanitizer, whose own operator new tracks allocations; valgrind's memcheck replaces these too with
// --soname-synonyms=somalloc=NONE (else it reports each delete of them as mismatched with malloc).
#if !defined(__SANITIZE_ADDRESS__)
namespace {

template <class Allocate>
void* allocateAdvised(std::size_t bytes, Allocate&& allocate) {
    for (;;) {
        if (void* p = allocate()) {
            trazo::adviseLargeAllocation(p, bytes);
            return p;
        }
        std::new_handler handler = std::get_new_handler();
        if (!handler) throw std::bad_alloc();
        handler();
    }
}

}  // namespace

void* operator new(std::size_t bytes) {
    return allocateAdvised(bytes, [&] { return std::malloc(bytes ? bytes : 1); });
}

// Over-aligned types (the BVH nodes, alignas(128)).
void* operator new(std::size_t bytes, std::align_val_t alignment) {
    const std::size_t align = std::max(static_cast<std::size_t>(alignment), sizeof(void*));
    const std::size_t rounded = (std::max<std::size_t>(bytes, 1) + align - 1) & ~(align - 1);  // aligned_alloc's rule
    if (rounded < bytes) throw std::bad_alloc();
    return allocateAdvised(bytes, [&] { return std::aligned_alloc(align, rounded); });
}
#endif

// Tests of the huge-page advice (host, Linux): which pages adviseHugePages marks, read back from the kernel's own
// account of the process's mappings (/proc/self/smaps, "hg" in VmFlags), and that large `new` blocks carry it
// (small ones may share a mapping another block's advice marked, so nothing is asserted of them).
#include "core/huge_pages.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "accel/wide_bvh_node.h"

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace trazo {
namespace {

#if defined(__linux__)
constexpr std::uintptr_t kHugePage = kHugePageBytes;

// The VmFlags of the mapping holding `address` ("" if none does).
std::string vmFlagsAt(const void* address) {
    const std::uintptr_t a = reinterpret_cast<std::uintptr_t>(address);
    std::ifstream smaps("/proc/self/smaps");
    std::string line;
    bool inside = false;
    while (std::getline(smaps, line)) {
        std::uintptr_t begin = 0, end = 0;
        char dash = 0;
        std::istringstream header(line);
        if (header >> std::hex >> begin >> dash >> end && dash == '-' && line.find(':') > line.find(' ')) {
            inside = begin <= a && a < end;
        } else if (inside && line.rfind("VmFlags:", 0) == 0) {
            return line.substr(8) + " ";
        }
    }
    return "";
}
bool advised(const void* address) { return vmFlagsAt(address).find(" hg ") != std::string::npos; }

// At least 8 MiB of fresh anonymous memory from `base`, 2 MiB-aligned, unmapped at the end.
struct Mapping {
    char* raw = nullptr;
    char* base = nullptr;
    Mapping() {
        void* p = mmap(nullptr, 5 * kHugePage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
        if (p == MAP_FAILED) return;
        raw = static_cast<char*>(p);
        base = reinterpret_cast<char*>((reinterpret_cast<std::uintptr_t>(p) + kHugePage - 1) & ~(kHugePage - 1));
    }
    ~Mapping() {
        if (raw) munmap(raw, 5 * kHugePage);
    }
};

TEST(HugePages, AdviceCoversExactlyTheWholeHugePagesInsideTheRange) {
    Mapping m;
    ASSERT_NE(m.base, nullptr);
    // [base + 1, base + 3 pages + 1): only the second and third 2 MiB pages lie wholly inside.
    if (!adviseHugePages(m.base + 1, 3 * kHugePage)) GTEST_SKIP() << "this kernel has no transparent huge pages";
    EXPECT_FALSE(advised(m.base));
    EXPECT_FALSE(advised(m.base + kHugePage - 1));
    EXPECT_TRUE(advised(m.base + kHugePage));
    EXPECT_TRUE(advised(m.base + 3 * kHugePage - 1));
    EXPECT_FALSE(advised(m.base + 3 * kHugePage));
}

TEST(HugePages, RangesWithoutAWholeHugePageAreNotAdvised) {
    Mapping m;
    ASSERT_NE(m.base, nullptr);
    EXPECT_FALSE(adviseHugePages(m.base, kHugePage - 1));
    EXPECT_FALSE(adviseHugePages(m.base + 1, 2 * kHugePage - 2));  // spans two pages, holds neither whole
    EXPECT_FALSE(adviseHugePages(m.base, 0));
    EXPECT_FALSE(advised(m.base + kHugePage));
}

#if !defined(__SANITIZE_ADDRESS__)
TEST(HugePages, LargeNewBlocksAreAdvised) {
    {
        Mapping probe;
        ASSERT_NE(probe.base, nullptr);
        if (!adviseHugePages(probe.base, 2 * kHugePage)) GTEST_SKIP() << "this kernel has no transparent huge pages";
    }
    std::vector<float> large(kHugePageAdviceBytes / sizeof(float) + 1);
    EXPECT_TRUE(advised(large.data() + large.size() / 2));
    std::vector<WideBvhNode> nodes(kHugePageAdviceBytes / sizeof(WideBvhNode) + 1);  // over-aligned: aligned new
    EXPECT_TRUE(advised(nodes.data() + nodes.size() / 2));
}
#endif

#endif  // __linux__

}  // namespace
}  // namespace trazo

// Tests (host) of the CPU backend's per-ISA kernels: every shipped scene renders bit for bit alike on every
// path this CPU runs (TRAZO_CPU_ISA forces one), and the environment variable chooses as documented.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "backends/cpu/cpu_kernels.h"
#include "fetched_assets.h"
#include "render_harness.h"
#include "test_paths.h"

namespace trazo {
namespace {

// Sets TRAZO_CPU_ISA for the scope, and restores what was there.
class ForcedIsa {
public:
    explicit ForcedIsa(const char* value) {
        if (const char* old = std::getenv("TRAZO_CPU_ISA")) old_ = old, hadOld_ = true;
        if (value) setenv("TRAZO_CPU_ISA", value, 1);
        else unsetenv("TRAZO_CPU_ISA");
    }
    ~ForcedIsa() {
        if (hadOld_) setenv("TRAZO_CPU_ISA", old_.c_str(), 1);
        else unsetenv("TRAZO_CPU_ISA");
    }

private:
    std::string old_;
    bool hadOld_ = false;
};

std::vector<CpuIsa> supportedIsas() {
    std::vector<CpuIsa> isas;
    for (CpuIsa isa : kCpuIsas) {
        if (cpuIsaSupported(isa)) isas.push_back(isa);
        else std::printf("cpu_isa: %s skipped: this CPU (or build) lacks it\n", cpuIsaName(isa));
    }
    return isas;
}

TEST(CpuIsa, EnvironmentChoosesThePath) {
    for (CpuIsa isa : supportedIsas()) {
        const ForcedIsa forced(cpuIsaName(isa));
        EXPECT_EQ(selectCpuKernels().isa, isa);
        EXPECT_EQ(cpuKernelsFor(isa)->isa, isa);
    }
    CpuIsa widest = CpuIsa::Sse2;
    for (CpuIsa isa : supportedIsas()) widest = isa;
    const ForcedIsa none(nullptr);
    EXPECT_EQ(selectCpuKernels().isa, widest);
    const ForcedIsa unknown("mmx");
    EXPECT_EQ(selectCpuKernels().isa, widest);  // with a warning
}

// All shipped scenes, small, two passes with the whole strata grids (every area-light cell at each point: the
// packets' largest blocks), on each path against the baseline.
TEST(CpuIsa, EveryPathRendersEveryShippedSceneAlike) {
    const std::vector<CpuIsa> isas = supportedIsas();
    if (isas.size() < 2) GTEST_SKIP() << "this CPU runs only the baseline path";
    int scenes = 0;
    for (const auto& entry : std::filesystem::directory_iterator(test::sourcePath("scenes"))) {
        if (entry.path().extension() != ".scene") continue;
        const std::string path = entry.path().string();
        if (!test::absentFetchedAsset(path).empty()) {
            std::printf("cpu_isa: %s skipped: %s\n", path.c_str(), test::absentFetchedAsset(path).c_str());
            continue;
        }
        ++scenes;
        test::RenderRequest request;
        request.passes = 2;
        request.seed = 7;
        request.width = 40;
        request.height = 30;
        request.blocks = StrataBlocks::whole();
        test::RenderedImage reference;
        {
            const ForcedIsa forced("sse2");
            reference = test::renderSceneFile(path, request);
        }
        ASSERT_EQ(reference.pixels.size(), 40u * 30u) << path;
        for (CpuIsa isa : isas) {
            if (isa == CpuIsa::Sse2) continue;
            const ForcedIsa forced(cpuIsaName(isa));
            const test::RenderedImage image = test::renderSceneFile(path, request);
            ASSERT_EQ(image.pixels.size(), reference.pixels.size());
            EXPECT_EQ(image.rays, reference.rays) << path << " on " << cpuIsaName(isa);
            EXPECT_EQ(std::memcmp(image.pixels.data(), reference.pixels.data(), image.pixels.size() * sizeof(Vec3)), 0)
                << path << " differs on " << cpuIsaName(isa);
        }
    }
    EXPECT_GT(scenes, 10);
}

}  // namespace
}  // namespace trazo

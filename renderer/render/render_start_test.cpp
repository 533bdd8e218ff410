// Tests of the start of a render's report: the backend's line and the refusal of CUDA where there is none, as the
// CLI and the viewer both print them.
#include "render/render_start.h"

#include <gtest/gtest.h>

namespace trazo {
namespace {

TEST(RenderStart, DescribesTheBackendAndWhyCudaWasNotUsed) {
    std::string fallback = "stale";
    const std::unique_ptr<Backend> cpu = openBackend(BackendChoice::Cpu, 2, nullptr, fallback);
    ASSERT_TRUE(cpu);
    EXPECT_EQ(fallback, "");
    EXPECT_EQ(describeBackend(*cpu, fallback), "cpu (2 CPU threads)");
    EXPECT_EQ(describeBackend(*cpu, "no CUDA device: none"),
              "cpu (2 CPU threads); CUDA not used: no CUDA device: none");
}

TEST(RenderStart, CudaWithoutADeviceIsRefusedWithItsReason) {
    std::string device;
    if (cudaDeviceAvailable(device)) GTEST_SKIP() << "a CUDA device is present: " << device;
    std::string fallback;
    testing::internal::CaptureStderr();
    const std::unique_ptr<Backend> backend = openBackend(BackendChoice::Cuda, 1, nullptr, fallback);
    const std::string printed = testing::internal::GetCapturedStderr();
    EXPECT_FALSE(backend);
    ASSERT_FALSE(fallback.empty());
    EXPECT_EQ(printed, "trazo: cannot use the CUDA backend: " + fallback + "\n");

    testing::internal::CaptureStderr();
    const std::unique_ptr<Backend> automatic = openBackend(BackendChoice::Auto, 1, nullptr, fallback);
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
    ASSERT_TRUE(automatic);
    EXPECT_EQ(automatic->name(), "cpu");
    EXPECT_FALSE(fallback.empty());
}

}  // namespace
}  // namespace trazo

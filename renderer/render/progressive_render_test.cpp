// Unit tests of the progressive render's target-error stop, on a backend whose "render" draws known random
// values (fake_backend.h).
#include "render/progressive_render.h"

#include <gtest/gtest.h>

#include "render/fake_backend.h"

namespace trazo {
namespace {

using test::FakeBackend;

TEST(ProgressiveRender, TargetErrorStopsNearTheTarget) {
    constexpr uint32_t kStrata = 12;
    FakeBackend backend(4000, kStrata, 0.5f);
    RenderLimits limits;
    limits.passes = kMaxProgressivePasses;
    limits.cyclePasses = kStrata;
    limits.targetError = 0.01;
    const RenderOutcome out = renderProgressive(backend, FrameParams{}, limits);
    EXPECT_TRUE(out.reachedTarget);
    EXPECT_EQ(out.passes % (2 * kStrata), 0u) << "checked only where the halves are balanced";
    EXPECT_LE(out.estimatedRelError, limits.targetError);
    EXPECT_GT(backend.trueRelError(), 0.6 * limits.targetError) << out.passes << " passes: stopped too late";
    EXPECT_LT(backend.trueRelError(), 1.25 * limits.targetError) << out.passes << " passes";
    EXPECT_LE(out.errorChecks, 12u);

    // The pass limit still bounds it.
    backend.reset();
    limits.passes = 48;
    const RenderOutcome capped = renderProgressive(backend, FrameParams{}, limits);
    EXPECT_EQ(capped.passes, 48u);
    EXPECT_FALSE(capped.reachedTarget);
}

}  // namespace
}  // namespace trazo

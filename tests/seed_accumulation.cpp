// Seed-scene accumulations (reader, flatten, the CLI's blocks and cycle) and the merge-bound comparison.
#include "seed_accumulation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "flatten/flatten.h"
#include "render/frame_setup.h"
#include "render/merge.h"
#include "render/progressive_render.h"
#include "scene/scene_reader.h"
#include "test_paths.h"

namespace trazo::test {

std::vector<AccumPixel> renderSeedAccumulation(Backend& backend, const std::string& sceneName, uint32_t width,
                                               uint32_t height, const std::vector<PassRange>& batches) {
    Diagnostics diags;
    const Scene scene = readSceneFile(sourcePath("scenes/" + sceneName), diags);
    EXPECT_FALSE(diags.hasErrors()) << sceneName;
    FlattenResult flat = flatten(scene);
    const StrataBlocks blocks = headlessBlocks(flat.arrays);
    const uint32_t cycle = fullCyclePasses(flat.arrays, blocks);
    backend.upload(flat.arrays);
    backend.resize(width, height);
    const FrameParams frame = makeFrameParams(scene, width, height, 0, blocks);
    for (const PassRange& range : batches) renderPassRange(backend, frame, range.first, range.count(), cycle);
    std::vector<AccumPixel> accum;
    backend.readAccumulation(accum);
    return accum;
}

namespace {

// Distance in floats between two finite floats of the same sign (the image is non-negative).
uint32_t ulpDistance(float a, float b) {
    uint32_t ia, ib;
    std::memcpy(&ia, &a, 4);
    std::memcpy(&ib, &b, 4);
    return ia > ib ? ia - ib : ib - ia;
}

}  // namespace

MergeComparison expectWithinMergeBound(const std::vector<AccumPixel>& a, const std::vector<AccumPixel>& b,
                                       uint32_t passes) {
    MergeComparison c;
    c.pixels = a.size();
    EXPECT_EQ(a.size(), b.size());
    if (a.size() != b.size()) return c;
    const double bound = mergeRelativeBound(passes);
    size_t failures = 0;
    for (size_t i = 0; i < a.size(); ++i) {
        const AccumPixel& p = a[i];
        const AccumPixel& q = b[i];
        bool ok = p.count == q.count && p.countB == q.countB && p.count == passes;
        for (int ch = 0; ch < 3; ++ch)
            for (const auto& [x, y] : {std::pair{p.sum[ch], q.sum[ch]}, std::pair{p.sumB[ch], q.sumB[ch]}}) {
                ok = ok && x >= 0 && y >= 0;  // the bound is for non-negative samples
                const double scale = std::max(x, y);
                const double relative = scale > 0 ? std::abs(x - y) / scale : 0.0;
                c.largestRelative = std::max(c.largestRelative, relative);
                ok = ok && relative <= bound;
            }
        const Vec3 e = p.estimate(), f = q.estimate();
        for (int ch = 0; ch < 3; ++ch) ok = ok && ulpDistance(e[ch], f[ch]) <= 1;
        c.identicalPixels += std::memcmp(&p, &q, sizeof p) == 0;
        c.identicalFloats += std::memcmp(&e, &f, sizeof e) == 0;
        if (!ok && ++failures <= 5)
            ADD_FAILURE() << "pixel " << i << ": counts " << p.count << "/" << q.count << ", " << p.countB << "/"
                          << q.countB << " (expected " << passes << "); sums " << p.sum[0] << " " << q.sum[0]
                          << "; bound " << bound;
    }
    EXPECT_EQ(failures, 0u);
    return c;
}

}  // namespace trazo::test

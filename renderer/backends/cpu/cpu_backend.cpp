// CPU backend: every pass runs renderSample over the image in 16×16 tiles on the backend's thread pool (ray
// queries: chunks of rays on the same threads), through the kernels of the CPU's widest instruction set
// (cpu_kernels.h).
// Each pixel's sum depends only on (pixel, passes), never on which thread ran it.
#include <algorithm>
#include <atomic>
#include <chrono>

#include "backends/backend.h"
#include "backends/cpu/cpu_kernels.h"
#include "core/thread_pool.h"
#include "flatten/flatten_mesh.h"

namespace trazo {

namespace {

constexpr uint32_t kTileSize = 16;

class CpuBackend final : public Backend {
public:
    explicit CpuBackend(unsigned threads) : pool_(threads), kernels_(selectCpuKernels()) {}

    std::string name() const override { return "cpu"; }
    std::string deviceName() const override { return std::to_string(pool_.threadCount()) + " CPU threads"; }

    void upload(const SceneArrays& arrays) override {
        arrays_ = arrays;
        makeView(true);
    }
    void upload(const SceneArrays& arrays, ArrayMask changed) override {
#define TRAZO_X(T, name, ...) \
    if (changed & maskOf(SceneArray::name)) arrays_.name = arrays.name;
        TRAZO_SCENE_ARRAYS(TRAZO_X)
#undef TRAZO_X
        if (changed & maskOf(SceneArray::values)) {
            arrays_.settings = arrays.settings;
            arrays_.features = arrays.features;
            arrays_.traversalStackNeed = arrays.traversalStackNeed;
        }
        makeView((changed & (maskOf(SceneArray::meshes) | maskOf(SceneArray::meshNodes))) != 0);
    }
    void uploadMoved(SceneArrays&& arrays) override {
        arrays_ = std::move(arrays);
        makeView(true);
    }
    void resize(uint32_t width, uint32_t height) override {
        width_ = width;
        height_ = height;
        accum_.assign((size_t)width * height, AccumPixel{});
        probePixels_.clear();  // its pixels were the old image's
        probe_.clear();
        rays_ = 0;
    }
    void reset() override {
        std::fill(accum_.begin(), accum_.end(), AccumPixel{});
        std::fill(probe_.begin(), probe_.end(), AccumPixel{});
        rays_ = 0;
    }
    bool hasProbe() const override { return true; }
    void resizeProbe(const std::vector<uint32_t>& pixels) override {
        checkProbePixels(pixels, width_, height_);
        probePixels_ = pixels;
        probe_.assign((pixels.size() + kProbeRow - 1) / kProbeRow * kProbeRow, AccumPixel{});
    }
    void readProbe(std::vector<AccumPixel>& out) override {
        out.assign(probe_.begin(), probe_.begin() + (ptrdiff_t)probePixels_.size());
    }
    void writeProbe(const std::vector<AccumPixel>& accum) override {
        checkProbeAccumulation(accum, probePixels_.size());
        std::copy(accum.begin(), accum.end(), probe_.begin());
    }

    void renderPasses(const FrameParams& target, uint32_t firstPass, uint32_t passCount) override {
        const FrameParams frame =
            boundFrame(target, width_, height_, probePixels_.data(), (uint32_t)probePixels_.size());
        const uint32_t width = frame.accumWidth(), height = frame.accumHeight();
        AccumPixel* const accum = frame.target.probe ? probe_.data() : accum_.data();
        const uint32_t tilesX = (width + kTileSize - 1) / kTileSize;
        const uint32_t tilesY = (height + kTileSize - 1) / kTileSize;
        const uint32_t tileCount = tilesX * tilesY;
        std::atomic<uint64_t> rays{0};
        const uint32_t variant = sampleVariantFor(view_.settings.integrator, view_.features);
        const CameraPacketKernels& packets = kernels_.cameraPackets();
        const bool inPackets = packets.available && packets.renderTile[variant] && cameraPacketsApply(view_);
        const TileRenderFn renderTile = inPackets ? packets.renderTile[variant] : kernels_.renderTile[variant];
        pool_.parallelFor(tileCount, 1, [&](size_t tile, size_t) {
            const uint32_t x0 = (uint32_t(tile) % tilesX) * kTileSize, y0 = (uint32_t(tile) / tilesX) * kTileSize;
            const Tile t{x0, y0, std::min(x0 + kTileSize, width), std::min(y0 + kTileSize, height)};
            rays.fetch_add(renderTile(view_, frame, t, firstPass, passCount, accum), std::memory_order_relaxed);
        });
        rays_ += rays.load();
    }

    void readAccumulation(std::vector<AccumPixel>& out) override { out = accum_; }
    const std::vector<AccumPixel>* hostAccumulation() const override { return &accum_; }
    uint64_t raysTraced() const override { return rays_; }

    using Backend::traceRays;
    double traceRays(const std::vector<RayQuery>& queries, RayQueryKind kind, std::vector<RayAnswer>& out) override {
        out.resize(queries.size());
        constexpr size_t kChunk = 4096;
        const auto start = std::chrono::steady_clock::now();
        pool_.parallelFor(queries.size(), kChunk, [&](size_t begin, size_t end) {
            kernels_.answerRayQueries(view_, queries.data() + begin, end - begin, kind, out.data() + begin);
        });
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }

private:
    // The kernels' view of arrays_; where they are AVX2 or AVX-512 ones, with the meshes' eight-wide BVHs and
    // leaf blocks, made again when the meshes changed (widenMeshBvhs: 60 ms and 57 MB for a million triangles in
    // the memory of the last upload, against 0.4 s for their BVH; build/bench/bvh/bvh_bench).
    void makeView(bool meshesChanged) {
        if (meshesChanged && kernels_.isa != CpuIsa::Sse2) widenMeshBvhs(arrays_, meshes8_);
        view_ = hostView(arrays_);
        viewEightWide(view_, meshes8_);
    }

    ThreadPool pool_;  // started with the backend, for every pass it renders
    const CpuKernels& kernels_;
    SceneArrays arrays_;
    EightWideMeshes meshes8_;
    SceneView view_{};
    uint32_t width_ = 0, height_ = 0;
    std::vector<AccumPixel> accum_;
    std::vector<uint32_t> probePixels_;
    std::vector<AccumPixel> probe_;  // kProbeRow pixels a row, the last padded
    uint64_t rays_ = 0;
};

}  // namespace

std::unique_ptr<Backend> createCpuBackend(unsigned threads) { return std::make_unique<CpuBackend>(threads); }

}  // namespace trazo

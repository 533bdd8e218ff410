// CUDA backend: the same renderSample() as the CPU backend, one thread per pixel, one launch per pass (ray
// queries: one thread per ray).
#include <cuda_runtime.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

#include "backends/backend.h"
#include "backends/cuda/render_pass_launch.h"

namespace trazo {

// The viewer's CUDA-GL interop (cuda_gl_display.cu).
class CudaGlDisplay;
CudaGlDisplay* createCudaGlDisplay();
void destroyCudaGlDisplay(CudaGlDisplay* display);
void releaseCudaGlDisplay(CudaGlDisplay& display);
bool resolveIntoGlBuffer(CudaGlDisplay& display, unsigned glBuffer, const AccumPixel* accum, uint32_t width,
                         uint32_t height, std::string& why);

namespace {

// Throws with the failing call's file:line; Backend methods turn it into a runtime failure (exit 1).
#define TRAZO_CUDA_CHECK(call)                                                                         \
    do {                                                                                               \
        const cudaError_t status_ = (call);                                                            \
        if (status_ != cudaSuccess)                                                                    \
            throw std::runtime_error(std::string(__FILE__) + ":" + std::to_string(__LINE__) + ": " + \
                                     #call + ": " + cudaGetErrorString(status_));                      \
    } while (0)

__global__ void rayQueryKernel(SceneView scene, const RayQuery* queries, uint32_t count, RayQueryKind kind,
                                RayAnswer* out) {
    const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i < count) out[i] = answerRayQuery(scene, queries[i], kind);
}

template <IntegratorKind K, FeatureMask F>
struct LaunchVariant {
    static constexpr auto value = &launchRenderPass<K, F>;
};
const auto kLaunchVariants = makeVariantTable<LaunchVariant>();

template <typename T>
class DeviceArray {
public:
    DeviceArray() = default;
    DeviceArray(const DeviceArray&) = delete;
    DeviceArray& operator=(const DeviceArray&) = delete;
    ~DeviceArray() { cudaFree(data_); }

    // Copies `host` to the device unless it equals what was copied last time.
    void assign(const std::vector<T>& host) {
        if (known_ && host.size() == shadow_.size() &&
            (host.empty() || std::memcmp(host.data(), shadow_.data(), host.size() * sizeof(T)) == 0))
            return;
        reserve(host.size());
        count_ = host.size();
        if (count_) TRAZO_CUDA_CHECK(cudaMemcpy(data_, host.data(), count_ * sizeof(T), cudaMemcpyHostToDevice));
        shadow_ = host;
        known_ = true;
    }
    // Room for `count` elements the device will write (an output): nothing is copied, and the contents are
    // no longer known here, so the next assign() copies whatever it is given.
    void resizeForOutput(size_t count) {
        reserve(count);
        count_ = count;
        shadow_.clear();
        known_ = false;
    }
    ArrayView<T> view() const { return ArrayView<T>{data_, (uint32_t)count_}; }
    T* data() const { return data_; }

private:
    // The new block first: if it cannot be had, the array (and every view of it) keeps the old one.
    void reserve(size_t count) {
        if (count <= capacity_) return;
        T* fresh = nullptr;
        TRAZO_CUDA_CHECK(cudaMalloc(&fresh, count * sizeof(T)));
        cudaFree(data_);
        data_ = fresh;
        capacity_ = count;
    }

    T* data_ = nullptr;
    size_t count_ = 0, capacity_ = 0;
    std::vector<T> shadow_;  // host copy of the device contents, when known_
    bool known_ = true;
};

// A pair of CUDA events for timing a launch.
struct EventTimer {
    cudaEvent_t start = nullptr, stop = nullptr;
    EventTimer() {
        TRAZO_CUDA_CHECK(cudaEventCreate(&start));
        TRAZO_CUDA_CHECK(cudaEventCreate(&stop));
    }
    ~EventTimer() {
        cudaEventDestroy(start);
        cudaEventDestroy(stop);
    }
    EventTimer(const EventTimer&) = delete;
    EventTimer& operator=(const EventTimer&) = delete;
};

// TRAZO_CUDA_SYNC_EVERY_PASS=1: wait for each pass, so a kernel fault names its pass instead of the batch's.
bool syncEveryPass() {
    const char* value = std::getenv("TRAZO_CUDA_SYNC_EVERY_PASS");
    return value && *value && std::strcmp(value, "0") != 0;
}

// A failed launch or wait of passes [first, end): which passes, and what the device said.
void checkPasses(cudaError_t status, uint32_t first, uint32_t end) {
    if (status == cudaSuccess) return;
    throw std::runtime_error("CUDA fault in passes [" + std::to_string(first) + ", " + std::to_string(end) +
                             "): " + cudaGetErrorString(status) +
                             (end - first > 1 ? " (TRAZO_CUDA_SYNC_EVERY_PASS=1 names the pass)" : ""));
}

class CudaBackend final : public Backend {
public:
    // Every call first makes `device` current on its thread: a MultiBackend drives each device from its own.
    explicit CudaBackend(int device) : deviceIndex_(device) {
        useDevice();
        cudaDeviceProp prop{};
        TRAZO_CUDA_CHECK(cudaGetDeviceProperties(&prop, deviceIndex_));
        deviceName_ = prop.name;
        // A binary without code for this device fails here, where `auto` can still take the CPU, rather than
        // at the first launch.
        cudaFuncAttributes attributes{};
        const cudaError_t image = cudaFuncGetAttributes(&attributes, rayQueryKernel);
        if (image != cudaSuccess) {
            cudaGetLastError();
            throw std::runtime_error("this trazo has no kernels for " + deviceName_ + " (compute capability " +
                                     std::to_string(prop.major) + "." + std::to_string(prop.minor) +
                                     "): rebuild with -DCMAKE_CUDA_ARCHITECTURES=" + std::to_string(prop.major) +
                                     std::to_string(prop.minor) + " (" + cudaGetErrorString(image) + ")");
        }
        syncEveryPass_ = syncEveryPass();
        TRAZO_CUDA_CHECK(cudaMalloc(&rayCounter_, sizeof(unsigned long long)));
        TRAZO_CUDA_CHECK(cudaMemset(rayCounter_, 0, sizeof(unsigned long long)));
    }
    ~CudaBackend() override {
        cudaSetDevice(deviceIndex_);  // the members' device arrays are freed after this body, on this device
        cudaFree(accum_);
        cudaFree(probe_);
        cudaFree(rayCounter_);
    }

    std::string name() const override { return "cuda"; }
    bool runsOnCuda() const override { return true; }
    std::string deviceName() const override { return deviceName_; }

    // Arrays equal to the ones already on the device are not copied again (an edited material re-sends
    // the materials, not the meshes).
    bool accepts(const SceneArrays& a, std::string& why) const override {
        if (a.traversalStackNeed <= (uint32_t)kDeviceTraversalStackSize) return true;
        why = "the scene's BVHs need a traversal stack of " + std::to_string(a.traversalStackNeed) +
              " entries and the CUDA kernels hold " + std::to_string(kDeviceTraversalStackSize);
        return false;
    }
    void upload(const SceneArrays& a) override { upload(a, kAllArrays); }
    // Arrays outside `changed` are neither compared nor sent.
    void upload(const SceneArrays& a, ArrayMask changed) override {
        useDevice();
        std::string why;
        if (!accepts(a, why)) throw std::runtime_error(why);
#define TRAZO_X(T, name, ...)                                            \
    if (changed & maskOf(SceneArray::name)) device_.name.assign(a.name); \
    view_.name = device_.name.view();
        TRAZO_SCENE_ARRAYS(TRAZO_X)
#undef TRAZO_X
        view_.settings = a.settings;
        view_.features = a.features;
    }
    void resize(uint32_t width, uint32_t height) override {
        useDevice();
        cudaFree(accum_);
        accum_ = nullptr;
        width_ = height_ = 0;  // until the new buffer exists: nothing to clear or read
        TRAZO_CUDA_CHECK(cudaMalloc(&accum_, (size_t)width * height * sizeof(AccumPixel)));
        width_ = width;
        height_ = height;
        probePixels_.assign(std::vector<uint32_t>{});  // its pixels were the old image's
        cudaFree(probe_);
        probe_ = nullptr;
        probeCount_ = 0;
        reset();
    }
    void reset() override {
        useDevice();
        TRAZO_CUDA_CHECK(cudaMemset(accum_, 0, pixelCount() * sizeof(AccumPixel)));
        if (probe_) TRAZO_CUDA_CHECK(cudaMemset(probe_, 0, probePixelCount() * sizeof(AccumPixel)));
        TRAZO_CUDA_CHECK(cudaMemset(rayCounter_, 0, sizeof(unsigned long long)));
    }
    bool hasProbe() const override { return true; }
    void resizeProbe(const std::vector<uint32_t>& pixels) override {
        checkProbePixels(pixels, width_, height_);
        useDevice();
        cudaFree(probe_);
        probe_ = nullptr;
        probeCount_ = 0;
        const size_t padded = (pixels.size() + kProbeRow - 1) / kProbeRow * kProbeRow;
        TRAZO_CUDA_CHECK(cudaMalloc(&probe_, padded * sizeof(AccumPixel)));
        TRAZO_CUDA_CHECK(cudaMemset(probe_, 0, padded * sizeof(AccumPixel)));
        probePixels_.assign(pixels);
        probeCount_ = (uint32_t)pixels.size();
    }
    void readProbe(std::vector<AccumPixel>& out) override {
        useDevice();
        out.resize(probeCount_);
        TRAZO_CUDA_CHECK(cudaMemcpy(out.data(), probe_, probeCount_ * sizeof(AccumPixel), cudaMemcpyDeviceToHost));
    }
    void writeProbe(const std::vector<AccumPixel>& accum) override {
        checkProbeAccumulation(accum, probeCount_);
        useDevice();
        TRAZO_CUDA_CHECK(cudaMemcpy(probe_, accum.data(), probeCount_ * sizeof(AccumPixel), cudaMemcpyHostToDevice));
    }
    void renderPasses(const FrameParams& target, uint32_t firstPass, uint32_t passCount) override {
        useDevice();
        const FrameParams frame = boundFrame(target, width_, height_, probePixels_.data(), probeCount_);
        AccumPixel* const accum = frame.target.probe ? probe_ : accum_;
        const dim3 block(kPassBlockX, kPassBlockY);
        const dim3 grid((frame.accumWidth() + block.x - 1) / block.x, (frame.accumHeight() + block.y - 1) / block.y);
        const auto launch = kLaunchVariants[sampleVariantFor(view_.settings.integrator, view_.features)];
        for (uint32_t pass = firstPass; pass < firstPass + passCount; ++pass) {
            launch(grid, block, view_, frame, pass, accum, rayCounter_);
            checkPasses(cudaGetLastError(), pass, pass + 1);
            if (syncEveryPass_) checkPasses(cudaDeviceSynchronize(), pass, pass + 1);
        }
        checkPasses(cudaDeviceSynchronize(), firstPass, firstPass + passCount);
    }
    void readAccumulation(std::vector<AccumPixel>& out) override {
        useDevice();
        out.resize(pixelCount());
        TRAZO_CUDA_CHECK(cudaMemcpy(out.data(), accum_, pixelCount() * sizeof(AccumPixel), cudaMemcpyDeviceToHost));
    }
    bool resolveToGlBuffer(unsigned glBuffer, uint32_t width, uint32_t height, std::string& why) override {
        if (width != width_ || height != height_) {
            why = "the GL buffer's size differs from the accumulation's";
            return false;
        }
        useDevice();
        if (!glDisplay_) glDisplay_.reset(createCudaGlDisplay());
        return resolveIntoGlBuffer(*glDisplay_, glBuffer, accum_, width, height, why);
    }
    void releaseGlBuffer() override {
        if (glDisplay_) releaseCudaGlDisplay(*glDisplay_);
    }
    uint64_t raysTraced() const override {
        useDevice();
        unsigned long long rays = 0;
        TRAZO_CUDA_CHECK(cudaMemcpy(&rays, rayCounter_, sizeof(rays), cudaMemcpyDeviceToHost));
        return rays;
    }

    using Backend::traceRays;
    double traceRays(const std::vector<RayQuery>& queries, RayQueryKind kind, std::vector<RayAnswer>& out) override {
        out.assign(queries.size(), RayAnswer{0.0f, kMissAnswer});
        if (queries.empty()) return 0.0;
        useDevice();
        queries_.assign(queries);
        hits_.resizeForOutput(queries.size());
        const uint32_t count = (uint32_t)queries.size();
        constexpr uint32_t kBlock = 128;
        const EventTimer timer;
        TRAZO_CUDA_CHECK(cudaEventRecord(timer.start));
        rayQueryKernel<<<(count + kBlock - 1) / kBlock, kBlock>>>(view_, queries_.data(), count, kind, hits_.data());
        TRAZO_CUDA_CHECK(cudaGetLastError());
        TRAZO_CUDA_CHECK(cudaEventRecord(timer.stop));
        TRAZO_CUDA_CHECK(cudaEventSynchronize(timer.stop));
        float milliseconds = 0.0f;
        TRAZO_CUDA_CHECK(cudaEventElapsedTime(&milliseconds, timer.start, timer.stop));
        TRAZO_CUDA_CHECK(cudaMemcpy(out.data(), hits_.data(), count * sizeof(RayAnswer), cudaMemcpyDeviceToHost));
        return milliseconds * 1e-3;
    }

private:
    size_t pixelCount() const { return (size_t)width_ * height_; }
    size_t probePixelCount() const { return (size_t)(probeCount_ + kProbeRow - 1) / kProbeRow * kProbeRow; }
    void useDevice() const { TRAZO_CUDA_CHECK(cudaSetDevice(deviceIndex_)); }

    int deviceIndex_ = 0;
    std::string deviceName_;
    bool syncEveryPass_ = false;
    struct DeviceScene {
#define TRAZO_X(T, name, ...) DeviceArray<T> name;
        TRAZO_SCENE_ARRAYS(TRAZO_X)
#undef TRAZO_X
    } device_;
    SceneView view_{};
    DeviceArray<RayQuery> queries_;  // traceRays' buffers, kept for the next call
    DeviceArray<RayAnswer> hits_;
    AccumPixel* accum_ = nullptr;
    DeviceArray<uint32_t> probePixels_;  // resizeProbe's list; the probe's accumulation, kProbeRow a row:
    AccumPixel* probe_ = nullptr;
    uint32_t probeCount_ = 0;
    unsigned long long* rayCounter_ = nullptr;
    uint32_t width_ = 0, height_ = 0;
    std::unique_ptr<CudaGlDisplay, void (*)(CudaGlDisplay*)> glDisplay_{nullptr, destroyCudaGlDisplay};
};

}  // namespace

bool cudaDeviceAvailableImpl(std::string& deviceName) {
    int count = 0;  // not written when the driver is missing
    const cudaError_t status = cudaGetDeviceCount(&count);
    if (status != cudaSuccess || count == 0) {
        deviceName = status != cudaSuccess ? cudaGetErrorString(status) : "no CUDA device found";
        cudaGetLastError();  // clear the sticky error for later calls
        return false;
    }
    cudaDeviceProp prop{};
    if (cudaGetDeviceProperties(&prop, 0) != cudaSuccess) return false;
    deviceName = prop.name;
    return true;
}

int cudaDeviceCountImpl(std::string& why) {
    int count = 0;
    const cudaError_t status = cudaGetDeviceCount(&count);
    if (status != cudaSuccess || count == 0) {
        why = status != cudaSuccess ? cudaGetErrorString(status) : "no CUDA device found";
        cudaGetLastError();
        return 0;
    }
    return count;
}

std::unique_ptr<Backend> createCudaBackendOnImpl(int index, std::string& error) {
    try {
        return std::make_unique<CudaBackend>(index);
    } catch (const std::exception& e) {
        error = e.what();
        return nullptr;
    }
}

std::unique_ptr<Backend> createCudaBackend(std::string& error) { return createCudaBackendOnImpl(0, error); }

}  // namespace trazo

// Backend: where passes run and accumulation lives (CPU threads or a CUDA device). Host-side interface.
#pragma once

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "flatten/array_mask.h"
#include "flatten/scene_arrays.h"
#include "integrator/frame_params.h"
#include "integrator/ray_query.h"
#include "core/accumulation.h"

namespace trazo {

class Backend {
public:
    virtual ~Backend() = default;

    virtual std::string name() const = 0;        // "cpu" or "cuda"
    virtual bool runsOnCuda() const { return false; }  // the viewer's backend menu shows it as CUDA
    virtual std::string deviceName() const = 0;  // e.g. "2 threads" or "NVIDIA H100 80GB HBM3"

    // Whether this backend's kernels can render the scene; when not, says why (the CUDA kernels hold a
    // fixed traversal stack). upload() throws for a scene this refuses.
    virtual bool accepts(const SceneArrays& arrays, std::string& why) const {
        (void)arrays, (void)why;
        return true;
    }
    // Copies the flattened scene into backend memory (replacing any previous one).
    virtual void upload(const SceneArrays& arrays) = 0;
    // Replaces only the arrays (and values) in `changed`; the rest stay as uploaded before, which must be
    // what `arrays` holds there (an edit: changedArrays() between the two flattens). Backends that cannot
    // update in part upload everything.
    virtual void upload(const SceneArrays& arrays, ArrayMask changed) {
        (void)changed;
        upload(arrays);
    }
    // The same for a caller that no longer needs the arrays: a backend that renders from host memory takes
    // them over instead of copying (the CPU backend: a million-triangle mesh is 160 MB of arrays). `arrays`
    // is left valid but unspecified.
    virtual void uploadMoved(SceneArrays&& arrays) { upload(arrays); }
    // (Re)allocates the accumulation buffer for width × height and clears it.
    virtual void resize(uint32_t width, uint32_t height) = 0;
    // Clears the sums and counts (no reallocation).
    virtual void reset() = 0;
    // Adds passes [firstPass, firstPass + passCount) to every pixel of the accumulation frame.target names
    // (the image's, or the probe's); blocks until done.
    virtual void renderPasses(const FrameParams& frame, uint32_t firstPass, uint32_t passCount) = 0;
    // Copies the accumulation buffer (row 0 = top) to the host.
    virtual void readAccumulation(std::vector<AccumPixel>& out) = 0;
    // The accumulation itself where it is host memory (the CPU backend's), to read without a copy until the next
    // call that renders or resizes; null where readAccumulation must copy it. A copy of a large image costs more
    // than a one-pass render of a simple scene (its fresh pages fault in one by one).
    virtual const std::vector<AccumPixel>* hostAccumulation() const { return nullptr; }
    // The error probe (render/error_probe.h): a second accumulation, of the image pixels `pixels` lists
    // (indices y·width + x) rendered again with an independent seed. resizeProbe takes the list and
    // (re)allocates and clears it; reset() clears it too; readProbe gives one AccumPixel per listed pixel. A
    // backend without one (hasProbe() false) leaves the estimate to the image's halves.
    virtual bool hasProbe() const { return false; }
    virtual void resizeProbe(const std::vector<uint32_t>& pixels) {
        (void)pixels;
        throw std::logic_error("the " + name() + " backend has no error probe");
    }
    virtual void readProbe(std::vector<AccumPixel>& out) {
        (void)out;
        throw std::logic_error("the " + name() + " backend has no error probe");
    }
    // Replaces the probe's accumulation with `accum`, one AccumPixel per listed pixel as readProbe gives them
    // (a grown probe keeps what its pixels had summed: render/error_probe.h).
    virtual void writeProbe(const std::vector<AccumPixel>& accum) {
        (void)accum;
        throw std::logic_error("the " + name() + " backend has no error probe");
    }
    // Rays traced since the last reset.
    virtual uint64_t raysTraced() const = 0;
    // Answers every query against the uploaded scene (answerRayQuery: benchmarks, agreement tests, the
    // viewer's picking with RayQueryKind::Object) into `out`. Returns the seconds spent tracing, without
    // copies to or from the device.
    virtual double traceRays(const std::vector<RayQuery>& queries, RayQueryKind kind, std::vector<RayAnswer>& out) = 0;

    // Display (the viewer): writes the current estimate, sum / count as float RGBA (alpha 1, row 0 = top),
    // into the OpenGL buffer object `glBuffer` (at least width·height·16 bytes; width × height must be the
    // accumulation's size) without a copy through the host. Needs a GL context current on this thread that
    // the backend's device can share (CUDA-GL interop). Returns false with the reason when it cannot; the
    // caller then fills the buffer from readAccumulation() itself.
    virtual bool resolveToGlBuffer(unsigned glBuffer, uint32_t width, uint32_t height, std::string& why) {
        (void)glBuffer, (void)width, (void)height;
        why = "the " + name() + " backend has no GL interop";
        return false;
    }
    // Lets go of the GL buffer resolveToGlBuffer wrote to (CUDA: unregisters it). Called before the buffer's
    // storage is specified again, which a registered buffer must not see.
    virtual void releaseGlBuffer() {}
};

// The frame a backend renders: the caller's, with a probe pass's `target` pointed at the backend's own copy of
// the list (`probePixels`, `probeCount` of them, in the memory its kernels read). Refuses a frame whose
// pixels are not the allocated accumulation's (resize, resizeProbe): a kernel would write out of bounds.
inline FrameParams boundFrame(const FrameParams& frame, uint32_t width, uint32_t height, const uint32_t* probePixels,
                              uint32_t probeCount) {
    const bool matches = frame.camera.width == width && frame.camera.height == height &&
                         (!frame.target.probe || (probePixels != nullptr && probeCount > 0));
    if (!matches) throw std::logic_error("renderPasses: the frame's pixels differ from the allocated accumulation");
    FrameParams bound = frame;
    if (frame.target.probe) bound.target = PassPixels{true, probePixels, probeCount};
    return bound;
}

// Probe pixels as the list says, each checked against the image (width × height): an index beyond it is refused.
inline void checkProbePixels(const std::vector<uint32_t>& pixels, uint32_t width, uint32_t height) {
    for (uint32_t p : pixels)
        if ((uint64_t)p >= (uint64_t)width * height) throw std::logic_error("resizeProbe: a pixel beyond the image");
}

inline void checkProbeAccumulation(const std::vector<AccumPixel>& accum, size_t probePixels) {
    if (accum.size() != probePixels) throw std::logic_error("writeProbe: not one AccumPixel per probed pixel");
}

// Backend::traceRays's answers as their t alone: Nearest t (+inf on a miss) or Shadow 1 (blocked) or 0.
inline double traceRayDistances(Backend& backend, const std::vector<RayQuery>& queries, RayQueryKind kind,
                                std::vector<float>& out) {
    std::vector<RayAnswer> answers;
    const double seconds = backend.traceRays(queries, kind, answers);
    out.resize(answers.size());
    for (size_t i = 0; i < answers.size(); ++i) out[i] = answers[i].t;
    return seconds;
}

enum class BackendChoice { Auto, Cpu, Cuda };

// threads = 0: all hardware threads. On failure returns null and says why in `error`
// (e.g. CUDA requested but not built, or no device). Auto falls back to the CPU.
std::unique_ptr<Backend> createBackend(BackendChoice choice, unsigned threads, std::string& error);
// The same for one scene: a backend that does not accept it (Backend::accepts) counts as unavailable.
std::unique_ptr<Backend> createBackendFor(const SceneArrays& arrays, BackendChoice choice, unsigned threads,
                                          std::string& error);

std::unique_ptr<Backend> createCpuBackend(unsigned threads);

// True when this build has the CUDA backend and a usable device is present; names it.
bool cudaDeviceAvailable(std::string& deviceName);

// The CUDA devices present: 0 without the CUDA backend, a driver or a device (`why` then says which).
int cudaDeviceCount(std::string& why);
// A CUDA backend on device `index` (each of its calls makes that device current on the calling thread); null
// with the reason. Device 0 is the backend createBackend(Cuda, ...) opens.
std::unique_ptr<Backend> createCudaBackendOn(int index, std::string& error);

}  // namespace trazo

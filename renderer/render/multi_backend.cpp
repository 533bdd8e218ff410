// MultiBackend: threads per call (a call is a batch of passes: ~0.2 s, so starting threads costs nothing
// measurable), contiguous pass splits, the merge's sum.
#include "render/multi_backend.h"

#include <exception>
#include <stdexcept>
#include <thread>

#include "render/merge.h"

namespace trazo {

MultiBackend::MultiBackend(std::vector<std::unique_ptr<Backend>> backends) : backends_(std::move(backends)) {
    if (backends_.empty()) throw std::invalid_argument("MultiBackend needs at least one backend");
}

std::string MultiBackend::name() const { return backends_[0]->name(); }

std::string MultiBackend::deviceName() const {
    std::string text = std::to_string(backends_.size()) + " devices: ";
    for (size_t i = 0; i < backends_.size(); ++i) {
        if (i) text += ", ";
        text += backends_[i]->deviceName();
    }
    return text;
}

bool MultiBackend::accepts(const SceneArrays& arrays, std::string& why) const {
    for (const auto& b : backends_)
        if (!b->accepts(arrays, why)) return false;
    return true;
}

void MultiBackend::forEach(const std::function<void(size_t)>& f) {
    std::vector<std::exception_ptr> errors(backends_.size());
    std::vector<std::thread> threads;
    for (size_t i = 0; i < backends_.size(); ++i)
        threads.emplace_back([&, i] {
            try {
                f(i);
            } catch (...) {
                errors[i] = std::current_exception();
            }
        });
    for (std::thread& t : threads) t.join();
    for (const std::exception_ptr& e : errors)
        if (e) std::rethrow_exception(e);
}

void MultiBackend::upload(const SceneArrays& arrays) {
    forEach([&](size_t i) { backends_[i]->upload(arrays); });
}

void MultiBackend::resize(uint32_t width, uint32_t height) {
    forEach([&](size_t i) { backends_[i]->resize(width, height); });
}

void MultiBackend::reset() {
    forEach([&](size_t i) { backends_[i]->reset(); });
}

PassRange splitPasses(uint32_t first, uint32_t count, size_t n, size_t i) {
    const uint32_t share = count / (uint32_t)n, extra = count % (uint32_t)n;
    const uint32_t begin = first + (uint32_t)i * share + std::min((uint32_t)i, extra);
    return PassRange{begin, begin + share + ((uint32_t)i < extra ? 1u : 0u)};
}

void MultiBackend::renderPasses(const FrameParams& frame, uint32_t firstPass, uint32_t passCount) {
    forEach([&](size_t i) {
        const PassRange share = splitPasses(firstPass, passCount, backends_.size(), i);
        if (share.count() > 0) backends_[i]->renderPasses(frame, share.first, share.count());
    });
}

void MultiBackend::readSum(void (Backend::*read)(std::vector<AccumPixel>&), std::vector<AccumPixel>& out) {
    std::vector<std::vector<AccumPixel>> parts(backends_.size());
    forEach([&](size_t i) { (backends_[i].get()->*read)(parts[i]); });
    out.assign(parts[0].size(), AccumPixel{});
    for (const std::vector<AccumPixel>& part : parts) addAccumulation(out, part);  // in device order
}

void MultiBackend::readAccumulation(std::vector<AccumPixel>& out) { readSum(&Backend::readAccumulation, out); }

bool MultiBackend::hasProbe() const {
    for (const auto& b : backends_)
        if (!b->hasProbe()) return false;
    return true;
}

void MultiBackend::resizeProbe(const std::vector<uint32_t>& pixels) {
    forEach([&](size_t i) { backends_[i]->resizeProbe(pixels); });
}

void MultiBackend::readProbe(std::vector<AccumPixel>& out) { readSum(&Backend::readProbe, out); }

void MultiBackend::writeProbe(const std::vector<AccumPixel>& accum) {
    const std::vector<AccumPixel> cleared(accum.size());
    forEach([&](size_t i) { backends_[i]->writeProbe(i == 0 ? accum : cleared); });
}

uint64_t MultiBackend::raysTraced() const {
    uint64_t rays = 0;
    for (const auto& b : backends_) rays += b->raysTraced();
    return rays;
}

double MultiBackend::traceRays(const std::vector<RayQuery>& queries, RayQueryKind kind, std::vector<RayAnswer>& out) {
    return backends_[0]->traceRays(queries, kind, out);
}

}  // namespace trazo

// The kernel instances of every integrator (core/integrator_kinds.h) in one table, keyed by (integrator,
// features): each integrator names its own instances, and the table lays them end to end, so both backends
// dispatch identically and a new integrator adds its instances without multiplying the others'.
#pragma once

#include <array>
#include <utility>

#include "core/integrator_kinds.h"
#include "integrator/path/path_integrator.h"
#include "integrator/thesis/thesis_integrator.h"

namespace trazo {

template <IntegratorKind K>
struct IntegratorOf;
#define TRAZO_X(kind, type, keyword)                \
    template <>                                     \
    struct IntegratorOf<IntegratorKind::kind> {     \
        using Type = type;                          \
    };
TRAZO_INTEGRATORS(TRAZO_X)
#undef TRAZO_X

// How many instances each integrator has, in list order.
constexpr uint32_t kIntegratorInstances[] = {
#define TRAZO_X(kind, type, keyword) type::kInstances,
    TRAZO_INTEGRATORS(TRAZO_X)
#undef TRAZO_X
};

constexpr uint32_t firstVariantOf(IntegratorKind kind) {
    uint32_t first = 0;
    for (uint32_t k = 0; k < (uint32_t)kind; ++k) first += kIntegratorInstances[k];
    return first;
}
constexpr uint32_t kSampleVariantCount = firstVariantOf(IntegratorKind(kIntegratorCount));

struct SampleVariant {
    IntegratorKind integrator;
    FeatureMask features;
};

// Entry v of the table: which integrator, specialised for which feature bits.
constexpr SampleVariant sampleVariant(uint32_t v) {
    uint32_t k = 0;
    while (v >= kIntegratorInstances[k]) v -= kIntegratorInstances[k++];
    const IntegratorKind kind = IntegratorKind(k);
#define TRAZO_X(kind_, type, keyword) \
    if (kind == IntegratorKind::kind_) return SampleVariant{kind, type::instanceFeatures(v)};
    TRAZO_INTEGRATORS(TRAZO_X)
#undef TRAZO_X
    return SampleVariant{kind, 0u};
}

// The entry that renders a scene with this integrator and these features.
constexpr uint32_t sampleVariantFor(IntegratorKind kind, FeatureMask mask) {
#define TRAZO_X(kind_, type, keyword) \
    if (kind == IntegratorKind::kind_) return firstVariantOf(kind) + type::instanceFor(mask);
    TRAZO_INTEGRATORS(TRAZO_X)
#undef TRAZO_X
    return 0;
}

// The thesis's oracle, every feature on, in the table.
constexpr uint32_t kAllFeaturesVariant =
    firstVariantOf(IntegratorKind::Thesis) + ThesisIntegrator::kAllFeaturesInstance;

// One sample of pixel (px, py) in this pass by integrator K specialised for F. `given` (host x86 only, else
// null): the scene's antialiasing side is 1, and this is the camera ray of the pixel's one position, traced.
template <IntegratorKind K, FeatureMask F>
TRAZO_HD Vec3 renderSample(const SceneView& scene, const FrameParams& frame, uint32_t px, uint32_t py,
                           uint32_t pass, uint32_t& rays, const TracedRay* given = nullptr) {
    return IntegratorOf<K>::Type::template sample<F>(scene, frame, px, py, pass, rays, given);
}

// A table with Entry<integrator, features>::value of entry v at index v, e.g. the CPU's tile renderers or the
// CUDA kernels' launchers.
template <template <IntegratorKind, FeatureMask> class Entry, uint32_t... V>
constexpr auto makeVariantTable(std::integer_sequence<uint32_t, V...>) {
    using Value = decltype(Entry<IntegratorKind::Thesis, 0>::value);
    return std::array<Value, sizeof...(V)>{Entry<sampleVariant(V).integrator, sampleVariant(V).features>::value...};
}

template <template <IntegratorKind, FeatureMask> class Entry>
constexpr auto makeVariantTable() {
    return makeVariantTable<Entry>(std::make_integer_sequence<uint32_t, kSampleVariantCount>{});
}

static_assert(sampleVariant(kAllFeaturesVariant).features == kAllSampleFeatures);

}  // namespace trazo

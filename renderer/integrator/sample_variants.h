// The specialised instances of renderSample<F>: one per combination of the coarse feature bits below,
// chosen at upload from the scene's FeatureMask, through the same table on both backends.
#pragma once

#include <array>
#include <utility>

#include "integrator/render_sample.h"

namespace trazo {

// Bits worth a separate instance (each guards a loop or a branch with ray work behind it): 16 instances.
constexpr FeatureMask kSpecialisedFeatures =
    kFeatureAreaLights | kFeatureReflection | kFeatureRefraction | kFeatureIndirect;
// SPEC §6's dispersion and subsurface scattering: a scene that uses either takes one more instance, with every
// feature on. The 16 instances of the other features compile exactly as without them (the same code,
// registers and spills), and a bit each would have doubled the instances, and the CUDA build, twice over.
constexpr FeatureMask kRareFeatures = kFeatureDispersion | kFeatureSubsurface;
constexpr uint32_t kSampleVariantCount = 17;
// The index of the instance with every feature on: the oracle.
constexpr uint32_t kAllFeaturesVariant = kSampleVariantCount - 1;
constexpr FeatureMask kAllSampleFeatures = kSpecialisedFeatures | kRareFeatures;

constexpr FeatureMask variantFeatures(uint32_t variant) {
    if (variant == kAllFeaturesVariant) return kAllSampleFeatures;
    return ((variant & 1u) ? kFeatureAreaLights : 0u) | ((variant & 2u) ? kFeatureReflection : 0u) |
           ((variant & 4u) ? kFeatureRefraction : 0u) | ((variant & 8u) ? kFeatureIndirect : 0u);
}

constexpr uint32_t sampleVariantFor(FeatureMask mask) {
    if (mask & kRareFeatures) return kAllFeaturesVariant;
    return ((mask & kFeatureAreaLights) ? 1u : 0u) | ((mask & kFeatureReflection) ? 2u : 0u) |
           ((mask & kFeatureRefraction) ? 4u : 0u) | ((mask & kFeatureIndirect) ? 8u : 0u);
}

static_assert(variantFeatures(kAllFeaturesVariant) == kAllSampleFeatures);
static_assert(sampleVariantFor(kAllSampleFeatures) == kAllFeaturesVariant);
static_assert(variantFeatures(kAllFeaturesVariant - 1) == kSpecialisedFeatures);

// A table with Entry<variantFeatures(i)>::value at index i, e.g. the CPU's sample functions or the CUDA
// kernels, so both backends dispatch identically.
template <template <FeatureMask> class Entry, uint32_t... I>
constexpr auto makeVariantTable(std::integer_sequence<uint32_t, I...>) {
    using Value = decltype(Entry<0>::value);
    return std::array<Value, sizeof...(I)>{Entry<variantFeatures(I)>::value...};
}

template <template <FeatureMask> class Entry>
constexpr auto makeVariantTable() {
    return makeVariantTable<Entry>(std::make_integer_sequence<uint32_t, kSampleVariantCount>{});
}

}  // namespace trazo

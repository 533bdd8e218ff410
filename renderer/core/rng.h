// Counter-based random numbers shared by both backends: a value is a pure function of
// (seed, pixel, pass, dimension), so images do not depend on thread count or scheduling.
#pragma once

#include <cstdint>

#include "core/hd.h"

namespace trazo {

// A 32-bit integer hash with good avalanche (Wellons' "lowbias32" triple32 variant). A template over the
// unsigned type so that the host's SIMD lanes (integrator/packets/packet_lanes.h) draw the same numbers from one source.
template <typename U>
TRAZO_HD U hashBits(U x) {
    x ^= x >> 17;
    x *= 0xed5ad4bbu;
    x ^= x >> 11;
    x *= 0xac4c1b51u;
    x ^= x >> 15;
    x *= 0x31848babu;
    x ^= x >> 14;
    return x;
}

// hashU32(h combined with v), v a uint32_t or lanes of them.
template <typename U>
TRAZO_HD U hashCombineBits(uint32_t h, U v) {
    return hashBits<U>(h ^ (v + 0x9e3779b9u + (h << 6) + (h >> 2)));
}

TRAZO_HD uint32_t hashU32(uint32_t x) { return hashBits(x); }
TRAZO_HD uint32_t hashCombine(uint32_t h, uint32_t v) { return hashCombineBits(h, v); }

// Maps 32 random bits to [0, 1) exactly representable (24 bits of mantissa).
TRAZO_HD float bitsToUnitFloat(uint32_t bits) { return float(bits >> 8) * (1.0f / 16777216.0f); }

// The stream of one pixel in one pass. Dimensions are drawn in a fixed order by the integrator.
struct SampleStream {
    uint32_t key;
    uint32_t dimension = 0;

    TRAZO_HD SampleStream(uint32_t seed, uint32_t pixelIndex, uint32_t pass)
        : key(hashCombine(hashCombine(hashU32(seed ^ 0x5bd1e995u), pixelIndex), pass)) {}

    TRAZO_HD uint32_t nextBits() { return hashCombine(key, dimension++); }
    TRAZO_HD float next() { return bitsToUnitFloat(nextBits()); }
};

// A pseudo-random permutation of [0, count) chosen by `key`: Kensler's hash-based permutation ("Correlated
// Multi-Jittered Sampling", Pixar 2013), a bijection on the next power of two walked until it lands in range
// (fewer than two rounds on average). A count of 0 or 1 has the one answer 0 (0 would otherwise divide by
// zero: the scene's bounds keep every grid far from a wrapped count, this keeps a kernel safe regardless).
TRAZO_HD uint32_t permuteIndex(uint32_t i, uint32_t count, uint32_t key) {
    if (count <= 1u) return 0u;
    uint32_t w = count - 1;
    w |= w >> 1;
    w |= w >> 2;
    w |= w >> 4;
    w |= w >> 8;
    w |= w >> 16;
    do {
        i ^= key;
        i *= 0xe170893du;
        i ^= key >> 16;
        i ^= (i & w) >> 4;
        i ^= key >> 8;
        i *= 0x0929eb3fu;
        i ^= key >> 23;
        i ^= (i & w) >> 1;
        i *= 1u | key >> 27;
        i *= 0x6935fa69u;
        i ^= (i & w) >> 11;
        i *= 0x74dcb303u;
        i ^= (i & w) >> 2;
        i *= 0x9e501cc3u;
        i ^= (i & w) >> 2;
        i *= 0xc860a3dfu;
        i &= w;
        i ^= i >> 5;
    } while (i >= count);
    return (i + key) % count;
}

// The stratum a pixel uses in a pass for a grid of `count` cells: every `count` consecutive passes visit
// every stratum once, in an order drawn per pixel and per grid. A shuffled order (rather than a sweep)
// spreads the first passes of a cycle over the whole grid, so an image short of a full cycle is already
// an unbiased estimate of the whole light or cone, not of one strip of it. A count of 0 gives stratum 0.
TRAZO_HD uint32_t stratumForPass(uint32_t seed, uint32_t pixelIndex, uint32_t gridId, uint32_t pass, uint32_t count) {
    if (count <= 1u) return 0u;
    const uint32_t key = hashCombine(hashCombine(hashU32(seed + 0x68e31da4u), pixelIndex), gridId);
    return permuteIndex(pass % count, count, key);
}

}  // namespace trazo

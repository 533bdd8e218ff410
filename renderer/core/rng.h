// Counter-based random numbers shared by both backends: a value is a pure function of
// (seed, pixel, pass, dimension), so images do not depend on thread count or scheduling.
#pragma once

#include <cstdint>

#include "core/hd.h"

namespace trazo {

// A 32-bit integer hash with good avalanche (Wellons' "lowbias32" triple32 variant).
TRAZO_HD uint32_t hashU32(uint32_t x) {
    x ^= x >> 17;
    x *= 0xed5ad4bbu;
    x ^= x >> 11;
    x *= 0xac4c1b51u;
    x ^= x >> 15;
    x *= 0x31848babu;
    x ^= x >> 14;
    return x;
}

TRAZO_HD uint32_t hashCombine(uint32_t h, uint32_t v) { return hashU32(h ^ (v + 0x9e3779b9u + (h << 6) + (h >> 2))); }

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

// The stratum a pixel uses in a pass for a grid of `count` cells: the pass cycles through every
// stratum, starting at an offset drawn per pixel and per grid so neighbouring pixels differ.
TRAZO_HD uint32_t stratumForPass(uint32_t seed, uint32_t pixelIndex, uint32_t gridId, uint32_t pass, uint32_t count) {
    const uint32_t offset = hashCombine(hashCombine(hashU32(seed + 0x68e31da4u), pixelIndex), gridId);
    return (uint32_t)(((uint64_t)offset + pass) % count);
}

}  // namespace trazo

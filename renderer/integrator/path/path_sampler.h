// The path tracer's sample dimensions: a scrambled Sobol (0,2)-sequence per pair of dimensions (pbrt-v4's
// "padded" Sobol sampler with Owen scrambling), indexed by the pass, so the pixel's positions, each vertex's
// light sample and each vertex's scattered direction are stratified over the passes in every 2D projection
// that matters, while pairs of different dimensions stay independent. Host and device.
//
// Each half of the accumulation (frame_params.h: passes alternate between two halves in blocks) takes its own
// scramble and counts its own passes, so the two halves are independent estimates of the pixel, as the error
// estimate requires, and each is a stratified sequence of its own.
#pragma once

#include "core/rng.h"
#include "integrator/frame_params.h"

namespace trazo {

TRAZO_HD uint32_t reverseBits32(uint32_t x) {
#if defined(__CUDA_ARCH__)
    return __brev(x);
#else
    x = (x << 16) | (x >> 16);
    x = ((x & 0x00ff00ffu) << 8) | ((x & 0xff00ff00u) >> 8);
    x = ((x & 0x0f0f0f0fu) << 4) | ((x & 0xf0f0f0f0u) >> 4);
    x = ((x & 0x33333333u) << 2) | ((x & 0xccccccccu) >> 2);
    return ((x & 0x55555555u) << 1) | ((x & 0xaaaaaaaau) >> 1);
#endif
}

// Laine and Karras's hash: each bit of x flipped by a function of the bits below it and the seed.
TRAZO_HD uint32_t laineKarras(uint32_t x, uint32_t seed) {
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return x;
}

// Owen's nested uniform scramble of the 32 bits of a point in [0, 1) (the hash on its reversed bits, so that
// each bit is flipped by a function of the bits above it): keeps a (0,2)-sequence's stratification and
// randomises its points. Points are kept bit-reversed until here: the first Sobol dimension reversed is the
// index itself, and the reversal that the scramble would undo is not done.
TRAZO_HD uint32_t owenScrambleReversed(uint32_t reversed, uint32_t seed) {
    return reverseBits32(laineKarras(reversed, seed));
}

// The second Sobol dimension of point i (the polynomial x + 1), its bits reversed: direction numbers
// v_k = v_{k−1} ^ v_{k−1} << 1 from v_0 = 1.
TRAZO_HD uint32_t sobolSecondReversed(uint32_t i) {
    uint32_t r = 0;
    for (uint32_t v = 1u; i != 0; i >>= 1, v ^= v << 1)
        if (i & 1u) r ^= v;
    return r;
}

// Dimensions of a path: the pixel position, then per vertex the light's choice, its point, the BSDF's lobe and
// its direction.
constexpr uint32_t kDimensionPixel = 0;
TRAZO_HD uint32_t lightChoiceDimension(uint32_t vertex) { return 1u + 4u * vertex; }
TRAZO_HD uint32_t lightPointDimension(uint32_t vertex) { return 2u + 4u * vertex; }
TRAZO_HD uint32_t lobeDimension(uint32_t vertex) { return 3u + 4u * vertex; }
TRAZO_HD uint32_t directionDimension(uint32_t vertex) { return 4u + 4u * vertex; }

struct PathSampler {
    uint32_t key;    // the frame's seed, the pixel and the half
    uint32_t index;  // the pass's place among its half's passes

    TRAZO_HD PathSampler(const FrameParams& frame, uint32_t pixelIndex, uint32_t pass) {
        const uint32_t block = frame.halfBlock;
        const uint32_t half = frame.inSecondHalf(pass) ? 1u : 0u;
        index = block == 0 ? pass : (pass / (2u * block)) * block + pass % block;
        key = hashCombine(hashCombine(hashU32(frame.seed ^ 0x50b01u), pixelIndex), half);
    }

    // Each dimension pair visits the sequence in its own order (Burley's shuffle: the index Owen-scrambled,
    // which keeps every power-of-two prefix a (0,m,2)-net): with one order for all, the pairs' values would share
    // their leading bits pass by pass, up to a fixed flip, and correlate.
    TRAZO_HD uint32_t shuffled(uint32_t dimension) const {
        return reverseBits32(laineKarras(reverseBits32(index), hashCombine(key, 3u * dimension)));
    }

    TRAZO_HD float get1D(uint32_t dimension) const {
        return bitsToUnitFloat(owenScrambleReversed(shuffled(dimension), hashCombine(key, 3u * dimension + 1u)));
    }
    TRAZO_HD void get2D(uint32_t dimension, float& a, float& b) const {
        const uint32_t i = shuffled(dimension);
        a = bitsToUnitFloat(owenScrambleReversed(i, hashCombine(key, 3u * dimension + 1u)));
        b = bitsToUnitFloat(owenScrambleReversed(sobolSecondReversed(i), hashCombine(key, 3u * dimension + 2u)));
    }
};

}  // namespace trazo

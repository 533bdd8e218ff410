// The sampling steps of SPEC §6's subsurface random walk, host and device: the entry direction (cosine about
// the inward normal), the isotropic phase function and the exponential free path.
#pragma once

#include <cmath>

#include "core/vec3.h"
#include "shading/scattering.h"

namespace trazo {

// A direction uniform on the unit sphere (pdf 1/4π): z = 1 − 2u1 uniform in [−1, 1] (Archimedes), and
// sin θ = 2√(u1(1 − u1)), which keeps its precision at the poles where √(1 − z²) would cancel.
TRAZO_HD Vec3 sampleIsotropic(float u1, float u2) {
    const float z = 1.0f - 2.0f * u1;
    const float sinTheta = 2.0f * sqrtf(maxOf(0.0f, u1 * (1.0f - u1)));
    float sinPhi, cosPhi;
    sinCos(6.28318530717958648f * u2, sinPhi, cosPhi);
    return {sinTheta * cosPhi, sinTheta * sinPhi, z};
}

// A direction about the unit vector n with pdf cos θ/π (Malley: a uniform disk point lifted to the
// hemisphere), cos θ = √(1 − u1) > 0 for u1 < 1, so never tangent to the surface.
TRAZO_HD Vec3 sampleCosineAbout(Vec3 n, float u1, float u2) {
    const float sinTheta = sqrtf(u1), cosTheta = sqrtf(1.0f - u1);
    float sinPhi, cosPhi;
    sinCos(6.28318530717958648f * u2, sinPhi, cosPhi);
    const ConeFrame f = coneFrame(n);
    return f.t1 * (sinTheta * cosPhi) + f.t2 * (sinTheta * sinPhi) + n * cosTheta;
}

// A distance with pdf e^(−s/d)/d (mean d, the free path of a medium of extinction 1/d): −d·ln(1 − u), through
// log1p for u near 0. u is held below 1 (the largest float under it gives ≈ 16.6·d), so a u of exactly 1
// from some other generator cannot give an infinite path.
TRAZO_HD float sampleFreePath(float meanFreePath, float u) {
    return meanFreePath * -log1pf(-minOf(u, 0.99999994f));
}

}  // namespace trazo

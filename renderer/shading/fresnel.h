// The exact unpolarised dielectric Fresnel reflectance of SPEC §6 (Fresnel), host and device.
#pragma once

#include <cmath>

#include "core/vec3.h"

namespace trazo {

// F = ½(rs² + rp²) for light arriving from the side of index n1 at an interface with index n2, where
// cosThetaI is the cosine of the angle to the normal (its sign is ignored; values beyond 1 count as 1).
// F = 1 under total internal reflection, 0 when n1 = n2 (no interface).
//
// Written in the relative index k = n2/n1 and c = k·cos θt = √(cos²θi + k² − 1) (Snell), so that
//   rs = (cos θi − c) / (cos θi + c),   rp = (k² cos θi − c) / (k² cos θi + c).
// Near the critical angle c² is a difference of nearly equal terms, so k² − 1 is formed as (k−1)(k+1)
// from k − 1 = (n2 − n1)/n1, exact to an ulp or two of itself, and never from the rounded k (whose error
// would swamp c² for indices close together). The result is the exact F of an incidence cosine within an
// ulp of the argument, give or take a few ulps of F (fresnel_test.cpp); the textbook
// 1 − (n1/n2)²(1 − cos²θi) needs thousands of ulps there. Both denominators are > 0 whenever c² > 0, so no
// NaN; |rs|, |rp| ≤ 1 in floats, so F ∈ [0, 1]. At grazing incidence (cos θi = 0) rs = rp = −1 and F = 1;
// at the critical angle c = 0 and F = 1, so the TIR branch joins continuously.
TRAZO_HD float dielectricFresnel(float cosThetaI, float n1, float n2) {
    if (n1 == n2) return 0.0f;
    const float cosI = minOf(fabsf(cosThetaI), 1.0f);
    const float k = n2 / n1;
    const float kMinus1 = (n2 - n1) / n1;  // k − 1 from the indices, not from the rounded k
    const float c2 = fmaf(cosI, cosI, kMinus1 * (kMinus1 + 2.0f));
    if (!(c2 > 0.0f)) return 1.0f;  // total internal reflection (and the critical angle itself)
    const float c = sqrtf(c2);
    const float kkCosI = k * k * cosI;
    // An index ratio beyond about 1.8e19 squares out of float: there rs → −1 and rp → 1, so F → 1.
    if (!(c2 < INFINITY && kkCosI < INFINITY)) return 1.0f;
    const float rs = (cosI - c) / (cosI + c);
    const float rp = (kkCosI - c) / (kkCosI + c);
    return 0.5f * (rs * rs + rp * rp);
}

}  // namespace trazo

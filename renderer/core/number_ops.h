// The number types that shading formulas and shape tests are written over, once (host and device): ScalarOps, one
// float; the host's SIMD lanes are LaneOps (integrator/packets/packet_lanes.h). A formula templated on T uses the
// language's arithmetic, comparisons, &, |, ! and c ? a : b, which GCC's vector extensions give lanes too, vector
// functions (dot, cross, normalize) by overload, and T:: for the few operations a lane must name. Each is the same
// IEEE operation for both types, so with -ffp-contract=off the lanes compute the scalar code's bits.
#pragma once

#include <cmath>
#include <cstdint>

#include "core/hd.h"
#include "core/vec3.h"

namespace trazo {

struct ScalarOps {
    using F = float;    // a number
    using I = int32_t;  // an integer
    using B = bool;     // a comparison's result (lanes: one per lane)
    using V = Vec3;     // a 3-vector

    TRAZO_HD static F splat(float x) { return x; }
    TRAZO_HD static V splat(Vec3 v) { return v; }
    // Whether any (all) of the comparison's lanes hold: lanes leave a loop or skip a branch only when all agree.
    TRAZO_HD static bool any(bool b) { return b; }
    TRAZO_HD static bool all(bool b) { return b; }
    TRAZO_HD static F min(F a, F b) { return minOf(a, b); }
    TRAZO_HD static F max(F a, F b) { return maxOf(a, b); }
    TRAZO_HD static F sqrt(F x) { return sqrtf(x); }
    TRAZO_HD static F abs(F x) { return fabsf(x); }
    TRAZO_HD static F copysign(F magnitude, F sign) { return copysignf(magnitude, sign); }
    TRAZO_HD static F fma(F a, F b, F c) { return fmaf(a, b, c); }
    // e^x; lanes call libm's expf in the lanes of `needed` only (its bits cannot be reproduced in SIMD).
    TRAZO_HD static F exp(F x, bool /*needed*/) { return expf(x); }
    TRAZO_HD static V select(bool m, V a, V b) { return m ? a : b; }
    TRAZO_HD static I truncate(F x) { return (I)x; }
    TRAZO_HD static F toFloat(I k) { return (F)k; }
};

}  // namespace trazo

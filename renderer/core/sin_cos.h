// sin and cos of one angle at once (host and device), written once as a template over the number type
// (core/number_ops.h) so that the host's SIMD lanes (LaneOps) compute the same bits as the scalar code: libm's
// sinf/cosf cannot be reproduced in lanes (glibc picks its variant at run time), and a call per direction is
// 8–9 % of a render with indirect light.
#pragma once

#include "core/hd.h"
#include "core/number_ops.h"

namespace trazo {

// sin x and cos x for 0 ≤ x < 2¹²·π/2, where callers keep their angles (outside it the results are unspecified,
// and the scalar conversion of a NaN to k would be undefined). The nearest multiple k of π/2 comes off in three
// parts (Cody and Waite; k times the first two is exact), then Cephes' minimax polynomials on [−π/4, π/4], and
// k mod 4 picks the signs: within 2 ulp of the true values on [0, 2π], within 1e-7 absolutely up to 2¹²·π/2
// (sin_cos_test.cpp). Every operation is IEEE single precision in a fixed order (the host builds with
// -ffp-contract=off), so lanes and scalars agree bit for bit.
template <class T>
TRAZO_HD void sinCosOf(typename T::F x, typename T::F& s, typename T::F& c) {
    using F = typename T::F;
    using I = typename T::I;
    const I k = T::truncate(x * 0.636619772f + 0.5f);
    const F kf = T::toFloat(k);
    const F r = ((x - kf * 1.5703125f) - kf * 4.837512969970703125e-4f) - kf * 7.54978995489188216e-8f;
    const F z = r * r;
    const F sinR = r + r * z * (-1.6666654611e-1f + z * (8.3321608736e-3f + z * -1.9515295891e-4f));
    const F cosR =
        1.0f - 0.5f * z + z * z * (4.166664568298827e-2f + z * (-1.388731625493765e-3f + z * 2.443315711809948e-5f));
    // x = k·π/2 + r: sin x is sin r, cos r, −sin r, −cos r and cos x is cos r, −sin r, −cos r, sin r for k mod 4
    // = 0, 1, 2, 3.
    const auto odd = (k & 1) != 0;
    const F sinAbs = odd ? cosR : sinR, cosAbs = odd ? sinR : cosR;
    s = (k & 2) != 0 ? -sinAbs : sinAbs;
    c = ((k + 1) & 2) != 0 ? -cosAbs : cosAbs;
}

TRAZO_HD void sinCos(float x, float& s, float& c) { sinCosOf<ScalarOps>(x, s, c); }

}  // namespace trazo

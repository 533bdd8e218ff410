// Error-free float transformations (host and device) for intersection code that must not lose digits, written
// over the number type (core/number_ops.h: T, and F for what needs no named operation) so that the shape tests'
// SIMD lanes share them.
#pragma once

#include "core/hd.h"
#include "core/number_ops.h"
#include "core/vec3.h"

namespace trazo {

// hi + lo is exactly the real result (lo = the rounding error of hi).
template <class F>
struct TwoOf {
    F hi, lo;
};
using TwoFloat = TwoOf<float>;

// Knuth's TwoSum: no multiply-add in it for a compiler to contract, so it stays exact under nvcc's
// default -fmad=true and --use_fast_math (neither reassociates additions).
template <class F>
TRAZO_HD TwoOf<F> twoSum(F a, F b) {
    const F s = a + b;
    const F bVirtual = s - a;
    const F aVirtual = s - bVirtual;
    return {s, (a - aVirtual) + (b - bVirtual)};
}

template <class T>
TRAZO_HD TwoOf<typename T::F> twoProductOf(typename T::F a, typename T::F b) {
    const typename T::F p = a * b;
    return {p, T::fma(a, b, -p)};
}
TRAZO_HD TwoFloat twoProduct(float a, float b) { return twoProductOf<ScalarOps>(a, b); }

// a·b − c·d to within 1.5 ulp (Kahan's algorithm, pbrt-v4's DifferenceOfProducts): exactly 0 when
// a·b = c·d, unlike a plain a·b − c·d that a compiler may contract into one fma.
template <class T>
TRAZO_HD typename T::F differenceOfProductsOf(typename T::F a, typename T::F b, typename T::F c, typename T::F d) {
    const typename T::F cd = c * d;
    const typename T::F error = T::fma(-c, d, cd);
    return T::fma(a, b, -cd) + error;
}
TRAZO_HD float differenceOfProducts(float a, float b, float c, float d) {
    return differenceOfProductsOf<ScalarOps>(a, b, c, d);
}

// u × v with every component accurate to its own magnitude, even for nearly parallel u and v. Either may be a
// Vec3 where T is lanes (one vector for all).
template <class T, class U, class W>
TRAZO_HD typename T::V crossAccurateOf(const U& u, const W& v) {
    return {differenceOfProductsOf<T>(T::splat(u.y), T::splat(v.z), T::splat(u.z), T::splat(v.y)),
            differenceOfProductsOf<T>(T::splat(u.z), T::splat(v.x), T::splat(u.x), T::splat(v.z)),
            differenceOfProductsOf<T>(T::splat(u.x), T::splat(v.y), T::splat(u.y), T::splat(v.x))};
}
TRAZO_HD Vec3 crossAccurate(Vec3 u, Vec3 v) { return crossAccurateOf<ScalarOps>(u, v); }

// |u|² − r² as if computed in twice the precision, then rounded (Ogita, Rump & Oishi 2005: Dot2 over
// the four products u·u and r·(−r)).
template <class T>
TRAZO_HD typename T::F lengthSquaredMinusSquareAccurateOf(const typename T::V& u, float r) {
    using Two = TwoOf<typename T::F>;
    const Two x = twoProductOf<T>(u.x, u.x);
    const Two y = twoProductOf<T>(u.y, u.y);
    const Two z = twoProductOf<T>(u.z, u.z);
    const TwoFloat rr = twoProduct(r, r);
    const Two s1 = twoSum(x.hi, y.hi);
    const Two s2 = twoSum(s1.hi, z.hi);
    const Two s3 = twoSum(s2.hi, T::splat(-rr.hi));
    return s3.hi + ((s1.lo + s2.lo + s3.lo) + (x.lo + y.lo + z.lo - rr.lo));
}
TRAZO_HD float lengthSquaredMinusSquareAccurate(Vec3 u, float r) {
    return lengthSquaredMinusSquareAccurateOf<ScalarOps>(u, r);
}

}  // namespace trazo

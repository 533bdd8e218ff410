// Error-free float transformations (host and device) for intersection code that must not lose digits.
#pragma once

#include "core/hd.h"
#include "core/vec3.h"

namespace trazo {

// hi + lo is exactly the real result (lo = the rounding error of hi).
struct TwoFloat {
    float hi, lo;
};

// Knuth's TwoSum: no multiply-add in it for a compiler to contract, so it stays exact under nvcc's
// default -fmad=true and --use_fast_math (neither reassociates additions).
TRAZO_HD TwoFloat twoSum(float a, float b) {
    const float s = a + b;
    const float bVirtual = s - a;
    const float aVirtual = s - bVirtual;
    return {s, (a - aVirtual) + (b - bVirtual)};
}

TRAZO_HD TwoFloat twoProduct(float a, float b) {
    const float p = a * b;
    return {p, fmaf(a, b, -p)};
}

// a·b − c·d to within 1.5 ulp (Kahan's algorithm, pbrt-v4's DifferenceOfProducts): exactly 0 when
// a·b = c·d, unlike a plain a·b − c·d that a compiler may contract into one fma.
TRAZO_HD float differenceOfProducts(float a, float b, float c, float d) {
    const float cd = c * d;
    const float error = fmaf(-c, d, cd);
    return fmaf(a, b, -cd) + error;
}

// u × v with every component accurate to its own magnitude, even for nearly parallel u and v.
TRAZO_HD Vec3 crossAccurate(Vec3 u, Vec3 v) {
    return {differenceOfProducts(u.y, v.z, u.z, v.y), differenceOfProducts(u.z, v.x, u.x, v.z),
            differenceOfProducts(u.x, v.y, u.y, v.x)};
}

// |u|² − r² as if computed in twice the precision, then rounded (Ogita, Rump & Oishi 2005: Dot2 over
// the four products u·u and r·(−r)).
TRAZO_HD float lengthSquaredMinusSquareAccurate(Vec3 u, float r) {
    const TwoFloat x = twoProduct(u.x, u.x);
    const TwoFloat y = twoProduct(u.y, u.y);
    const TwoFloat z = twoProduct(u.z, u.z);
    const TwoFloat rr = twoProduct(r, r);
    const TwoFloat s1 = twoSum(x.hi, y.hi);
    const TwoFloat s2 = twoSum(s1.hi, z.hi);
    const TwoFloat s3 = twoSum(s2.hi, -rr.hi);
    return s3.hi + ((s1.lo + s2.lo + s3.lo) + (x.lo + y.lo + z.lo - rr.lo));
}

}  // namespace trazo

// The Beckmann microfacet lobe of SPEC §7: §5's distribution D (slope m) with Smith's masking G1, so that the
// lobe conserves energy and can be sampled; host and device.
#pragma once

#include <cmath>

#include "core/vec3.h"

namespace trazo {

constexpr float kPi = 3.14159265358979f;

// D(h) = exp(−tan²θh / m²) / (π m² cos⁴θh), for cos θh = n·h > 0.
TRAZO_HD float beckmannD(float cosH, float m) {
    if (!(cosH > 0.0f)) return 0.0f;
    const float cos2 = cosH * cosH;
    const float tan2 = (1.0f - cos2) / cos2;
    const float m2 = m * m;
    return expf(-tan2 / m2) / (kPi * m2 * cos2 * cos2);
}

// Smith's G1 for Beckmann: 2 / (1 + erf(μ) + exp(−μ²)/(μ√π)), μ = 1/(m·tan θ) (SPEC §7); 1 at normal incidence.
TRAZO_HD float beckmannG1(float cosW, float m) {
    if (!(cosW > 0.0f)) return 0.0f;
    const float sin2 = maxOf(0.0f, 1.0f - cosW * cosW);
    if (sin2 == 0.0f) return 1.0f;
    const float mu = cosW / (m * sqrtf(sin2));
    if (mu > 8.0f) return 1.0f;  // erf(μ) = 1 and the exponential term below 1e-28
    return 2.0f / (1.0f + erff(mu) + expf(-mu * mu) / (mu * 1.7724538509f));
}

// f·(n·wi) of the lobe without its colour: D·G1(wo)·G1(wi) / (4·(n·wo)); 0 unless both are above n.
TRAZO_HD float beckmannCos(Vec3 n, Vec3 wo, Vec3 wi, float m) {
    const float cosO = dot(n, wo), cosI = dot(n, wi);
    if (!(cosO > 0.0f) || !(cosI > 0.0f)) return 0.0f;
    const Vec3 h = normalize(wo + wi);
    return beckmannD(dot(n, h), m) * beckmannG1(cosO, m) * beckmannG1(cosI, m) / (4.0f * cosO);
}

// A microfacet normal with density D(h)·(n·h) about n (t1, t2: a tangent frame): tan²θ = −m² ln(1 − u1).
TRAZO_HD Vec3 sampleBeckmannNormal(Vec3 n, Vec3 t1, Vec3 t2, float m, float u1, float u2) {
    const float tan2 = -m * m * logf(1.0f - u1);
    const float cosTheta = 1.0f / sqrtf(1.0f + tan2);
    const float sinTheta = sqrtf(maxOf(0.0f, 1.0f - cosTheta * cosTheta));
    const float phi = 2.0f * kPi * u2;
    return normalize(n * cosTheta + (t1 * cosf(phi) + t2 * sinf(phi)) * sinTheta);
}

// The density in solid angle of wi = reflect(wo about h) when h is drawn by sampleBeckmannNormal.
TRAZO_HD float beckmannPdf(Vec3 n, Vec3 wo, Vec3 wi, float m) {
    if (!(dot(n, wi) > 0.0f) || !(dot(n, wo) > 0.0f)) return 0.0f;
    const Vec3 h = normalize(wo + wi);
    const float cosH = dot(n, h), oh = dot(wo, h);
    if (!(oh > 0.0f)) return 0.0f;
    return beckmannD(cosH, m) * cosH / (4.0f * oh);
}

}  // namespace trazo

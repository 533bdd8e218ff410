// SPEC §7's image transform: the stored and shown value is 2^Exposure × the pixel; 8-bit outputs and the viewer
// then apply the view transform (the identity, or sRGB's transfer function) before rounding. Host and device
// (the CUDA display writes its pixel buffer with it).
#pragma once

#include <cmath>
#include <cstdint>

#include "core/hd.h"
#include "core/integrator_kinds.h"

namespace trazo {

// Auto: linear under the thesis's integrator, sRGB under the path tracer (SPEC §7's default).
enum class ViewTransform : uint32_t { Auto, Linear, Srgb };

constexpr ViewTransform resolveViewTransform(ViewTransform t, IntegratorKind integrator) {
    if (t != ViewTransform::Auto) return t;
    return integrator == IntegratorKind::Thesis ? ViewTransform::Linear : ViewTransform::Srgb;
}

// What an 8-bit output and the viewer store for x (exposure applied): E(clamp(x, 0, 1)) in [0, 1].
struct DisplayTransform {
    float scale = 1.0f;  // 2^Exposure
    bool srgb = false;

    TRAZO_HD float encode(float x) const {
        x *= scale;
        x = x > 0.0f ? (x < 1.0f ? x : 1.0f) : 0.0f;  // NaN goes to 0
        if (!srgb) return x;
        return x <= 0.0031308f ? 12.92f * x : 1.055f * powf(x, 1.0f / 2.4f) - 0.055f;
    }
    TRAZO_HD bool identity() const { return scale == 1.0f && !srgb; }
};

inline DisplayTransform displayTransform(float exposureStops, ViewTransform t, IntegratorKind integrator) {
    return DisplayTransform{std::exp2(exposureStops), resolveViewTransform(t, integrator) == ViewTransform::Srgb};
}

}  // namespace trazo

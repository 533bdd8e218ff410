// ShadingPoint (host and device): made at a hit by surface.h (facingShadingPoint), read by the light
// integrators (direct_light.h, indirect_light.h) and the shadow packets (occluded_packet.h).
#pragma once

#include "core/hd.h"
#include "core/ray.h"
#include "core/vec3.h"

namespace trazo {

// Everything a shading point needs to send shadow rays and draw its strata.
struct ShadingPoint {
    Vec3 p;
    Vec3 ng;       // geometric normal turned towards the viewer
    Vec3 n;        // shading normal turned towards the viewer
    Vec3 v;        // towards the viewer
    float offset;  // how far along ng p's error bound reaches (offsetDistance, HitPoint::offset)
#if !TRAZO_DEVICE_PATHS
    Vec3 above;  // host: offsetRayOrigin towards +ng, where nearly every shadow and indirect ray leaves
#endif

    TRAZO_HD ShadingPoint(Vec3 pIn, float offsetIn, Vec3 ngIn, Vec3 nIn, Vec3 vIn)
        : p(pIn), ng(ngIn), n(nIn), v(vIn), offset(offsetIn) {
#if !TRAZO_DEVICE_PATHS
        above = bumpedOrigin(p, ng * offset);
#endif
    }
    // offsetRayOrigin(p, offset, ng, towards), bit for bit. The device recomputes it: a GPU thread's
    // registers are scarcer than its arithmetic (ptxas: caching it cost up to 12 registers a kernel).
    TRAZO_HD Vec3 rayOrigin(Vec3 towards) const {
        const bool below = dot(towards, ng) < 0.0f;
#if !TRAZO_DEVICE_PATHS
        if (!below) return above;
#endif
        return bumpedOrigin(p, below ? -(ng * offset) : ng * offset);
    }
};

}  // namespace trazo

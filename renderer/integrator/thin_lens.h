// The thin-lens camera of SPEC §6 (Depth of field), host and device: a point of the lens from one stratum of
// its equal-area polar grid, and the ray from that point through the pinhole ray's point on the focal plane.
#pragma once

#include <cmath>
#include <cstdint>

#include "core/sin_cos.h"
#include "integrator/camera_frame.h"

namespace trazo {

// A point of the unit disk, uniform (u1, u2 ∈ [0, 1)) within stratum `stratum` ∈ [0, 2q²) of the grid of q
// rings of equal area × 2q sectors (LensQuality q). Order: ring-major, ring i = stratum / 2q from the centre
// out, sector j = stratum mod 2q counter-clockwise from +x (the camera's right). Ring i is ρ² ∈ [i/q, (i+1)/q)
// and sector j is φ ∈ [πj/q, π(j+1)/q), so every stratum has area π/(2q²); ρ = √((i + u1)/q) is uniform in
// area within the ring (ρ = u would crowd the centre). Boundaries hold to float rounding. A q of 0 counts as 1
// (the scene's bounds exclude it; this keeps a kernel from dividing by zero).
TRAZO_HD void lensStratumPoint(uint32_t stratum, uint32_t q, float u1, float u2, float& x, float& y) {
    const uint32_t rings = q > 0u ? q : 1u;
    const uint32_t ring = stratum / (2u * rings), sector = stratum - ring * (2u * rings);
    const float rho = sqrtf((float(ring) + u1) / float(rings));
    float sinPhi, cosPhi;
    sinCos((float(sector) + u2) * (3.14159265358979f / float(rings)), sinPhi, cosPhi);
    x = rho * cosPhi;
    y = rho * sinPhi;
}

// The ray of image position (x, y) (pixels, as generateCameraRay) through lens point (lensX, lensY) of the unit
// disk: from POV + aperture·(lensX·right + lensY·up) towards POV + f·d/(d·forward), d the pinhole direction and
// f = focalDistance (the caller resolves §6's 0 to |POI − POV|). Every lens point's ray of one image position
// meets the pinhole ray on the plane at distance f along forward, so that plane is in focus; d·forward > 0
// for any field of view under 180°. The direction is formed relative to POV (focus offset − lens offset), so
// a camera far from the origin loses no precision to the subtraction. Aperture 0 returns the pinhole ray
// itself, bit for bit (§6: r = 0 is §5's pixel).
TRAZO_HD Ray thinLensRay(const CameraFrame& c, float x, float y, float aperture, float focalDistance, float lensX,
                         float lensY) {
    const Ray pinhole = generateCameraRay(c, x, y);
    if (aperture == 0.0f) return pinhole;
    const float forward = dot(pinhole.direction, c.forward);
    const Vec3 toFocus = pinhole.direction * (focalDistance / forward);
    const Vec3 toLens = (c.right * lensX + c.up * lensY) * aperture;
    const Vec3 direction = toFocus - toLens;
    // A focal distance beyond about 1e19 squares out of float: the same direction from both divided by it.
    if (!isFinite(dot(direction, direction)))
        return Ray{c.origin + toLens,
                   normalize(pinhole.direction * (1.0f / forward) - toLens * (1.0f / focalDistance))};
    return Ray{c.origin + toLens, normalize(direction)};
}

}  // namespace trazo

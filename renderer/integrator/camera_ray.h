// The camera ray of a sample: the antialiasing position in the pixel and, with SPEC §6's lens, a point of it.
// Shared by every integrator.
#pragma once

#include "core/render_settings.h"
#include "integrator/camera_frame.h"
#include "integrator/strata.h"
#include "integrator/thin_lens.h"

namespace trazo {

// Antialiasing position s of the k×k sub-pixel centres (SPEC §5 Pixel).
TRAZO_HD void antialiasingPosition(uint32_t k, uint32_t s, uint32_t px, uint32_t py, float& x, float& y) {
    x = float(px) + (float(s % k) + 0.5f) / float(k);
    y = float(py) + (float(s / k) + 0.5f) / float(k);
}

// The camera ray through image position (x, y): the pinhole's, or with a lens (SPEC §6) one point of a stratum
// of its 2q² strata, a grid of its own: position j of a pass's antialiasing block takes the lens block j places
// on, so the positions of one pass take different lens strata and each visits every one per 2q² passes.
TRAZO_HD Ray cameraRay(const CameraFrame& camera, const RenderSettings& s, float x, float y,
                       const StrataKey& pixelStrata, uint32_t j, SampleStream& rng) {
    if (s.aperture == 0.0f) return generateCameraRay(camera, x, y);
    const uint32_t q = s.lensQuality;
    const uint32_t stratum = pixelStrata.block(kGridLens, 2u * q * q, 1u, j).stratum(0);
    float lensX, lensY;
    const float u1 = rng.next();
    lensStratumPoint(stratum, q, u1, rng.next(), lensX, lensY);
    return thinLensRay(camera, x, y, s.aperture, s.focalDistance, lensX, lensY);
}

}  // namespace trazo

// Image output (host): writes a linear RGB image to .png/.bmp/.jpg/.tga (8-bit) or .exr/.hdr/.pfm (float).
#pragma once

#include <string>
#include <vector>

#include "core/vec3.h"
#include "core/view_transform.h"

namespace trazo {

enum class ImageFormat { Png, Bmp, Jpeg, Tga, Exr, Hdr, Pfm };

// Format from the file extension (case-insensitive: .png .bmp .jpg .jpeg .tga .exr .hdr .pfm); false if unknown.
bool imageFormatFromPath(const std::string& path, ImageFormat& format);
// Why imageFormatFromPath(path) fails, naming the extensions it knows: "'out.xyz': unknown image extension ...".
std::string unknownImageFormatReason(const std::string& path);

// Writes a linear RGB image, rows top to bottom (pixel (0,0) = top-left), through FreeImage, as SPEC §7's
// Image says with c = display.scale × the pixel (2^Exposure): 8-bit formats store round(255·E(clamp(c,0,1)))
// per channel, E the identity or sRGB's transfer function (display.srgb); NaN is written as 0, +inf as 255
// and -inf as 0. The default `display` is §5's output, round(255·clamp(pixel,0,1)) with no gamma. JPEG is
// lossy even at the best quality used here (4:4:4, "superb"), so only PNG, BMP and TGA hold those bytes
// exactly. .exr (32-bit float), .hdr (RGBE) and .pfm store c linear, without E (EXR and PFM exactly; RGBE to
// within ~1% of a pixel's largest channel, no negatives); a finite pixel whose c overflows is stored as ±FLT_MAX.
// PFM rows run bottom to top as the format requires (FreeImage's own PFM reader shows them upside down).
// Written through replaceAtomically (io/atomic_file.h): a failure never leaves a half-written file or a
// temporary behind, and an existing `path` stays as it was.
// Returns false with a plain reason in `error` on failure (unknown extension, bad size, missing or
// unwritable folder, FreeImage or disk failure).
bool writeImage(const std::string& path, int width, int height, const std::vector<Vec3>& rgbTopDown,
                std::string& error, const DisplayTransform& display = {});

}  // namespace trazo

// Partial renders on disk (docs/PARTIAL_FORMAT.md): a readable header (the fingerprint of everything that
// decides the image, the passes rendered, rays, seconds), the raw accumulation of both error-estimate halves,
// and an XXH64 checksum of all of it. Written atomically; a short or damaged file is an error that names it.
// Host code.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/accumulation.h"
#include "render/pass_range.h"
#include "scene/scene.h"

namespace trazo {

inline constexpr uint32_t kPartialFormatVersion = 1;

struct AssetHash {
    std::string path;  // as the scene resolved it (informative: a cluster node may mount it elsewhere)
    uint64_t hash = 0;  // XXH64 of the file's bytes
};

// Everything that decides a render's image: two partials merge only when these agree. Paths are kept for the
// reader; only the hashes are compared.
struct Fingerprint {
    std::string scenePath;
    uint64_t sceneHash = 0;           // XXH64 of the scene file's bytes
    std::vector<AssetHash> assets;    // textures, OBJ meshes, .csg files, in the scene's order
    uint32_t width = 0, height = 0;   // the render's size (--width/--height or the scene's)
    uint32_t seed = 0;
    std::string blocks;               // describeBlocks of the blocks the passes took (auto resolved)
    uint32_t fullCycle = 0;           // settings: fullCyclePasses, which sets the halves and strata windows
    std::string version;              // "trazo X.Y.Z"
    // SPEC §7's image transform, which the merge's image needs and the accumulation lacks: Exposure in stops and
    // the view transform resolved (auto → linear or srgb). In the header only when not 0 and linear, so files
    // of scenes without them are as before.
    float exposure = 0.0f;
    bool srgb = false;
};

// Hashes the scene file and every asset `scene` read (scenePath, sceneHash, assets); the caller sets the rest.
// False with "cannot read 'PATH': REASON".
bool hashSceneFiles(const Scene& scene, Fingerprint& out, std::string& error);

// "" when a and b agree; otherwise the first field that differs and both values, e.g. "seed (0 vs 7)". Fields:
// scene, assets, settings, size, seed, blocks, version, display.
std::string fingerprintDifference(const Fingerprint& a, const Fingerprint& b);

struct PartialHeader {
    Fingerprint fingerprint;
    std::vector<PassRange> passes;  // the passes the accumulation holds: joined ranges (one for a single render)
    PassRange requested;            // the passes asked for (a time limit or a signal may stop short of them)
    uint32_t parts = 1;             // partial renders merged into this one
    uint64_t rays = 0;
    double seconds = 0.0;           // render seconds (summed over parts)
    std::string backend;            // e.g. "cpu (2 CPU threads)"; "a; b" when parts differ
};

// Writes header + accumulation (width × height pixels, row 0 = top) through replaceAtomically. False with a
// message naming the file.
bool writePartialFile(const std::string& path, const PartialHeader& header, const std::vector<AccumPixel>& accum,
                      std::string& error);

// Reads and checks the header and the file's size against it, without reading the pixels. False with
// "PATH: REASON" (not a partial file, unknown format version, truncated: N bytes of M, ...).
bool readPartialHeader(const std::string& path, PartialHeader& header, std::string& error);

// Reads the whole file and checks its checksum; `accum` gets width × height pixels.
bool readPartialFile(const std::string& path, PartialHeader& header, std::vector<AccumPixel>& accum,
                     std::string& error);

// The same without holding the file's pixels: `take(first, pixels, count)` gets them in order, a few thousand
// at a time (a merge adds them to its total as they come, so it holds one image, not two). The checksum is
// known only at the end: on false, what `take` was given must be thrown away.
using TakePixels = std::function<void(size_t first, const AccumPixel* pixels, size_t count)>;
bool readPartialPixels(const std::string& path, PartialHeader& header, const TakePixels& take, std::string& error);

}  // namespace trazo

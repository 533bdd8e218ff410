// RenderStats: the seed's timing split plus counts, printed at the end and written by --stats as JSON.
#pragma once

#include <cmath>
#include <cstdint>
#include <string>

namespace trazo {

struct RenderStats {
    std::string scene;
    std::string backend, device;
    uint32_t width = 0, height = 0;
    uint32_t spp = 0;            // passes per pixel actually rendered
    uint32_t fullCycle = 0;      // passes of one full cycle of the scene's strata
    uint32_t seed = 0;
    std::string features;
    double parseSeconds = 0, uploadSeconds = 0, renderSeconds = 0;  // parseSeconds: all of scene creation
    double readSeconds = 0, buildSeconds = 0;  // scene creation's two parts: reading files (scene, OBJ, CSG,
                                               // textures), then building (flatten: meshes, BVHs)
    double writeSeconds = 0;  // writing the output: the image, or the partial file (--partial)
    double peakRssMb = 0;                      // the process's peak resident set (getrusage), at the end
    uint64_t rays = 0;
    bool fixedGrid = false;             // --fixed-grid
    std::string blocks;                 // describeBlocks of the strata a pass took
    double estimatedRelError = NAN;     // error_probe.h, or error_estimate.h's halves; NaN when neither can tell
    uint32_t probePixels = 0;           // the error probe's pixels (0: estimated from the halves)
    bool estimateBalanced = false;      // unbiased: from the probe, or from halves of whole 2-cycle windows
    bool noSamplingNoise = false;       // every pass is the same image: the error is 0 exactly
    double targetError = 0.0;           // --target-error (0 = none)
    bool reachedTarget = false;

    double mraysPerSecond() const { return renderSeconds > 0 ? rays / renderSeconds * 1e-6 : 0.0; }
};

std::string formatStatsSummary(const RenderStats& s);  // human-readable, a few lines
std::string formatStatsJson(const RenderStats& s);

// JSON values as the stats files write them: a quoted, escaped string; a number (%.6g), null when not finite.
std::string jsonString(const std::string& s);
std::string jsonNumber(double v);

// A stats file's JSON object, one `"key": value` a line, in the order added.
class JsonObject {
public:
    void add(const char* key, const std::string& value);
    std::string text() const { return "{\n" + body_ + "\n}\n"; }

private:
    std::string body_;
};

}  // namespace trazo

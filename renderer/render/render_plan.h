// What a headless render will do, decided before anything is allocated from what was asked and the flattened
// scene: its size and memory, its blocks and passes, whether it is noiseless, how it stops and what it says
// first. The one place a headless render is planned; the strata facts it shares with the viewer are
// strata_plan.h's. Pure: the CLI (app/headless_render.cpp) carries it out, the tests check it. Host code.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "flatten/scene_arrays.h"
#include "render/pass_range.h"
#include "render/progressive_render.h"
#include "render/strata_plan.h"
#include "scene/scene.h"

namespace trazo {

// The part of a command line that shapes a render (app/command_line.h says what each option means).
struct RenderRequest {
    std::optional<uint32_t> width, height;  // default: the scene's RenderWidth × RenderHeight
    std::optional<StrataBlocks> blocks;     // default: headlessBlocks
    std::optional<uint32_t> spp;
    std::optional<PassRange> passes;
    double seconds = 0.0;
    double targetError = 0.0;
    bool partial = false;  // a partial file of passes, to merge later, rather than an image
};

// The host memory a render of width × height holds besides the scene: the backend's accumulation (on the CPU
// backend; the CUDA backend holds it on the device), its copy read back for the image, and the resolved image.
// The writer's own buffer (at most 16 bytes a pixel) comes after the accumulation is freed.
constexpr uint64_t kHostBytesPerPixel = 2 * sizeof(AccumPixel) + sizeof(Vec3);

struct RenderPlan {
    uint32_t width = 0, height = 0;
    StrataBlocks blocks{};
    uint32_t fullCycle = 0;  // fullCyclePasses of the blocks: the halves' split
    // The passes to render. Default: one complete estimate (every stratum of every grid on the camera path
    // once: cameraPathPasses); bounded only by the time or the target error when either is given.
    PassRange range;
    bool defaultPasses = false;     // neither --spp nor --passes
    bool openEndedPartial = false;  // a partial render that only the time or the target error ends
    uint64_t hostBytes = 0;         // width · height · kHostBytesPerPixel
    std::string note;               // said before a long render ("" for none: a time limit bounds it already)
    bool noiseless = false;         // noSamplingNoise: the error is 0, and no probe is drawn

    uint64_t pixels() const { return uint64_t(width) * height; }
    // The progressive render's limits; `errorProbe`: whether the backend has a probe (partial renders take
    // none: their parts are merged, and the merge estimates from the halves).
    RenderLimits limits(const RenderRequest& request, bool errorProbe) const;
};

RenderPlan planRender(const RenderRequest& request, const Scene& scene, const SceneArrays& arrays);

// An estimate of the rays one pass traces for a pixel, from above: the pass's antialiasing positions, each a
// camera ray with its whole reflection chain (ReflectionSteps when the scene reflects) and transmission
// chain, each point of which takes its block of every light and of the indirect directions (each with its
// point Q's lights). Mirrors take no shadow rays, so a mirror chain costs less than this says.
double raysPerPixelPass(const SceneArrays& arrays, const StrataBlocks& blocks);

// The passes of a render without --spp, --time or --target-error (SPEC §7's path tracer takes at least this many).
constexpr uint32_t kPathDefaultPasses = 64;
uint32_t defaultPasses(const SceneArrays& arrays, const StrataBlocks& blocks);

// What a render of `passes` passes over width × height pixels will trace (raysPerPixelPass), and a line that
// says so before a long one: empty below kLongRenderRays.
constexpr double kLongRenderRays = 1e10;  // ~100 s at 100 Mrays/s (a CPU); a minute or so on a GPU
std::string longRenderNote(const SceneArrays& arrays, const StrataBlocks& blocks, uint32_t passes,
                           bool defaultPasses, uint32_t width, uint32_t height);

// Whether every pass of every seed renders the same image, so that its error is 0 and needs no estimate: the
// sample function draws no random number and picks no stratum (render variant 0: point lights only, without
// reflection, refraction, indirect light or SPEC §6's dispersion and subsurface scattering) at one antialiasing
// position, the pixel's centre, through a pinhole.
bool noSamplingNoise(const SceneArrays& arrays);

// Why --target-error cannot work with these limits ("" when it can): no probe, and strata that do not repeat
// within kMaxCyclePasses.
std::string targetErrorProblem(const RenderLimits& limits);

}  // namespace trazo

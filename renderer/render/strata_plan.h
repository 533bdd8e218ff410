// How a render walks the scene's stratified grids: the blocks each pass takes (integrator/strata.h) and the
// passes that make one full cycle of every grid. Host code.
#pragma once

#include <cstdint>
#include <string>

#include "flatten/scene_arrays.h"
#include "integrator/strata.h"
#include "scene/diagnostic.h"
#include "scene/scene.h"

namespace trazo {

constexpr uint32_t kMaxCyclePasses = 1u << 16;

// kMaxGridStrata, kMaxStrataQuality and kMaxReflectionSteps, the bounds checkRenderBounds applies, are in
// scene/scene.h beside the scene language's other limits.

// Reports (file:line of the parameter, else of its block or the scene) every setting above its bound; false
// when any is. Read-time bounds for the scene language: the render refuses, status 2, before any work.
bool checkRenderBounds(const Scene& scene, Diagnostics& diags);

// An estimate of the rays one pass traces for a pixel, from above: the pass's antialiasing positions, each a
// camera ray with its whole reflection chain (ReflectionSteps when the scene reflects) and transmission
// chain, each point of which takes its block of every light and of the indirect directions (each with its
// point Q's lights). Mirrors take no shadow rays, so a mirror chain costs less than this says.
double raysPerPixelPass(const SceneArrays& arrays, const StrataBlocks& blocks);

// What a render of `passes` passes over width × height pixels will trace (raysPerPixelPass), and a line that
// says so before a long one: empty below kLongRenderRays.
constexpr double kLongRenderRays = 1e10;  // ~100 s at 100 Mrays/s (a CPU); a minute or so on a GPU
std::string longRenderNote(const SceneArrays& arrays, const StrataBlocks& blocks, uint32_t passes,
                           bool defaultPasses, uint32_t width, uint32_t height);

// Passes for one full cycle of every stratified grid the scene uses (antialiasing positions, area-light
// cells at camera-path points and at indirect hits, glossy strata, indirect directions), each in its blocks:
// the least common multiple of the grids' block counts, capped at kMaxCyclePasses. After a cycle every
// stratum of every grid has been evaluated equally often.
uint32_t fullCyclePasses(const SceneArrays& arrays, const StrataBlocks& blocks);

// Passes for one cycle of the grids on the camera path only (antialiasing, area lights at camera-path points,
// glossy cones, indirect directions): the headless render's default. At indirect hits each direction then
// takes one block of the light, different directions different blocks.
uint32_t cameraPathPasses(const SceneArrays& arrays, const StrataBlocks& blocks);

// Whether every pass of every seed renders the same image, so that its error is 0 and needs no estimate: the
// sample function draws no random number and picks no stratum (render variant 0: point lights only, without
// reflection, refraction, indirect light or SPEC §6's dispersion and subsurface scattering) at one antialiasing
// position, the pixel's centre, through a pinhole.
bool noSamplingNoise(const SceneArrays& arrays);

// The blocks a headless render takes, chosen from measurement: see the definition for the rule and its numbers.
StrataBlocks headlessBlocks(const SceneArrays& arrays);

// Each target at most the largest grid of its kind in the scene (1 for a kind it lacks): the same blocks,
// and no growth past what changes anything.
StrataBlocks clampToScene(const SceneArrays& arrays, const StrataBlocks& blocks);

// --blocks: "1" (one stratum of every grid per pass), "whole" (every stratum: the thesis's estimator), or
// four targets "AA,LIGHT,INDIRECT,LIGHT_AT_INDIRECT" (positive integers or "whole"). False with the reason.
bool parseStrataBlocks(const std::string& text, StrataBlocks& out, std::string& why);
std::string describeBlocks(const StrataBlocks& blocks);  // the four targets, as parseStrataBlocks reads them

}  // namespace trazo

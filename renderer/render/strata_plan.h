// How a render walks the scene's stratified grids: the blocks each pass takes (integrator/strata.h), the
// passes that make one full cycle of every grid, and the grids' read-time bounds. Shared by the headless
// render's plan (render_plan.h) and the viewer, which grows its blocks up to headlessBlocks. Host code.
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

// Passes for one full cycle of every stratified grid the scene uses (antialiasing positions, area-light
// cells at camera-path points and at indirect hits, glossy strata, indirect directions), each in its blocks:
// the least common multiple of the grids' block counts, capped at kMaxCyclePasses. After a cycle every
// stratum of every grid has been evaluated equally often.
uint32_t fullCyclePasses(const SceneArrays& arrays, const StrataBlocks& blocks);

// Passes for one cycle of the grids on the camera path only (antialiasing, area lights at camera-path points,
// glossy cones, indirect directions): the headless render's default. At indirect hits each direction then
// takes one block of the light, different directions different blocks.
uint32_t cameraPathPasses(const SceneArrays& arrays, const StrataBlocks& blocks);

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

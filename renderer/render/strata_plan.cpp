#include "render/strata_plan.h"

#include <algorithm>
#include <charconv>
#include <initializer_list>
#include <numeric>
#include <vector>

#include "core/feature_mask.h"
#include "integrator/strata.h"

namespace trazo {

namespace {

// The camera lens's strata (SPEC §6): 2q², one a pass at each antialiasing position; 1 for a pinhole.
uint64_t lensStrata(const RenderSettings& s) {
    return s.aperture > 0.0f ? 2 * (uint64_t)s.lensQuality * s.lensQuality : 1u;
}

// The grids that take one stratum a pass cycle together: glossy cones (2q²), the camera's lens and a
// dispersing ray's colour channel (SPEC §6: the three in turn).
uint64_t unblockedPasses(const SceneArrays& a) {
    const uint64_t q = a.settings.reflectionQuality;
    const uint64_t glossy = (a.features & kFeatureGlossy) && q > 0 ? 2 * q * q : 1u;
    const uint64_t channels = (a.features & kFeatureDispersion) ? 3u : 1u;
    return std::min<uint64_t>(std::lcm(std::lcm(glossy, lensStrata(a.settings)), channels), kMaxCyclePasses);
}

// The path tracer's grids (SPEC §7), one stratum a pass each: the antialiasing cells, the lens and each area
// light's Subdivision cells.
uint32_t pathCyclePasses(const SceneArrays& a) {
    const uint64_t k = antialiasingSide(a.settings.antialiasing);
    uint64_t cycle = std::lcm(k * k, lensStrata(a.settings));
    for (const AreaLightData& l : a.areaLights)
        cycle = std::min<uint64_t>(std::lcm(cycle, (uint64_t)l.cellsU * l.cellsV), kMaxCyclePasses);
    return (uint32_t)std::min<uint64_t>(cycle, kMaxCyclePasses);
}

// The lcm of the passes of the grids on the camera path, and with atIndirect of the grids at indirect hits.
uint32_t cyclePasses(const SceneArrays& a, const StrataBlocks& blocks, bool atIndirect) {
    if (a.settings.integrator == IntegratorKind::Path) return pathCyclePasses(a);
    uint64_t cycle = 1;
    auto include = [&](uint64_t count, uint32_t target) {
        if (count == 0) return;
        const uint64_t passes = count > UINT32_MAX ? count : blockPasses((uint32_t)count, target);
        cycle = std::min<uint64_t>(std::lcm(cycle, passes), kMaxCyclePasses);
    };
    const uint64_t k = antialiasingSide(a.settings.antialiasing);
    include(k * k, blocks.antialiasing);
    const bool indirect = (a.features & kFeatureIndirect) && a.settings.indirectQuality > 0;
    for (const AreaLightData& l : a.areaLights) {
        include((uint64_t)l.cellsU * l.cellsV, blocks.areaLight);
        if (indirect && atIndirect) include((uint64_t)l.cellsU * l.cellsV, blocks.lightAtIndirect);
    }
    include(unblockedPasses(a), 1u);
    const uint64_t qi = a.settings.indirectQuality;
    if (indirect) include(2 * qi * qi, blocks.indirect);
    return (uint32_t)cycle;
}

}  // namespace

uint32_t fullCyclePasses(const SceneArrays& a, const StrataBlocks& blocks) { return cyclePasses(a, blocks, true); }

uint32_t cameraPathPasses(const SceneArrays& a, const StrataBlocks& blocks) { return cyclePasses(a, blocks, false); }

// Measured on the seed scenes (time × two-seed variance of `--blocks` choices: bench/peers/blocks_sweep.sh;
// bench/peers/thesis_table.sh compares the result with the fixed grid on all of them): a grid on the camera path is worth a whole block whenever nothing
// above it must cycle, because the rays above it are then traced once. Glossy cones cycle one stratum per
// pass (2q² passes), so the other camera-path grids take blocks that complete once in those passes. At indirect hits one cell per
// direction, rotated so a pass's directions take different cells, beats the thesis's every-cell fan by 3×
// in time × variance on scene 9 (the fan spends 25 shadow rays where the direction's own variance dominates).
StrataBlocks headlessBlocks(const SceneArrays& a) {
    if (a.settings.integrator == IntegratorKind::Path) return StrataBlocks::ones();  // one stratum a pass
    const uint32_t unblocked = (uint32_t)unblockedPasses(a);
    auto completingIn = [&](uint64_t count) {  // the block that completes a grid of `count` in `unblocked` passes
        if (count == 0 || count > UINT32_MAX) return 1u;
        return (uint32_t)(count / std::gcd(count, (uint64_t)unblocked));
    };
    StrataBlocks b;
    const uint64_t k = antialiasingSide(a.settings.antialiasing);
    b.antialiasing = completingIn(k * k);
    b.areaLight = 1;
    for (const AreaLightData& l : a.areaLights)
        b.areaLight = std::max(b.areaLight, completingIn((uint64_t)l.cellsU * l.cellsV));
    b.indirect = kWholeGrid;
    b.lightAtIndirect = 1;
    return clampToScene(a, b);
}

namespace {

SourceLocation firstGiven(std::initializer_list<const SourceLocation*> places, const std::string& scenePath) {
    for (const SourceLocation* at : places)
        if (!at->file.empty()) return *at;
    return SourceLocation{scenePath, 0, 0};
}

}  // namespace

bool checkRenderBounds(const Scene& scene, Diagnostics& diags) {
    bool ok = true;
    const SceneSettings& s = scene.settings;
    const std::string bound = std::to_string(kMaxGridStrata);
    auto quality = [&](const char* name, int q, const SourceLocation& at) {
        const uint64_t strata = 2 * (uint64_t)std::max(q, 0) * (uint64_t)std::max(q, 0);
        if (strata <= kMaxGridStrata) return;
        diags.error(firstGiven({&at, &s.where}, scene.path),
                    std::string(name) + " " + std::to_string(q) + " asks for 2·q² = " + std::to_string(strata) +
                        " strata; at most " + bound + " (q ≤ " + std::to_string(kMaxStrataQuality) +
                        ") are allowed");
        ok = false;
    };
    quality("ReflectionQuality", s.reflectionQuality, s.reflectionQualityAt);
    quality("IndirectQuality", s.indirectQuality, s.indirectQualityAt);
    quality("LensQuality", scene.camera.lensQuality, scene.camera.lensQualityAt);
    if ((uint64_t)std::max(s.reflectionSteps, 0) > kMaxReflectionSteps) {
        diags.error(firstGiven({&s.reflectionStepsAt, &s.where}, scene.path),
                    "ReflectionSteps " + std::to_string(s.reflectionSteps) + " is more than the " +
                        std::to_string(kMaxReflectionSteps) + " reflections a ray may take");
        ok = false;
    }
    for (const AreaLight& l : scene.areaLights) {
        const uint64_t cells = (uint64_t)std::max(l.subdivisionX, 0) * (uint64_t)std::max(l.subdivisionY, 0);
        if (cells <= kMaxGridStrata) continue;
        diags.error(firstGiven({&l.subdivisionAt, &l.where}, scene.path),
                    "Subdivision " + std::to_string(l.subdivisionX) + " " + std::to_string(l.subdivisionY) + " asks for " +
                        std::to_string(cells) + " cells; an area light has at most " + bound + " (e.g. " +
                        std::to_string(kMaxGridSide) + " " + std::to_string(kMaxGridSide) + ")");
        ok = false;
    }
    return ok;
}

StrataBlocks clampToScene(const SceneArrays& a, const StrataBlocks& b) {
    const uint64_t k = antialiasingSide(a.settings.antialiasing);
    const bool indirect = (a.features & kFeatureIndirect) && a.settings.indirectQuality > 0;
    uint64_t cells = 1;
    for (const AreaLightData& l : a.areaLights) cells = std::max<uint64_t>(cells, (uint64_t)l.cellsU * l.cellsV);
    const uint64_t qi = a.settings.indirectQuality;
    auto clamp = [](uint32_t target, uint64_t largest) { return (uint32_t)std::min<uint64_t>(target, largest); };
    return StrataBlocks{clamp(b.antialiasing, k * k), clamp(b.areaLight, a.areaLights.empty() ? 1 : cells),
                        clamp(b.indirect, indirect ? 2 * qi * qi : 1), clamp(b.lightAtIndirect, indirect ? cells : 1)};
}

namespace {

bool parseTarget(const std::string& text, uint32_t& out) {
    if (text == "whole") {
        out = kWholeGrid;
        return true;
    }
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, out);
    return ec == std::errc() && ptr == end && out >= 1;
}

std::string describeTarget(uint32_t t) { return t == kWholeGrid ? "whole" : std::to_string(t); }

}  // namespace

bool parseStrataBlocks(const std::string& text, StrataBlocks& out, std::string& why) {
    std::vector<std::string> parts;
    for (size_t start = 0;;) {
        const size_t comma = text.find(',', start);
        parts.push_back(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    uint32_t t[4];
    if (parts.size() == 1 && parseTarget(parts[0], t[0])) {
        t[1] = t[2] = t[3] = t[0];
    } else if (parts.size() == 4 && parseTarget(parts[0], t[0]) && parseTarget(parts[1], t[1]) &&
               parseTarget(parts[2], t[2]) && parseTarget(parts[3], t[3])) {
    } else {
        why = "expected auto, one target, or four comma-separated targets (each a positive integer or whole)";
        return false;
    }
    out = StrataBlocks{t[0], t[1], t[2], t[3]};
    return true;
}

std::string describeBlocks(const StrataBlocks& b) {
    return describeTarget(b.antialiasing) + "," + describeTarget(b.areaLight) + "," + describeTarget(b.indirect) +
           "," + describeTarget(b.lightAtIndirect);
}

}  // namespace trazo

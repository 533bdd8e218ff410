#include "render/render_plan.h"

#include <algorithm>
#include <cstdio>

#include "core/feature_mask.h"
#include "integrator/sample_variants.h"

namespace trazo {

namespace {

std::string formatCount(double x) {
    char text[32];
    if (x < 1e6) std::snprintf(text, sizeof text, "%.0f", x);
    else std::snprintf(text, sizeof text, "%.2g", x);
    return text;
}

}  // namespace

bool noSamplingNoise(const SceneArrays& a) {
    return sampleVariantFor(a.settings.integrator, a.features) == 0 &&
           antialiasingSide(a.settings.antialiasing) == 1 &&
           a.settings.aperture == 0.0f;
}

double raysPerPixelPass(const SceneArrays& a, const StrataBlocks& blocks) {
    auto blockOf = [](uint64_t count, uint32_t target) -> double {
        return count > UINT32_MAX ? (double)count : (double)blockFor((uint32_t)count, target);
    };
    auto lightRays = [&](uint32_t target) {
        double rays = (double)a.pointLights.size();
        for (const AreaLightData& l : a.areaLights) rays += blockOf((uint64_t)l.cellsU * l.cellsV, target);
        return rays;
    };
    double perHit = lightRays(blocks.areaLight);
    const uint64_t qi = a.settings.indirectQuality;
    if ((a.features & kFeatureIndirect) && qi > 0)
        perHit += blockOf(2 * qi * qi, blocks.indirect) * (1.0 + lightRays(blocks.lightAtIndirect));
    double chain = 1.0;
    if (a.features & (kFeatureReflection | kFeatureGlossy))
        chain += (double)std::min<uint64_t>(a.settings.reflectionSteps, kMaxReflectionDepth);
    if (a.features & kFeatureRefraction) chain += (double)kMaxTransmissionSegments;
    const uint64_t k = antialiasingSide(a.settings.antialiasing);
    return blockOf(k * k, blocks.antialiasing) * chain * (1.0 + perHit);
}

std::string longRenderNote(const SceneArrays& a, const StrataBlocks& blocks, uint32_t passes, bool defaultPasses,
                           uint32_t width, uint32_t height) {
    const double perPixelPass = raysPerPixelPass(a, blocks);
    const double rays = perPixelPass * passes * width * height;
    if (rays < kLongRenderRays) return {};
    std::string note = "this render will trace up to about " + formatCount(rays) + " rays: " +
                       std::to_string(passes) + (passes == 1 ? " pass" : " passes");
    if (defaultPasses) {
        note += passes >= kMaxCyclePasses ? " (the default: the scene's strata cycle, cut at " +
                                                std::to_string(kMaxCyclePasses) + " passes)"
                                          : " (the default: one full cycle of the scene's strata)";
    }
    note += " of up to " + formatCount(perPixelPass) + " rays a pixel, " + std::to_string(width) + "×" +
            std::to_string(height) + " pixels; --spp or --time renders less";
    return note;
}

// What a render without --spp, --time or --target-error takes: one full cycle of the camera path's strata; under
// the path tracer, whose cycle may be one pass, the fewest whole cycles of at least kPathDefaultPasses.
uint32_t defaultPasses(const SceneArrays& arrays, const StrataBlocks& blocks) {
    const uint32_t cycle = cameraPathPasses(arrays, blocks);
    if (arrays.settings.integrator != IntegratorKind::Path || cycle >= kPathDefaultPasses) return cycle;
    return (kPathDefaultPasses + cycle - 1) / cycle * cycle;
}

RenderPlan planRender(const RenderRequest& request, const Scene& scene, const SceneArrays& arrays) {
    RenderPlan plan;
    plan.width = request.width.value_or(uint32_t(scene.settings.renderWidth));
    plan.height = request.height.value_or(uint32_t(scene.settings.renderHeight));
    plan.hostBytes = plan.pixels() * kHostBytesPerPixel;
    plan.blocks = request.blocks.value_or(headlessBlocks(arrays));
    plan.fullCycle = fullCyclePasses(arrays, plan.blocks);
    plan.noiseless = noSamplingNoise(arrays);
    const uint32_t cameraPasses = defaultPasses(arrays, plan.blocks);
    const bool openEnded = request.seconds > 0 || request.targetError > 0;
    plan.defaultPasses = !request.spp && !request.passes;
    plan.openEndedPartial = request.partial && plan.defaultPasses && openEnded;
    const uint32_t defaultEnd = request.spp ? *request.spp : (openEnded ? kMaxProgressivePasses : cameraPasses);
    plan.range = request.passes ? *request.passes : PassRange{0, defaultEnd};
    if (request.seconds <= 0) {
        const uint32_t passes = request.targetError > 0 ? cameraPasses : plan.range.count();
        plan.note = longRenderNote(arrays, plan.blocks, passes, plan.defaultPasses, plan.width, plan.height);
    }
    return plan;
}

RenderLimits RenderPlan::limits(const RenderRequest& request, bool errorProbe) const {
    RenderLimits l;
    l.seconds = request.seconds;
    l.targetError = request.targetError;
    l.cyclePasses = fullCycle;
    l.errorProbe = !request.partial && errorProbe && !noiseless;
    l.noiseless = noiseless;
    l.passes = range.count();
    l.firstPass = range.first;
    return l;
}

std::string targetErrorProblem(const RenderLimits& limits) {
    if (limits.targetError <= 0 || limits.noiseless || limits.errorProbe || splitsHalves(limits.cyclePasses)) return "";
    return "this scene's strata do not repeat within " + std::to_string(kMaxCyclePasses) +
           " passes, so its error cannot be estimated; use --spp or --time";
}

}  // namespace trazo

#include "render/render_plan.h"

namespace trazo {

RenderPlan planRender(const RenderRequest& request, const Scene& scene, const SceneArrays& arrays) {
    RenderPlan plan;
    plan.width = request.width.value_or(uint32_t(scene.settings.renderWidth));
    plan.height = request.height.value_or(uint32_t(scene.settings.renderHeight));
    plan.hostBytes = plan.pixels() * kHostBytesPerPixel;
    plan.blocks = request.blocks.value_or(headlessBlocks(arrays));
    plan.fullCycle = fullCyclePasses(arrays, plan.blocks);
    plan.noiseless = noSamplingNoise(arrays);
    const uint32_t cameraPasses = cameraPathPasses(arrays, plan.blocks);
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

// What the Render panel shows, read from the session and the display.
#include "view/render_info.h"

#include "render/strata_plan.h"

namespace trazo {

RenderInfo describeRender(ViewerSession& session, const Display& display, bool cudaBuilt) {
    RenderInfo info;
    info.backend = session.backend().name();
    info.device = session.backend().deviceName();
    info.displayPath = displayPathName(display.path());
    if (!display.interopFailure().empty() && display.path() == DisplayPath::Host && info.backend == "cuda")
        info.displayPath += " (interop: " + display.interopFailure() + ")";
    info.cudaBuilt = cudaBuilt;
    info.width = session.renderWidth();
    info.height = session.renderHeight();
    if (session.previewDivisor() > 1) info.displayPath += ", preview at 1/" + std::to_string(session.previewDivisor());
    info.passes = session.accumulation().passes();
    info.cyclePasses = session.accumulation().cyclePasses();
    info.samples = session.accumulation().samples();
    info.blocks = describeBlocks(session.accumulation().blocks());
    info.elapsedSeconds = session.accumulation().renderSeconds();
    if (info.elapsedSeconds > 0) {
        info.samplesPerSecond = info.samples * info.width * info.height / info.elapsedSeconds;
        info.mraysPerSecond = double(session.accumulation().rays()) / info.elapsedSeconds * 1e-6;
    }
    for (const Diagnostic& d : session.flattenWarnings().items) info.unsupported.push_back(formatDiagnostic(d));
    for (const ConvergencePoint& p : session.accumulation().convergence())
        info.convergence.emplace_back(p.seconds, p.relError);
    info.targetReached = session.accumulation().targetReached();
    return info;
}

}  // namespace trazo

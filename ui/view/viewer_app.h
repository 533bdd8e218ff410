// runViewer(): the interactive viewer's entry point (`trazo SCENE`), the frame loop that wires the window,
// the display, the panels and the session together.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "backends/backend.h"
#include "integrator/strata.h"

namespace trazo {

struct ViewerOptions {
    std::string scenePath;
    BackendChoice backend = BackendChoice::Auto;
    unsigned threads = 0;
    uint32_t seed = 0;
    uint32_t width = 0, height = 0;  // 0: the scene's RenderWidth / RenderHeight
    std::optional<uint32_t> frames;  // automation: run this many passes, save `screenshot` (if any), exit
    std::string screenshot;          // --screenshot: the automation's output, else the screenshot key's default
    bool quiet = false;              // no start and exit lines
    std::optional<StrataBlocks> blocks;  // --blocks: fixed blocks; none: one stratum per pass, growing
};

// Exit status: 0 (closed, or automation done), 1 (no display or GL, backend or file failure), 2 (bad scene).
int runViewer(const ViewerOptions& options);

}  // namespace trazo

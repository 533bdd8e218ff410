// trazo: headless render (--render), merge of partial renders (merge), or the interactive viewer (SCENE, with
// --frames/--screenshot for automation).
#include <cstdio>
#include <cstring>

#include "command_line.h"
#include "headless_render.h"
#include "merge_command.h"
#if defined(TRAZO_HAS_VIEWER)
#include "view/viewer_app.h"
#endif

int main(int argc, char** argv) {
    if (argc > 1 && std::strcmp(argv[1], "merge") == 0) {
        trazo::MergeCommandLine merge;
        if (auto status = trazo::parseMergeCommandLine(argc - 1, argv + 1, merge)) return *status;
        return trazo::runMerge(merge);
    }
    trazo::CommandLine options;
    if (auto status = trazo::parseCommandLine(argc, argv, options)) return *status;
    if (!options.renderScene.empty()) return trazo::runHeadlessRender(options);
#if defined(TRAZO_HAS_VIEWER)
    trazo::ViewerOptions viewer;
    viewer.scenePath = options.viewerScene;
    viewer.backend = options.backend;
    viewer.threads = options.threads;
    viewer.seed = options.seed;
    viewer.width = options.request.width.value_or(0);
    viewer.height = options.request.height.value_or(0);
    viewer.frames = options.frames;
    viewer.screenshot = options.screenshot;
    viewer.quiet = options.quiet;
    viewer.blocks = options.request.blocks;
    return trazo::runViewer(viewer);
#else
    std::fprintf(stderr,
                 "trazo: this build has no viewer (GLFW, Dear ImGui or python3-glad were missing); render headless "
                 "with `trazo --render %s -o image.png`\n",
                 options.viewerScene.c_str());
    return 1;
#endif
}

// trazo: headless render (--render) or, in a later issue, the interactive viewer.
#include <cstdio>

#include "command_line.h"
#include "headless_render.h"

int main(int argc, char** argv) {
    trazo::CommandLine options;
    if (auto status = trazo::parseCommandLine(argc, argv, options)) return *status;
    if (!options.renderScene.empty()) return trazo::runHeadlessRender(options);
    std::fprintf(stderr,
                 "trazo: the interactive viewer is not part of this build yet; render headless with "
                 "`trazo --render %s -o image.png`\n",
                 options.viewerScene.c_str());
    return 1;
}

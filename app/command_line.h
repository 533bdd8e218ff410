// The command line (README.md "Using it"), parsed into plain options (CLI11 stays in one file).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "backends/backend.h"
#include "integrator/strata.h"
#include "render/pass_range.h"
#include "render/render_plan.h"

namespace trazo {

struct CommandLine {
    std::string renderScene;  // --render SCENE (headless)
    std::string viewerScene;  // positional SCENE (viewer)
    std::string output = "out.bmp";
    // What to render: --width, --height, --spp, --time, --target-error, --passes A:B (the same samples as those
    // passes of --spp B), and --blocks (parseStrataBlocks; whole with --fixed-grid; none, "auto": the render's
    // own choice, headlessBlocks, or the viewer's growing blocks). `partial` follows --partial.
    RenderRequest request;
    bool fixedGrid = false;  // --fixed-grid: every stratum of every grid in each pass, as the thesis did
    BackendChoice backend = BackendChoice::Auto;
    unsigned threads = 0;
    uint32_t seed = 0;
    std::string statsPath;
    bool quiet = false;
    std::optional<uint32_t> frames;  // viewer automation: run N passes in the window, save --screenshot, exit
    std::string screenshot;          // viewer: the automation's image, else the screenshot key's default name
    // --partial: the accumulation of the passes goes to this file instead of an image (docs/PARTIAL_FORMAT.md).
    std::string partialPath;
    // --devices all|0,1 (with --backend cuda): split each batch of passes over these CUDA devices.
    struct DeviceList {
        bool all = false;
        std::vector<int> ids;
    };
    std::optional<DeviceList> devices;
};

// trazo merge PARTS... [-o IMAGE] [--stats FILE] [--allow-gaps] [--partial FILE] [--passes A:B] [--quiet]
struct MergeCommandLine {
    std::vector<std::string> parts;
    std::string output;       // -o: the merged image (any format --render writes)
    std::string statsPath;    // --stats: JSON, the keys of --render's where they apply, plus "parts"
    std::string partialPath;  // --partial: the merged accumulation as a partial file again
    bool allowGaps = false;
    std::optional<PassRange> passes;  // the passes the parts must cover (default: 0 to the last asked for)
    bool quiet = false;
};

// Parses argv. Returns the exit status to stop with (0 after --help/--version, 2 on bad usage, with the
// message already printed), or nothing when the program should go on.
std::optional<int> parseCommandLine(int argc, char** argv, CommandLine& out);
// The same for `trazo merge` (argv[0] is "merge").
std::optional<int> parseMergeCommandLine(int argc, char** argv, MergeCommandLine& out);

}  // namespace trazo

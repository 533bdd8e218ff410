// CLI11 parsing of the trazo command line (the only file that includes CLI11: it is slow to compile).
#include "command_line.h"

#include <CLI/CLI.hpp>

#include "render/progressive_render.h"
#include "render/strata_plan.h"
#include "scene/scene.h"

namespace trazo {

namespace {

// "all" or device numbers separated by commas, each once.
bool parseDevices(const std::string& text, CommandLine::DeviceList& out, std::string& why) {
    out = CommandLine::DeviceList{};
    if (text == "all") {
        out.all = true;
        return true;
    }
    size_t at = 0;
    while (at <= text.size()) {
        size_t comma = text.find(',', at);
        if (comma == std::string::npos) comma = text.size();
        const std::string item = text.substr(at, comma - at);
        if (item.empty() || item.size() > 4 || item.find_first_not_of("0123456789") != std::string::npos) {
            why = "expected all, or CUDA device numbers separated by commas (e.g. 0,1)";
            return false;
        }
        const int id = std::stoi(item);
        for (int seen : out.ids)
            if (seen == id) {
                why = "device " + item + " is listed twice";
                return false;
            }
        out.ids.push_back(id);
        at = comma + 1;
    }
    return true;
}

// --passes A:B (none when not given) into `out`; false after printing why, after `prefix` ("trazo: merge").
bool readPassesOption(const std::string& text, const char* prefix, std::optional<PassRange>& out) {
    if (text.empty()) return true;
    PassRange range;
    std::string why;
    if (!parsePassRange(text, range, why, kMaxProgressivePasses)) {
        std::fprintf(stderr, "%s: --passes %s: %s\n", prefix, text.c_str(), why.c_str());
        return false;
    }
    out = range;
    return true;
}

}  // namespace

namespace {

// Options whose text is read after parsing (they need more than CLI11's checks).
struct OptionText {
    std::string blocks = "auto", passes, devices;
};

void declareOptions(CLI::App& app, CommandLine& out, OptionText& text) {
    app.set_version_flag("--version", "trazo " TRAZO_VERSION);
    app.footer("trazo merge PARTS... -o IMAGE merges partial renders (--partial) into one image: trazo merge --help");
    app.add_option("SCENE", out.viewerScene, "Scene to open in the interactive viewer");
    app.add_option("--render", out.renderScene, "Render SCENE headless to a file")->type_name("SCENE");
    app.add_option("-o,--output", out.output, "Output image; format by extension (png bmp jpg tga exr hdr pfm)")
        ->capture_default_str();
    app.add_option("--spp", out.request.spp, "Passes per pixel (default: one full cycle of the scene's strata)")
        ->check(CLI::Range(1u, 1u << 24));
    app.add_option("--time", out.request.seconds, "Stop after this wall time in seconds (with --spp: whichever first)")
        ->check(CLI::PositiveNumber);
    app.add_option("--target-error", out.request.targetError,
                   "Stop once the estimated relative RMS error of the image falls below this (e.g. 0.01)")
        ->check(CLI::Range(1e-6, 1.0));
    app.add_flag("--fixed-grid", out.fixedGrid,
                 "The thesis's estimator: every pass evaluates every stratum of every grid (for comparisons)");
    app.add_option("--blocks", text.blocks,
                   "Strata of each grid per pass: auto (measured per scene), 1, whole (= --fixed-grid), or "
                   "AA,LIGHT,INDIRECT,LIGHT_AT_INDIRECT targets, e.g. 1,100,1,5")
        ->capture_default_str();
    const std::map<std::string, BackendChoice> backends{
        {"auto", BackendChoice::Auto}, {"cpu", BackendChoice::Cpu}, {"cuda", BackendChoice::Cuda}};
    app.add_option("--backend", out.backend, "auto (CUDA when a device is present), cpu or cuda")
        ->transform(CLI::CheckedTransformer(backends, CLI::ignore_case));
    app.add_option("--threads", out.threads, "CPU threads (default: all cores)")->check(CLI::Range(1u, 4096u));
    app.add_option("--seed", out.seed, "Random seed; the same seed gives the same image");
    const CLI::Range renderSize(1u, unsigned(kMaxRenderSize));
    app.add_option("--width", out.request.width, "Override RenderWidth")->check(renderSize);
    app.add_option("--height", out.request.height, "Override RenderHeight")->check(renderSize);
    app.add_option("--stats", out.statsPath, "Write timings and counts as JSON to this file");
    app.add_flag("--quiet", out.quiet, "No progress bar");
    app.add_option("--frames", out.frames, "Viewer: run N passes in the window, save --screenshot, exit 0")
        ->check(CLI::Range(1u, 1u << 24))
        ->type_name("N");
    app.add_option("--passes", text.passes,
                   "Render passes A to B-1 (A:B): the same samples as those passes of --spp B; with --partial, "
                   "for a merge")
        ->type_name("A:B");
    app.add_option("--partial", out.partialPath,
                   "Write the raw accumulation of the passes (docs/PARTIAL_FORMAT.md) for `trazo merge`, no image")
        ->type_name("FILE");
    app.add_option("--devices", text.devices, "With --backend cuda: split the passes over these CUDA devices (all, or 0,1)")
        ->type_name("all|N,N");
    app.add_option("--screenshot", out.screenshot,
                   "Viewer: image written after --frames passes (else the screenshot key's default name)")
        ->type_name("FILE");

}

// --blocks, --passes and --devices from their text into `out`; false after saying why.
bool readOptionText(const OptionText& text, CommandLine& out) {
    if (out.fixedGrid) {
        out.request.blocks = StrataBlocks::whole();
    } else if (text.blocks != "auto") {
        StrataBlocks parsed;
        std::string why;
        if (!parseStrataBlocks(text.blocks, parsed, why)) {
            std::fprintf(stderr, "trazo: --blocks %s: %s\n", text.blocks.c_str(), why.c_str());
            return false;
        }
        out.request.blocks = parsed;
    }
    if (!readPassesOption(text.passes, "trazo", out.request.passes)) return false;
    if (!text.devices.empty()) {
        CommandLine::DeviceList list;
        std::string why;
        if (!parseDevices(text.devices, list, why)) {
            std::fprintf(stderr, "trazo: --devices %s: %s\n", text.devices.c_str(), why.c_str());
            return false;
        }
        out.devices = list;
    }
    out.request.partial = !out.partialPath.empty();
    return true;
}

// Why the options given together make no command (null when they do). `outputGiven`: -o was on the line.
const char* conflictIn(const CommandLine& out, bool outputGiven) {
    const bool splitRender = out.request.passes || !out.partialPath.empty() || out.devices;
    if (!out.viewerScene.empty() && splitRender)
        return "trazo: --passes, --partial and --devices are for headless renders (`trazo --render SCENE`)\n";
    if (out.request.passes && out.request.spp)
        return "trazo: give either --spp N or --passes A:B (--spp N renders passes 0:N)\n";
    if (!out.partialPath.empty() && outputGiven)
        return "trazo: --partial writes the passes' accumulation, not an image: leave out -o (make the image "
               "with `trazo merge PARTS... -o IMAGE`)\n";
    if ((out.request.passes || !out.partialPath.empty()) && out.request.targetError > 0)
        return "trazo: --target-error needs the whole render's error: it cannot stop a part of one (--passes, "
               "--partial); use --spp or --time\n";
    if (out.devices && out.backend != BackendChoice::Cuda)
        return "trazo: --devices chooses CUDA devices: it needs --backend cuda\n";
    if (out.renderScene.empty() && out.viewerScene.empty())
        return "trazo: no scene given; try `trazo --render SCENE -o image.png` or `trazo --help`\n";
    if (!out.renderScene.empty() && !out.viewerScene.empty())
        return "trazo: give the scene either to --render or as the viewer's SCENE, not both\n";
    if (!out.renderScene.empty() && (out.frames || !out.screenshot.empty()))
        return "trazo: --frames and --screenshot are for the viewer (`trazo SCENE --frames N --screenshot FILE`); "
               "with --render use --spp and -o\n";
    return nullptr;
}

}  // namespace

std::optional<int> parseCommandLine(int argc, char** argv, CommandLine& out) {
    CLI::App app{"Trazo: a ray tracer for the scene language of SPEC.md, on CPU and CUDA", "trazo"};
    OptionText text;
    declareOptions(app, out, text);
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        app.exit(e);
        return 2;
    }
    if (!readOptionText(text, out)) return 2;
    if (const char* conflict = conflictIn(out, app.count("--output") > 0)) {
        std::fputs(conflict, stderr);
        return 2;
    }
    return std::nullopt;
}

std::optional<int> parseMergeCommandLine(int argc, char** argv, MergeCommandLine& out) {
    CLI::App app{"Merge partial renders (trazo --render SCENE --passes A:B --partial FILE) into the image of one "
                 "render of all their passes", "trazo merge"};
    app.add_option("PARTS", out.parts, "Partial files, in any order")->required()->type_name("PART...");
    app.add_option("-o,--output", out.output, "Output image; format by extension (png bmp jpg tga exr hdr pfm)")
        ->type_name("IMAGE");
    app.add_option("--stats", out.statsPath, "Write the merged counts and timings as JSON to this file")
        ->type_name("FILE");
    app.add_option("--partial", out.partialPath, "Also write the merge as a partial file (to merge further)")
        ->type_name("FILE");
    app.add_flag("--allow-gaps", out.allowGaps, "Merge the passes there are when some are missing (and name them)");
    std::string passes;
    app.add_option("--passes", passes, "The passes the parts must cover (default: 0 to the last pass asked for)")
        ->type_name("A:B");
    app.add_flag("--quiet", out.quiet, "Only errors and warnings on stderr");
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        app.exit(e);
        return 2;
    }
    if (!readPassesOption(passes, "trazo: merge", out.passes)) return 2;
    if (out.output.empty() && out.partialPath.empty()) {
        std::fputs("trazo: merge: nothing to write: give -o IMAGE, --partial FILE or both\n", stderr);
        return 2;
    }
    return std::nullopt;
}

}  // namespace trazo

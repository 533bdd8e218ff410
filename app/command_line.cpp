// CLI11 parsing of the trazo command line (the only file that includes CLI11: it is slow to compile).
#include "command_line.h"

#include <CLI/CLI.hpp>

#include "render/strata_plan.h"
#include "scene/scene.h"

namespace trazo {

std::optional<int> parseCommandLine(int argc, char** argv, CommandLine& out) {
    CLI::App app{"Trazo: a ray tracer for the scene language of SPEC.md, on CPU and CUDA", "trazo"};
    app.set_version_flag("--version", "trazo " TRAZO_VERSION);
    app.add_option("SCENE", out.viewerScene, "Scene to open in the interactive viewer");
    app.add_option("--render", out.renderScene, "Render SCENE headless to a file")->type_name("SCENE");
    app.add_option("-o,--output", out.output, "Output image; format by extension (png bmp jpg tga exr hdr pfm)")
        ->capture_default_str();
    app.add_option("--spp", out.spp, "Passes per pixel (default: one full cycle of the scene's strata)")
        ->check(CLI::Range(1u, 1u << 24));
    app.add_option("--time", out.seconds, "Stop after this wall time in seconds (with --spp: whichever first)")
        ->check(CLI::PositiveNumber);
    app.add_option("--target-error", out.targetError,
                   "Stop once the estimated relative RMS error of the image falls below this (e.g. 0.01)")
        ->check(CLI::Range(1e-6, 1.0));
    app.add_flag("--fixed-grid", out.fixedGrid,
                 "The thesis's estimator: every pass evaluates every stratum of every grid (for comparisons)");
    std::string blocks = "auto";
    app.add_option("--blocks", blocks,
                   "Strata of each grid per pass: auto (measured per scene), 1, whole (= --fixed-grid), or "
                   "AA,LIGHT,INDIRECT,LIGHT_AT_INDIRECT targets, e.g. 1,100,1,5")
        ->capture_default_str();
    const std::map<std::string, BackendChoice> backends{
        {"auto", BackendChoice::Auto}, {"cpu", BackendChoice::Cpu}, {"cuda", BackendChoice::Cuda}};
    app.add_option("--backend", out.backend, "auto (CUDA when a device is present), cpu or cuda")
        ->transform(CLI::CheckedTransformer(backends, CLI::ignore_case));
    app.add_option("--threads", out.threads, "CPU threads (default: all cores)")->check(CLI::Range(1u, 4096u));
    app.add_option("--seed", out.seed, "Random seed; the same seed gives the same image");
    app.add_option("--width", out.width, "Override RenderWidth")->check(CLI::Range(1u, unsigned(kMaxRenderSize)));
    app.add_option("--height", out.height, "Override RenderHeight")->check(CLI::Range(1u, unsigned(kMaxRenderSize)));
    app.add_option("--stats", out.statsPath, "Write timings and counts as JSON to this file");
    app.add_flag("--quiet", out.quiet, "No progress bar");
    app.add_option("--frames", out.frames, "Viewer: run N passes in the window, save --screenshot, exit 0")
        ->check(CLI::Range(1u, 1u << 24))
        ->type_name("N");
    app.add_option("--screenshot", out.screenshot,
                   "Viewer: image written after --frames passes (else the screenshot key's default name)")
        ->type_name("FILE");

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
    if (out.fixedGrid) {
        out.blocks = StrataBlocks::whole();
    } else if (blocks != "auto") {
        StrataBlocks parsed;
        std::string why;
        if (!parseStrataBlocks(blocks, parsed, why)) {
            std::fprintf(stderr, "trazo: --blocks %s: %s\n", blocks.c_str(), why.c_str());
            return 2;
        }
        out.blocks = parsed;
    }
    if (out.renderScene.empty() && out.viewerScene.empty()) {
        std::fputs("trazo: no scene given; try `trazo --render SCENE -o image.png` or `trazo --help`\n", stderr);
        return 2;
    }
    if (!out.renderScene.empty() && !out.viewerScene.empty()) {
        std::fputs("trazo: give the scene either to --render or as the viewer's SCENE, not both\n", stderr);
        return 2;
    }
    if (!out.renderScene.empty() && (out.frames || !out.screenshot.empty())) {
        std::fputs("trazo: --frames and --screenshot are for the viewer (`trazo SCENE --frames N --screenshot FILE`); "
                   "with --render use --spp and -o\n", stderr);
        return 2;
    }
    return std::nullopt;
}

}  // namespace trazo

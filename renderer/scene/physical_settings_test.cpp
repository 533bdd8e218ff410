// SPEC §7's settings as hostile input meets them (misspelt words, out-of-range and non-finite numbers, a missing
// environment map: FILE:LINE, a plain reason, exit status 2 and no image), the writer's round trip, and the
// image transform end to end: `trazo --render` and `trazo merge` store 2^Exposure × the pixel through the view.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

#include "core/view_transform.h"
#include "scene/scene_reader.h"
#include "scene/scene_writer.h"
#include "test_paths.h"
#include "test_scenes.h"

namespace trazo {
namespace {

namespace fs = std::filesystem;

struct Read {
    Scene scene;
    Diagnostics diags;
};

// `lines` inside a SceneSettings block that opens on line 1, so the block's first parameter is on line 3.
Read readSettings(const std::string& lines) {
    Read r;
    r.scene = readSceneText("SceneSettings\n{\n" + lines + "}\n", "s.scene", r.diags);
    return r;
}

std::string listed(const Diagnostics& d, bool errorsOnly = false) { return test::listedDiagnostics(d, errorsOnly); }

TEST(PhysicalSettings, AMisspeltIntegratorIsAnErrorWithAHint) {
    const Read r = readSettings("    Integrator pathh\n");
    EXPECT_EQ(listed(r.diags), "s.scene:3:16: error: Integrator must be one of thesis, path, got 'pathh' "
                               "(did you mean 'path'?)\n");
    EXPECT_EQ(r.scene.settings.integrator, IntegratorKind::Thesis);
}

TEST(PhysicalSettings, UnknownLightSamplingWordsAreErrors) {
    const Read near = readSettings("    LightSampling nees\n");
    EXPECT_EQ(listed(near.diags), "s.scene:3:19: error: LightSampling must be one of mis, nee, bsdf, got 'nees' "
                                  "(did you mean 'nee'?)\n");
    const Read far = readSettings("\n    LightSampling photon-mapping\n");
    const std::string errors = listed(far.diags, true);
    EXPECT_EQ(errors.rfind("s.scene:4:19: error: LightSampling must be one of mis, nee, bsdf, got 'photon-mapping'", 0),
              0u)
        << errors;
    EXPECT_EQ(far.scene.settings.lightSampling, LightSampling::Mis);
    for (const char* bad : {"MIS", "1", "\"mis\""}) {  // words are case-sensitive; a number or a path is no word
        const Read r = readSettings(std::string("    LightSampling ") + bad + "\n");
        EXPECT_TRUE(r.diags.hasErrors()) << bad;
        EXPECT_EQ(listed(r.diags, true).rfind("s.scene:3:", 0), 0u) << bad << ": " << listed(r.diags);
    }
}

TEST(PhysicalSettings, NegativeOrFractionalMaxBouncesIsAnError) {
    const Read r = readSettings("    MaxBounces -1\n");
    EXPECT_EQ(listed(r.diags), "s.scene:3:16: error: MaxBounces must not be negative, got -1\n");
    EXPECT_EQ(r.scene.settings.maxBounces, 64);
    const Read half = readSettings("    MaxBounces 2.5\n");
    EXPECT_NE(listed(half.diags, true).find("s.scene:3:16: error: MaxBounces: expected an integer, got '2.5'"),
              std::string::npos)
        << listed(half.diags);
}

TEST(PhysicalSettings, HugeMaxBouncesWarnsAndUsesTheLimit) {
    for (const char* huge : {"1000000000", "4097", "99999999999999999999"}) {
        const Read r = readSettings(std::string("    MaxBounces ") + huge + "\n");
        if (std::strlen(huge) > 18) {  // past int64: an error, not a wrap to something small
            EXPECT_TRUE(r.diags.hasErrors()) << huge << ": " << listed(r.diags);
            continue;
        }
        EXPECT_FALSE(r.diags.hasErrors()) << listed(r.diags);
        EXPECT_EQ(listed(r.diags), std::string("s.scene:3:16: warning: MaxBounces ") + huge +
                                       " is more than 4096; using 4096 (a path that nothing absorbs would run every "
                                       "bounce)\n");
        EXPECT_EQ(r.scene.settings.maxBounces, kMaxBounces);
    }
    const Read limit = readSettings("    MaxBounces 4096\n");
    EXPECT_TRUE(limit.diags.items.empty()) << listed(limit.diags);
    EXPECT_EQ(limit.scene.settings.maxBounces, 4096);
}

TEST(PhysicalSettings, ExposureBeyond64StopsIsAnError) {
    const Read r = readSettings("    Exposure 1e30\n");
    EXPECT_EQ(listed(r.diags), "s.scene:3:14: error: Exposure must be between -64 and 64 stops, got 1e30\n");
    EXPECT_EQ(r.scene.settings.exposure, 0.0f);
    EXPECT_TRUE(readSettings("    Exposure -64.5\n").diags.hasErrors());
    const Read edge = readSettings("    Exposure -64\n    ViewTransform srgb\n");
    EXPECT_TRUE(edge.diags.items.empty()) << listed(edge.diags);
    EXPECT_EQ(edge.scene.settings.exposure, -64.0f);
}

TEST(PhysicalSettings, NonFiniteNumbersAreErrors) {
    for (const char* value : {"nan", "NaN", "-nan", "inf", "-inf", "1e400", "1e39"}) {
        for (const char* name : {"Exposure", "EnvironmentRotation"}) {
            const Read r = readSettings(std::string("    ") + name + " " + value + "\n");
            const std::string errors = listed(r.diags, true);
            EXPECT_EQ(errors.rfind("s.scene:3:", 0), 0u) << name << " " << value << ": " << listed(r.diags);
            EXPECT_NE(errors.find("is not a finite number"), std::string::npos) << errors;
            EXPECT_EQ(r.scene.settings.exposure, 0.0f);
            EXPECT_EQ(r.scene.settings.environmentRotation, 0.0f);
        }
    }
}

TEST(PhysicalSettings, EverySettingSurvivesTheSceneWriter) {
    const std::string path = test::tempPath("physical_round_trip.scene");
    const std::string sky = test::writeTempFile("physical_round_trip_sky.pfm", std::string("PF\n1 1\n-1.0\n") +
                                                                                   std::string(12, '\0'));
    const Read r = readSettings("    Integrator path\n    MaxBounces 7\n    LightSampling bsdf\n"
                                "    EnvironmentMap \"" + sky + "\"\n    EnvironmentRotation 33.5\n"
                                "    Exposure -2.25\n    ViewTransform srgb\n");
    ASSERT_FALSE(r.diags.hasErrors()) << listed(r.diags);
    const std::string text = formatScene(r.scene, path);
    for (const char* line : {"Integrator path", "MaxBounces 7", "LightSampling bsdf", "EnvironmentRotation 33.5",
                             "Exposure -2.25", "ViewTransform srgb"})
        EXPECT_NE(text.find(line), std::string::npos) << line << " missing in\n" << text;
    Diagnostics diags;
    const Scene back = readSceneText(text, path, diags);
    ASSERT_FALSE(diags.hasErrors()) << listed(diags) << text;
    const SceneSettings &a = r.scene.settings, &b = back.settings;
    EXPECT_EQ(b.integrator, IntegratorKind::Path);
    EXPECT_EQ(b.maxBounces, a.maxBounces);
    EXPECT_EQ(b.lightSampling, LightSampling::Bsdf);
    EXPECT_EQ(fs::path(b.environmentMap), fs::path(a.environmentMap));
    ASSERT_NE(b.environmentImage, nullptr);
    EXPECT_EQ(b.environmentRotation, a.environmentRotation);
    EXPECT_EQ(b.exposure, -2.25f);
    EXPECT_EQ(b.viewTransform, ViewTransform::Srgb);
    EXPECT_EQ(formatScene(back, path), text);
    // Left to its default (auto), ViewTransform is not written: the scene keeps following its integrator.
    const Read automatic = readSettings("    Integrator path\n");
    EXPECT_EQ(formatScene(automatic.scene, path).find("ViewTransform"), std::string::npos);
    EXPECT_EQ(automatic.scene.settings.viewTransform, ViewTransform::Auto);
}

// --- the command line -------------------------------------------------------------------------------------

// A small lit scene with `settings` in its SceneSettings block (which opens on line 1; settings start on 5).
std::string cliScene(const std::string& settings) {
    return "SceneSettings\n{\n    RenderWidth 12\n    RenderHeight 8\n" + settings + "}\n"
           "Camera\n{\n    POV 0 0 5\n}\n"
           "Material\n{\n    Name white\n    DiffuseColor 0.7 0.6 0.5\n}\n"
           "Sphere\n{\n    Material white\n}\n"
           "PointLight\n{\n    Position 2 2 2\n    Color 20 20 20\n}\n";
}

TEST(PhysicalSettingsCli, AMissingEnvironmentMapExitsTwoNamingThePathAndWhy) {
    const std::string scene =
        test::writeTempFile("missing_sky.scene", cliScene("    EnvironmentMap \"missing.hdr\"\n"));
    const std::string out = test::tempPath("missing_sky.png");
    fs::remove(out);
    const test::CommandResult r = test::runTrazo("--render " + scene + " -o " + out + " --quiet");
    EXPECT_EQ(r.status, 2) << r.errors;
    const std::string missing = (fs::path(scene).parent_path() / "missing.hdr").string();
    EXPECT_NE(r.errors.find("missing_sky.scene:5:"), std::string::npos) << r.errors;
    EXPECT_NE(r.errors.find("'" + missing + "': No such file or directory"), std::string::npos) << r.errors;
    EXPECT_FALSE(fs::exists(out));
}

TEST(PhysicalSettingsCli, HostileSettingsExitTwoAndWriteNothing) {
    const std::string out = test::tempPath("hostile_settings.png");
    const std::pair<const char*, const char*> cases[] = {
        {"    Integrator pathh\n", "did you mean 'path'"}, {"    LightSampling all\n", "LightSampling must be one of"},
        {"    MaxBounces -1\n", "must not be negative"},   {"    Exposure 1e30\n", "between -64 and 64 stops"},
        {"    Exposure nan\n", "not a finite number"},     {"    ViewTransform gamma\n", "linear, srgb"},
        {"    EnvironmentMap \".\"\n", "Is a directory"},
    };
    for (const auto& [lines, why] : cases) {
        fs::remove(out);
        const std::string scene = test::writeTempFile("hostile_settings.scene", cliScene(lines));
        const test::CommandResult r = test::runTrazo("--render " + scene + " -o " + out + " --quiet");
        EXPECT_EQ(r.status, 2) << lines << r.errors;
        EXPECT_NE(r.errors.find("hostile_settings.scene:5:"), std::string::npos) << lines << r.errors;
        EXPECT_NE(r.errors.find(why), std::string::npos) << lines << r.errors;
        EXPECT_FALSE(fs::exists(out)) << lines;
    }
}

// A PFM's floats, rows as stored; empty when it is not a little-endian RGB PFM.
std::vector<float> readPfmFloats(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::string magic;
    int w = 0, h = 0;
    float scale = 0;
    in >> magic >> w >> h >> scale;
    in.get();
    if (magic != "PF" || w <= 0 || h <= 0 || !(scale < 0)) return {};
    std::vector<float> data(size_t(3) * w * h);
    in.read(reinterpret_cast<char*>(data.data()), std::streamsize(data.size() * sizeof(float)));
    return in ? data : std::vector<float>{};
}

// SPEC §7 Image through `trazo --render`: Exposure 1 doubles the float file exactly; sRGB encodes the 8-bit one.
TEST(PhysicalSettingsCli, RenderStoresTheExposedImageThroughTheView) {
    const std::string plain = test::writeTempFile("exposure0.scene", cliScene("    Integrator path\n"
                                                                              "    ViewTransform linear\n"));
    const std::string exposed = test::writeTempFile("exposure1.scene", cliScene("    Integrator path\n"
                                                                                "    Exposure 1\n"));
    const std::string options = " --backend cpu --threads 1 --spp 2 --quiet";
    const std::string base = test::tempPath("exposure0.pfm"), twice = test::tempPath("exposure1.pfm");
    ASSERT_EQ(test::runTrazo("--render " + plain + " -o " + base + options).status, 0);
    ASSERT_EQ(test::runTrazo("--render " + exposed + " -o " + twice + options).status, 0);
    const std::vector<float> a = readPfmFloats(base), b = readPfmFloats(twice);
    ASSERT_EQ(a.size(), size_t(3 * 12 * 8));
    ASSERT_EQ(b.size(), a.size());
    bool lit = false;
    for (size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(b[i], 2.0f * a[i]) << i;
        lit = lit || a[i] > 0.0f;
    }
    EXPECT_TRUE(lit);
    // Exposure 0 with `linear` is §5's output: the PNG's bytes are round(255·clamp(x)).
    const std::string png = test::tempPath("exposure0.png"), srgbPng = test::tempPath("exposure1.png");
    ASSERT_EQ(test::runTrazo("--render " + plain + " -o " + png + options).status, 0);
    ASSERT_EQ(test::runTrazo("--render " + exposed + " -o " + srgbPng + options).status, 0);
    const std::string linearText = test::readFileText(png), srgbText = test::readFileText(srgbPng);
    EXPECT_FALSE(linearText.empty());
    EXPECT_NE(linearText, srgbText);  // the sRGB bytes themselves are image_writer_test's
}

// `trazo merge` has no scene: the parts carry Exposure and the view (the header's `display:` line), so the
// merged image is the one a single render writes.
TEST(PhysicalSettingsCli, MergeStoresWhatTheRenderStores) {
    const std::string scene = test::writeTempFile("merge_exposure.scene", cliScene("    Integrator path\n"
                                                                                   "    Exposure 1.5\n"));
    const std::string dir = test::freshDir("merge_exposure");
    const std::string options = " --backend cpu --threads 1 --quiet";
    ASSERT_EQ(test::runTrazo("--render " + scene + " -o " + dir + "/whole.png --spp 4" + options).status, 0);
    for (const char* range : {"0:1", "1:4"})
        ASSERT_EQ(test::runTrazo("--render " + scene + " --passes " + range + " --partial " + dir + "/" +
                                 range[0] + ".part" + options)
                      .status,
                  0);
    const std::string header = test::readFileText(dir + "/0.part").substr(0, 600);
    EXPECT_NE(header.find("\ndisplay: exposure=1.5 view=srgb\n"), std::string::npos) << header;
    const test::CommandResult r =
        test::runTrazo("merge " + dir + "/0.part " + dir + "/1.part -o " + dir + "/merged.png --quiet");
    ASSERT_EQ(r.status, 0) << r.errors;
    EXPECT_EQ(test::readFileText(dir + "/merged.png"), test::readFileText(dir + "/whole.png"));
    // A thesis scene with neither setting writes no `display:` line: its partial files are as before.
    const std::string thesis = test::writeTempFile("merge_thesis.scene", cliScene(""));
    ASSERT_EQ(test::runTrazo("--render " + thesis + " --passes 0:1 --partial " + dir + "/t.part" + options).status, 0);
    EXPECT_EQ(test::readFileText(dir + "/t.part").substr(0, 600).find("display:"), std::string::npos);
}

}  // namespace
}  // namespace trazo

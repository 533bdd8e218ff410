// Scenes and diagnostics as the tests use them (test_scenes.h).
#include "test_scenes.h"

#include <gtest/gtest.h>

#include "scene/scene_reader.h"
#include "test_paths.h"

namespace trazo::test {

Scene readSourceScene(const std::string& relative) {
    Diagnostics diags;
    Scene scene = readSceneFile(sourcePath(relative), diags);
    EXPECT_FALSE(diags.hasErrors()) << relative << ":\n" << listedDiagnostics(diags, true);
    return scene;
}

std::string penumbraSceneText(const std::string& settings) {
    return "SceneSettings\n{\n" + settings + "}\n" +
           "Camera\n{\n    POV 0 3 8\n    POI 0 1 0\n    FOV 45\n}\n"
           "Material\n{\n    Name white\n    DiffuseColor 0.8 0.8 0.8\n}\n"
           "Box\n{\n    Material white\n    Scale 8 0.2 8\n    Translation 0 -0.1 0\n}\n"
           "Sphere\n{\n    Material white\n    Center 0 1 0\n    Radius 1\n}\n"
           "AreaLight\n{\n    Position 0.5 4 0\n    Direction 0 -1 0\n    Width 3\n    Height 3\n    Subdivision 4 4\n"
           "    Color 1 1 1\n}\n";
}

std::string listedDiagnostics(const Diagnostics& diags, bool errorsOnly) {
    std::string text;
    for (const Diagnostic& d : diags.items)
        if (!errorsOnly || d.severity == Severity::Error) text += formatDiagnostic(d) + "\n";
    return text;
}

}  // namespace trazo::test

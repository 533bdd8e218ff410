// Scene writer: one function per block, in the order the reader needs (textures, then materials, then the
// objects that name them).
#include "scene/scene_writer.h"

#include "io/text_file.h"

#include <cstdio>
#include <filesystem>

namespace trazo {
namespace {

// %.9g: every float reads back to the same bits.
std::string num(float v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.9g", double(v));
    return buffer;
}

std::string vec(Vec3 v) { return num(v.x) + " " + num(v.y) + " " + num(v.z); }

// Relative to the scene's own folder, so the saved scene still finds its files when the folder moves.
std::string quotedPath(const std::string& path, const std::string& scenePath) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path target = fs::absolute(fs::path(path), ec).lexically_normal();
    const fs::path folder = fs::absolute(fs::path(scenePath), ec).parent_path().lexically_normal();
    const fs::path relative = target.lexically_relative(folder);
    std::string quoted = (relative.empty() ? target : relative).generic_string();
    quoted.insert(quoted.begin(), '"');  // (not "\"" + …: GCC 12 warns falsely on that with -O2)
    quoted.push_back('"');
    return quoted;
}

class Writer {
public:
    Writer(const Scene& scene, const std::string& scenePath) : scene_(scene), path_(scenePath) {}

    std::string write() {
        out_ = "# Written by trazo's scene writer (SPEC.md); angles in Rotation are radians.\n";
        writeSettings();
        writeCamera();
        for (const Texture& t : scene_.textures) {
            open("Texture");
            line("Name", t.name);
            line("Source", quotedPath(t.source, path_));
            close();
        }
        for (const Material& m : scene_.materials) writeMaterial(m);
        for (const Sphere& s : scene_.spheres) {
            open("Sphere");
            material(s.material);
            line("Center", vec(s.center));
            line("Radius", num(s.radius));
            close();
        }
        for (const Box& b : scene_.boxes) {
            open("Box");
            material(b.material);
            transforms(b.transforms);
            close();
        }
        for (const Cylinder& c : scene_.cylinders) {
            open("Cylinder");
            material(c.material);
            line("Base", vec(c.base));
            line("Axis", vec(c.axis));
            line("Height", num(c.height));
            line("Radius", num(c.radius));
            close();
        }
        for (const Csg& c : scene_.csgs) {
            open("CSG");
            material(c.material);
            line("Source", quotedPath(c.source, path_));
            transforms(c.transforms);
            close();
        }
        for (const Mesh& m : scene_.meshes) {
            open("Mesh");
            material(m.material);
            line("Source", quotedPath(m.source, path_));
            transforms(m.transforms);
            close();
        }
        for (const PointLight& l : scene_.pointLights) {
            open("PointLight");
            line("Position", vec(l.position));
            line("Color", vec(l.color));
            close();
        }
        for (const AreaLight& l : scene_.areaLights) {
            open("AreaLight");
            line("Color", vec(l.color));
            line("Position", vec(l.position));
            line("Direction", vec(l.direction));
            line("RollAngle", num(l.rollAngle));
            line("Width", num(l.width));
            line("Height", num(l.height));
            line("Subdivision", std::to_string(l.subdivisionX) + " " + std::to_string(l.subdivisionY));
            close();
        }
        return std::move(out_);
    }

private:
    void open(const char* block) { out_ += std::string("\n") + block + "\n{\n"; }
    void close() { out_ += "}\n"; }
    void line(const char* name, const std::string& values) { out_ += std::string("    ") + name + " " + values + "\n"; }

    void writeSettings() {
        const SceneSettings& s = scene_.settings;
        open("SceneSettings");
        line("BackgroundColor", vec(s.backgroundColor));
        line("RenderWidth", std::to_string(s.renderWidth));
        line("RenderHeight", std::to_string(s.renderHeight));
        line("ReflectionQuality", std::to_string(s.reflectionQuality));
        line("ReflectionSteps", std::to_string(s.reflectionSteps));
        line("IndirectQuality", std::to_string(s.indirectQuality));
        line("ColorBleeding", num(s.colorBleeding));
        line("Antialiasing", std::to_string(s.antialiasing));
        close();
    }

    void writeCamera() {
        open("Camera");
        line("POV", vec(scene_.camera.pov));
        line("POI", vec(scene_.camera.poi));
        line("FOV", num(scene_.camera.fovDegrees));
        close();
    }

    void writeMaterial(const Material& m) {
        open("Material");
        line("Name", m.name);
        line("DiffuseColor", vec(m.diffuseColor));
        line("SpecularColor", vec(m.specularColor));
        line("EmissiveColor", vec(m.emissiveColor));
        texture("DiffuseTexture", m.diffuseTexture);
        texture("SpecularTexture", m.specularTexture);
        texture("EmissiveTexture", m.emissiveTexture);
        texture("NormalTexture", m.normalTexture);
        line("Roughness", num(m.roughness));
        line("Opacity", num(m.opacity));
        line("RefractionIndex", num(m.refractionIndex));
        line("ReflectionAngle", num(m.reflectionAngleDegrees));
        line("ReflectionAmount", num(m.reflectionAmount));
        close();
    }

    void texture(const char* slot, int32_t index) {
        if (index >= 0 && size_t(index) < scene_.textures.size()) line(slot, scene_.textures[size_t(index)].name);
    }

    void material(int32_t index) {
        if (index >= 0 && size_t(index) < scene_.materials.size()) line("Material", scene_.materials[size_t(index)].name);
    }

    void transforms(const std::vector<TransformStep>& steps) {
        for (const TransformStep& t : steps) {
            switch (t.kind) {
                case TransformStep::Kind::Translation: line("Translation", vec(t.value)); break;
                case TransformStep::Kind::Rotation: line("Rotation", vec(t.value) + " " + num(t.angle)); break;
                case TransformStep::Kind::Scale: line("Scale", vec(t.value)); break;
            }
        }
    }

    const Scene& scene_;
    const std::string& path_;
    std::string out_;
};

}  // namespace

std::string formatScene(const Scene& scene, const std::string& scenePath) { return Writer(scene, scenePath).write(); }

bool writeSceneFile(const Scene& scene, const std::string& path, std::string& error) {
    return writeTextFileAtomically(path, formatScene(scene, path), error);
}

}  // namespace trazo

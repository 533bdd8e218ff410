// Environment map reader (host): the texture reader's decoding, its messages naming an environment map, PFM's rows
// in the format's order, and texels that are not finite, non-negative radiance replaced.
#include "scene/environment_reader.h"

#include <cctype>
#include <cmath>
#include <fstream>
#include <utility>

#include "scene/texture_reader.h"

namespace trazo {
namespace {

// The component as radiance: NaN and negative values 0, infinite and larger ones the bound.
float radianceOf(float c) {
    if (!(c >= 0.0f)) return 0.0f;
    return c > kMaxEnvironmentTexel ? kMaxEnvironmentTexel : c;
}

bool isRadiance(Vec3 t) { return radianceOf(t.x) == t.x && radianceOf(t.y) == t.y && radianceOf(t.z) == t.z; }

// PFM stores its rows bottom to top, but FreeImage 3.18 reads the first row as the top (image_writer.cpp writes PFM
// rows flipped for the same reason): read as it is, a map from any other tool would put the sky underfoot.
bool isPfm(const std::string& path) {
    char head[3] = {};
    std::ifstream(path, std::ios::binary).read(head, 3);
    return head[0] == 'P' && (head[1] == 'F' || head[1] == 'f') && std::isspace(static_cast<unsigned char>(head[2]));
}

void flipRows(TextureImage& image) {
    for (int top = 0, bottom = image.height - 1; top < bottom; ++top, --bottom)
        std::swap_ranges(image.texels.begin() + size_t(top) * image.width,
                         image.texels.begin() + size_t(top + 1) * image.width,
                         image.texels.begin() + size_t(bottom) * image.width);
}

// "cannot read texture 'x': …" → "cannot read environment map 'x': …": the user wrote EnvironmentMap, not Texture.
std::string namingTheMap(std::string message) {
    const size_t at = message.find("texture '");
    if (at != std::string::npos && at < 16) message.replace(at, 7, "environment map");
    return message;
}

}  // namespace

std::shared_ptr<const TextureImage> readEnvironmentMap(const std::string& path, SourceLocation at, Diagnostics& diags) {
    Diagnostics read;
    std::shared_ptr<const TextureImage> image = readTextureImage(path, at, read);
    for (Diagnostic& d : read.items) {
        d.message = namingTheMap(std::move(d.message));
        diags.items.push_back(std::move(d));
    }
    if (!image) return nullptr;

    const bool flip = isPfm(path);
    size_t changed = 0;
    for (const Vec3& t : image->texels) changed += isRadiance(t) ? 0 : 1;
    if (changed == 0 && !flip) return image;
    auto fixed = std::make_shared<TextureImage>(*image);  // a copy only for a PFM or a map with bad texels
    if (flip) flipRows(*fixed);
    if (changed == 0) return fixed;
    for (Vec3& t : fixed->texels) t = Vec3(radianceOf(t.x), radianceOf(t.y), radianceOf(t.z));
    diags.warning(at, "environment map '" + path + "': " + std::to_string(changed) + " of " +
                          std::to_string(fixed->texels.size()) +
                          " texels are not finite, non-negative radiance; their NaN and negative components read "
                          "as 0, their infinite ones (and any above 1e12) as 1e12");
    return fixed;
}

}  // namespace trazo

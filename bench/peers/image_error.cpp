// image_error: the error of one image against a reference, or the two-seed variance of a render (host).
//   image_error IMAGE REFERENCE   → "rel_error R rmse E mean_ref M" (compareToReference's definitions:
//                                   RMSE over pixels and channels, divided by the reference's mean)
//   image_error --variance A B    → "variance V rel_sd S mean M": A and B are two renders of one scene with
//                                   different seeds, so E[(A−B)²] = 2·Var and Var ≈ mean((A−B)²)/2 per
//                                   pixel-channel; rel_sd = √Var / mean((A+B)/2), one render's relative error.
//   image_error --relmse A REF [--exclude-above T] [--mask M]
//                                 → "relmse R pixels N excluded K mean_a r g b mean_ref r g b": the relative
//                                   MSE, mean over pixels and channels of (a−r)²/(r²+0.01) (the denoising
//                                   literature's ε); pixels whose reference exceeds T in any channel (e.g. a
//                                   light seen directly) or whose mask M (any image of the same size) is
//                                   above 0.5 in any channel are left out, of the relMSE and of the means.
// Reads .pfm (our own reader: FreeImage shows PFM rows upside down) and, through the renderer's texture
// reader (FreeImage), .exr/.hdr as floats and .png/.bmp/... as 8- or 16-bit values over 255 or 65535.
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "render/error_estimate.h"
#include "scene/texture_reader.h"

namespace {

using trazo::Vec3;

struct Image {
    int width = 0, height = 0;
    std::vector<Vec3> pixels;  // bottom row first, as both readers give them
};

bool endsWith(const std::string& s, const char* tail) {
    const size_t n = std::strlen(tail);
    if (s.size() < n) return false;
    for (size_t i = 0; i < n; ++i)
        if (std::tolower((unsigned char)s[s.size() - n + i]) != tail[i]) return false;
    return true;
}

// PFM: "PF" (RGB) or "Pf" (grey), width height, scale (negative: little-endian), raw floats bottom row first.
bool readPfm(const std::string& path, Image& img, std::string& error) {
    FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) return error = path + ": " + std::strerror(errno), false;
    char kind[3] = {};
    float scale = 0;
    bool ok = std::fscanf(f, "%2s %d %d %f", kind, &img.width, &img.height, &scale) == 4 && img.width > 0 &&
              img.height > 0 && (kind[1] == 'F' || kind[1] == 'f') && kind[0] == 'P' && std::fgetc(f) != EOF;
    const int channels = kind[1] == 'F' ? 3 : 1;
    std::vector<float> raw((size_t)img.width * img.height * channels);
    ok = ok && std::fread(raw.data(), sizeof(float), raw.size(), f) == raw.size();
    std::fclose(f);
    if (!ok) return error = path + ": not a readable PFM file", false;
    if (scale > 0) {  // big-endian data on this little-endian host
        for (float& v : raw) {
            uint32_t bits;
            std::memcpy(&bits, &v, 4);
            bits = __builtin_bswap32(bits);
            std::memcpy(&v, &bits, 4);
        }
    }
    img.pixels.resize((size_t)img.width * img.height);
    for (size_t i = 0; i < img.pixels.size(); ++i)
        img.pixels[i] = channels == 3 ? Vec3(raw[3 * i], raw[3 * i + 1], raw[3 * i + 2]) : Vec3(raw[i]);
    return true;
}

bool readImage(const std::string& path, Image& img, std::string& error) {
    if (endsWith(path, ".pfm")) return readPfm(path, img, error);
    trazo::Diagnostics diags;
    const auto texture = trazo::readTextureImage(path, trazo::SourceLocation{path, 0, 0}, diags);
    if (!texture) {
        error = diags.items.empty() ? path + ": cannot be read" : trazo::formatDiagnostic(diags.items.front());
        return false;
    }
    img.width = texture->width, img.height = texture->height, img.pixels = texture->texels;
    return true;
}

double meanValue(const std::vector<Vec3>& p) {
    double sum = 0;
    for (const Vec3& v : p) sum += double(v.x) + v.y + v.z;
    return sum / (3.0 * p.size());
}

}  // namespace

// --relmse: see the top of the file.
static int relativeMse(int argc, char** argv) {
    std::string paths[2], maskPath;
    int count = 0;
    double above = INFINITY;
    for (int i = 2; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--exclude-above" && i + 1 < argc) {
            char* end = nullptr;
            above = std::strtod(argv[++i], &end);
            if (!end || *end || !(above == above)) return std::fprintf(stderr, "image_error: bad threshold\n"), 2;
        } else if (arg == "--mask" && i + 1 < argc) {
            maskPath = argv[++i];
        } else if (count < 2 && !(arg.size() > 1 && arg[0] == '-' && arg[1] == '-')) {
            paths[count++] = arg;
        } else {
            count = 3;
            break;
        }
    }
    if (count != 2) {
        std::fprintf(stderr, "usage: image_error --relmse A REFERENCE [--exclude-above T] [--mask M]\n");
        return 2;
    }
    Image a, b, mask;
    std::string error;
    if (!readImage(paths[0], a, error) || !readImage(paths[1], b, error) ||
        (!maskPath.empty() && !readImage(maskPath, mask, error))) {
        std::fprintf(stderr, "image_error: %s\n", error.c_str());
        return 2;
    }
    if (a.width != b.width || a.height != b.height ||
        (!maskPath.empty() && (mask.width != b.width || mask.height != b.height))) {
        std::fprintf(stderr, "image_error: sizes differ\n");
        return 2;
    }
    double sum = 0, meanA[3] = {}, meanB[3] = {};
    size_t used = 0;
    for (size_t i = 0; i < b.pixels.size(); ++i) {
        const Vec3 x = a.pixels[i], y = b.pixels[i];
        if (y.x > above || y.y > above || y.z > above) continue;
        if (!maskPath.empty() && (mask.pixels[i].x > 0.5f || mask.pixels[i].y > 0.5f || mask.pixels[i].z > 0.5f))
            continue;
        const double xs[3] = {x.x, x.y, x.z}, ys[3] = {y.x, y.y, y.z};
        for (int c = 0; c < 3; ++c) {
            const double d = xs[c] - ys[c];
            sum += d * d / (ys[c] * ys[c] + 0.01);
            meanA[c] += xs[c], meanB[c] += ys[c];
        }
        ++used;
    }
    const double n = used ? double(used) : 1.0;
    std::printf("relmse %.6g pixels %zu excluded %zu mean_a %.6g %.6g %.6g mean_ref %.6g %.6g %.6g\n",
                used ? sum / (3.0 * n) : 0.0, used, b.pixels.size() - used, meanA[0] / n, meanA[1] / n, meanA[2] / n,
                meanB[0] / n, meanB[1] / n, meanB[2] / n);
    return 0;
}

int main(int argc, char** argv) {
    if (argc >= 2 && std::string(argv[1]) == "--relmse") return relativeMse(argc, argv);
    const bool variance = argc == 4 && std::string(argv[1]) == "--variance";
    if (!variance && argc != 3) {
        std::fprintf(stderr,
                     "usage: image_error IMAGE REFERENCE | image_error --variance A B\n"
                     "       image_error --relmse A REFERENCE [--exclude-above T] [--mask M]\n");
        return 2;
    }
    Image a, b;
    std::string error;
    if (!readImage(argv[variance ? 2 : 1], a, error) || !readImage(argv[variance ? 3 : 2], b, error)) {
        std::fprintf(stderr, "image_error: %s\n", error.c_str());
        return 2;
    }
    if (a.width != b.width || a.height != b.height) {
        std::fprintf(stderr, "image_error: sizes differ (%d x %d against %d x %d)\n", a.width, a.height, b.width,
                     b.height);
        return 2;
    }
    if (!variance) {
        const trazo::ReferenceError e = trazo::compareToReference(a.pixels, b.pixels);
        std::printf("rel_error %.6g rmse %.6g mean_ref %.6g\n", e.relError, e.rmse, meanValue(b.pixels));
        return 0;
    }
    double sumSq = 0, sum = 0;
    for (size_t i = 0; i < a.pixels.size(); ++i) {
        const Vec3 d = a.pixels[i] - b.pixels[i], m = a.pixels[i] + b.pixels[i];
        sumSq += double(d.x) * d.x + double(d.y) * d.y + double(d.z) * d.z;
        sum += 0.5 * (double(m.x) + m.y + m.z);
    }
    const double n = 3.0 * a.pixels.size(), var = 0.5 * sumSq / n, mean = sum / n;
    std::printf("variance %.6g rel_sd %.6g mean %.6g\n", var, std::sqrt(var) / mean, mean);
    return 0;
}

// generate_head (build-time tool): writes head.obj, head_diffuse.png and head_normal.png, the procedural
// stand-in for the thesis's scanned head (scene 8). Usage: generate_head <output folder>
//
// The surface is star-shaped around a centre inside the skull: a direction d gets a radius
// r(d) = smooth union of an ellipsoid (skull and face) and a cylinder (neck), plus face features added
// along d, so it is closed and never folds over itself. The mesh is a UV sphere of that radius function
// with its rings spaced evenly by arc length; both textures are evaluated on the same analytic surface,
// so their features land where the geometry has them.
#include <FreeImage.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include <unistd.h>

namespace {

namespace fs = std::filesystem;

constexpr double kPi = 3.14159265358979323846;

// 96 x 77 gives 2·96·76 = 14592 triangles, close to the thesis's 14581-polygon scan.
constexpr int kColumns = 96;
constexpr int kRings = 77;
constexpr int kTextureSize = 1024;

// Model units are ~10x the scene's (the scene applies Scale 0.1, Translation 0 1 0). The FOV-20 camera
// at (0, 5, 15) sees scene y 2.36 .. 7.64 at z = 0, i.e. model y 13.6 .. 66.4: the crown at y = 62 and
// the chin at y = 27 fill most of that height, the neck runs out of the bottom of the frame.
struct V3 {
    double x = 0, y = 0, z = 0;
};
V3 operator+(V3 a, V3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
V3 operator-(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
V3 operator*(V3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
double dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V3 cross(V3 a, V3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
double length(V3 a) { return std::sqrt(dot(a, a)); }
V3 normalize(V3 a) {
    double l = length(a);
    return l > 0 ? a * (1.0 / l) : V3{0, 0, 1};
}

constexpr V3 kCentre{0.0, 44.0, 0.0};

double smoothstep(double e0, double e1, double x) {
    double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

// exp(-(dx/sx)² - (dy/sy)²): a bump of 1/e radii sx, sy.
double bump(double dx, double sx, double dy, double sy) { return std::exp(-(dx * dx) / (sx * sx) - (dy * dy) / (sy * sy)); }

// ---- noise (integer hash: the same assets on every machine) ----

uint32_t hash3(int32_t x, int32_t y, int32_t z, uint32_t seed) {
    uint32_t h = seed * 0x9E3779B9u;
    h ^= static_cast<uint32_t>(x) * 0x85EBCA6Bu;
    h = (h ^ (h >> 15)) * 0x2C1B3C6Du;
    h ^= static_cast<uint32_t>(y) * 0xC2B2AE35u;
    h = (h ^ (h >> 13)) * 0x297A2D39u;
    h ^= static_cast<uint32_t>(z) * 0x27D4EB2Fu;
    h = (h ^ (h >> 16)) * 0x85EBCA6Bu;
    return h ^ (h >> 13);
}
double unit(uint32_t h) { return (h & 0xFFFFFF) / double(0xFFFFFF); }

// Trilinear value noise in [-1, 1], quintic-smoothed.
double valueNoise(V3 p, uint32_t seed) {
    double fx = std::floor(p.x), fy = std::floor(p.y), fz = std::floor(p.z);
    int ix = int(fx), iy = int(fy), iz = int(fz);
    auto fade = [](double t) { return t * t * t * (t * (t * 6 - 15) + 10); };
    double tx = fade(p.x - fx), ty = fade(p.y - fy), tz = fade(p.z - fz);
    double c[2][2][2];
    for (int a = 0; a < 2; ++a)
        for (int b = 0; b < 2; ++b)
            for (int d = 0; d < 2; ++d) c[a][b][d] = unit(hash3(ix + a, iy + b, iz + d, seed)) * 2 - 1;
    auto lerp = [](double a, double b, double t) { return a + (b - a) * t; };
    double x00 = lerp(c[0][0][0], c[1][0][0], tx), x10 = lerp(c[0][1][0], c[1][1][0], tx);
    double x01 = lerp(c[0][0][1], c[1][0][1], tx), x11 = lerp(c[0][1][1], c[1][1][1], tx);
    return lerp(lerp(x00, x10, ty), lerp(x01, x11, ty), tz);
}

double fbm(V3 p, int octaves, uint32_t seed) {
    double sum = 0, amp = 0.5, norm = 0;
    for (int i = 0; i < octaves; ++i) {
        sum += amp * valueNoise(p, seed + i);
        norm += amp;
        p = p * 2.03;
        amp *= 0.5;
    }
    return sum / norm;
}

// Distance to the nearest jittered cell point (Worley F1), in cell units; also returns that cell's hash.
double cellular(V3 p, uint32_t seed, uint32_t& cellHash) {
    int ix = int(std::floor(p.x)), iy = int(std::floor(p.y)), iz = int(std::floor(p.z));
    double best = 1e9;
    for (int a = -1; a <= 1; ++a)
        for (int b = -1; b <= 1; ++b)
            for (int d = -1; d <= 1; ++d) {
                uint32_t h = hash3(ix + a, iy + b, iz + d, seed);
                V3 q{ix + a + unit(h), iy + b + unit(h * 747796405u + 1), iz + d + unit(h * 2891336453u + 7)};
                double dist = length(q - p);
                if (dist < best) {
                    best = dist;
                    cellHash = h;
                }
            }
    return best;
}

// ---- the surface ----

// θ from the top (+Y), φ around Y with φ = 0 facing +Z (the camera) and increasing towards +X.
V3 direction(double theta, double phi) {
    return {std::sin(theta) * std::sin(phi), std::cos(theta), std::sin(theta) * std::cos(phi)};
}

double skullRadius(V3 d) {
    // Semi-axes switch with the sign of a component whose square is what matters, so r stays smooth.
    double ax = 13.0 * (1.0 - 0.3 * smoothstep(0.0, -0.85, d.y));  // narrower jaw
    double ay = d.y > 0 ? 18.0 : 17.0;
    double az = d.z > 0 ? 15.0 : 16.5;  // deeper at the back of the skull
    return 1.0 / std::sqrt((d.x / ax) * (d.x / ax) + (d.y / ay) * (d.y / ay) + (d.z / az) * (d.z / az));
}

// Distance from kCentre along d to a vertical neck cylinder (radius 7.5, axis at z = -2.5, bottom y = 6);
// fades to 0 towards the horizontal, where the skull is far larger anyway.
double neckRadius(V3 d) {
    if (d.y >= 0) return 0.0;
    constexpr double kRadius = 7.5, kAxisZ = -2.5, kBottom = 6.0;
    double tBottom = (kCentre.y - kBottom) / -d.y;
    double s2 = d.x * d.x + d.z * d.z;
    double tSide = 1e9;
    if (s2 > 1e-12) {
        double oh = -kAxisZ * d.z;  // (centre - axis)·h with centre - axis = (0, -kAxisZ) in xz
        double c = kAxisZ * kAxisZ - kRadius * kRadius;
        tSide = (-oh + std::sqrt(oh * oh - s2 * c)) / s2;
    }
    return std::min(tBottom, tSide) * smoothstep(0.0, -0.3, d.y);
}

// Face features as offsets along d, in model units, evaluated at the base surface point p.
double featureOffset(V3 p) {
    const double front = smoothstep(2.0, 9.0, p.z);
    const double ax = std::abs(p.x);
    double off = 0.0;

    // Nose: a ridge from the bridge (y 47) growing to the tip (y 38.5), widening towards the nostrils.
    constexpr double kBridge = 47.0, kTip = 38.5;
    double amp, width;
    if (p.y > kBridge) {
        amp = 1.0 * std::exp(-std::pow((p.y - kBridge) / 2.0, 2));
        width = 1.2;
    } else if (p.y > kTip) {
        double t = (kBridge - p.y) / (kBridge - kTip);
        amp = 1.0 + 3.4 * std::pow(t, 1.3);
        width = 1.2 + 1.3 * t;
    } else {
        amp = 4.4 * std::exp(-std::pow((kTip - p.y) / 1.5, 2));
        width = 2.5;
    }
    off += front * amp * std::exp(-(p.x / width) * (p.x / width));

    off += front * (-2.2 * bump(ax - 4.8, 2.6, p.y - 46.0, 1.8));  // eye sockets
    off += front * (1.4 * bump(ax - 4.8, 1.8, p.y - 45.8, 1.2));   // eyeballs
    off += front * (1.3 * bump(ax - 4.5, 3.5, p.y - 49.0, 1.3));   // brow ridge
    off += front * (1.0 * bump(ax - 7.5, 2.8, p.y - 41.5, 2.5));   // cheekbones
    off += front * (-0.6 * bump(ax - 7.0, 2.5, p.y - 36.0, 2.5));  // cheek hollows
    off += front * (1.0 * bump(p.x, 3.2, p.y - 33.6, 0.9));        // upper lip
    off += front * (1.1 * bump(p.x, 2.8, p.y - 31.3, 0.9));        // lower lip
    off += front * (-0.5 * bump(ax - 3.6, 0.8, p.y - 32.5, 0.8));  // mouth corners
    off += front * (2.0 * bump(p.x, 3.4, p.y - 27.5, 2.4));        // chin
    off += front * (2.2 * bump(p.x, 6.0, p.y - 29.5, 3.5));        // jaw: keeps the chin forward

    // Ears: a rim with a hollow, on the sides.
    const double side = smoothstep(9.0, 12.5, ax);
    off += side * (2.6 * bump(p.y - 43.0, 3.8, p.z + 1.0, 2.0) - 0.8 * bump(p.y - 43.0, 1.8, p.z + 0.8, 1.0));

    off += 1.2 * bump(p.y - 50.0, 7.0, p.z + 12.0, 6.0);  // occiput
    return off;
}

struct SurfacePoint {
    V3 position;
    V3 base;  // before the features: the frame the texture features are laid out in
};

SurfacePoint surfacePoint(double theta, double phi) {
    V3 d = direction(theta, phi);
    double rs = skullRadius(d), rn = neckRadius(d);
    double r = std::pow(std::pow(rs, 8) + std::pow(rn, 8), 1.0 / 8);  // smooth union of two star shapes
    V3 base = kCentre + d * r;
    return {kCentre + d * (r + featureOffset(base)), base};
}

// θ(t) for t in [0, 1] such that rings at equal t are equally spaced along the profile (averaged over
// meridians): an even θ would crowd the neck's few rings and stretch the face's.
class RingSpacing {
public:
    RingSpacing() {
        constexpr int kSamples = 4096, kMeridians = 24;
        std::vector<double> sum(kSamples + 1, 0.0);
        for (int m = 0; m < kMeridians; ++m) {
            double phi = 2 * kPi * (m + 0.5) / kMeridians - kPi;
            std::vector<double> len(kSamples + 1, 0.0);
            V3 prev = surfacePoint(0.0, phi).position;
            for (int k = 1; k <= kSamples; ++k) {
                V3 p = surfacePoint(kPi * k / kSamples, phi).position;
                len[k] = len[k - 1] + length(p - prev);
                prev = p;
            }
            for (int k = 0; k <= kSamples; ++k) sum[k] += len[k] / len[kSamples];
        }
        for (double& s : sum) s /= kMeridians;
        cumulative_ = std::move(sum);
    }

    double theta(double t) const {
        auto it = std::lower_bound(cumulative_.begin(), cumulative_.end(), t);
        if (it == cumulative_.begin()) return 0.0;
        if (it == cumulative_.end()) return kPi;
        size_t k = size_t(it - cumulative_.begin());
        double a = cumulative_[k - 1], b = cumulative_[k];
        double f = b > a ? (t - a) / (b - a) : 0.0;
        return kPi * (double(k - 1) + f) / double(cumulative_.size() - 1);
    }

private:
    std::vector<double> cumulative_;
};

// Texture coordinates (OBJ/OpenGL: v = 0 is the bottom row of the image) to the surface. u = 0.5 is the
// face, so the seam (u = 0 = 1) runs down the back of the head; v = 1 is the crown.
double phiFromU(double u) { return 2 * kPi * u - kPi; }

// ---- textures ----

struct Rgb {
    double r, g, b;
};
Rgb mix(Rgb a, Rgb b, double t) { return {a.r + (b.r - a.r) * t, a.g + (b.g - a.g) * t, a.b + (b.b - a.b) * t}; }

// Where the hair starts: high at the forehead, down to the nape at the back.
double hairMask(V3 base, double phi) {
    double hairline = 36.0 + 17.5 * std::pow((1 + std::cos(phi)) / 2, 0.7);
    double wobble = 0.8 * fbm(base * 0.4, 3, 11);
    return smoothstep(hairline - 0.8, hairline + 0.8, base.y + wobble);
}

// Fine strands: noise stretched along the meridians (fast across φ, slow along θ), periodic in φ.
double hairStrands(double theta, double phi) {
    constexpr int kPeriod = 420;
    double x = (phi + kPi) / (2 * kPi) * kPeriod, y = theta * 18.0;
    int ix = int(std::floor(x)), iy = int(std::floor(y));
    double tx = x - ix, ty = y - iy;
    auto at = [&](int i, int j) { return unit(hash3(((i % kPeriod) + kPeriod) % kPeriod, j, 0, 5)); };
    auto s = [](double t) { return t * t * (3 - 2 * t); };
    double a = at(ix, iy) + (at(ix + 1, iy) - at(ix, iy)) * s(tx);
    double b = at(ix, iy + 1) + (at(ix + 1, iy + 1) - at(ix, iy + 1)) * s(tx);
    return a + (b - a) * s(ty);
}

Rgb albedo(const SurfacePoint& sp, double theta, double phi) {
    const V3 p = sp.base;
    const double front = smoothstep(2.0, 9.0, p.z);
    const double ax = std::abs(p.x);

    Rgb skin{0.78, 0.57, 0.47};
    double blotch = fbm(p * 0.15, 4, 1);
    skin = mix(skin, Rgb{0.70, 0.47, 0.40}, std::clamp(0.5 + blotch, 0.0, 1.0) * 0.5);
    uint32_t cell = 0;
    double freckle = cellular(p * 1.3, 2, cell);
    if ((cell & 7) == 0) skin = mix(skin, Rgb{0.60, 0.40, 0.30}, 0.5 * smoothstep(0.35, 0.1, freckle));
    double pore = cellular(p * 2.2, 3, cell);
    skin = mix(skin, Rgb{0.66, 0.46, 0.38}, 0.25 * smoothstep(0.3, 0.05, pore));

    double redness = front * (0.8 * bump(ax - 7.0, 3.0, p.y - 39.0, 2.5) + 0.6 * bump(p.x, 1.8, p.y - 38.0, 1.5));
    skin = mix(skin, Rgb{0.80, 0.45, 0.40}, std::min(redness, 1.0) * 0.6);
    double lips = front * std::max(bump(p.x, 3.0, p.y - 33.4, 0.75), bump(p.x, 2.6, p.y - 31.4, 0.8));
    skin = mix(skin, Rgb{0.66, 0.32, 0.32}, smoothstep(0.35, 0.6, lips));

    double brows = front * bump(ax - 4.6, 2.8, p.y - 49.6 + 0.06 * (ax - 4.6) * (ax - 4.6), 0.75);
    double browHair = 0.6 + 0.4 * hairStrands(theta * 3.0, phi * 1.0);
    skin = mix(skin, Rgb{0.22, 0.14, 0.09}, smoothstep(0.3, 0.7, brows) * browHair);

    // Eyes on the eyeball bumps: sclera, iris, pupil.
    double ex = ax - 4.8, ey = p.y - 45.8;
    double eye = front * bump(ex, 2.0, ey, 0.95);
    double iris = std::sqrt(ex * ex + ey * ey);
    Rgb eyeColour = mix(Rgb{0.86, 0.84, 0.80}, Rgb{0.22, 0.36, 0.48}, smoothstep(0.9, 0.75, iris));
    eyeColour = mix(eyeColour, Rgb{0.03, 0.03, 0.03}, smoothstep(0.38, 0.3, iris));
    skin = mix(skin, eyeColour, smoothstep(0.45, 0.6, eye));

    double hair = hairMask(p, phi);
    Rgb hairColour = mix(Rgb{0.12, 0.075, 0.05}, Rgb{0.30, 0.20, 0.12}, hairStrands(theta, phi));
    return mix(skin, hairColour, hair);
}

// Height (model units) for the normal map: pores, fine skin noise, forehead wrinkles, hair strands.
double detailHeight(const SurfacePoint& sp, double theta, double phi) {
    const V3 p = sp.base;
    const double front = smoothstep(2.0, 9.0, p.z);
    uint32_t cell = 0;
    double pore = cellular(p * 2.2, 3, cell);
    double h = -0.07 * smoothstep(0.3, 0.0, pore);                // pores, ~0.3 units across
    h += 0.05 * fbm(p * 0.9, 3, 4);                               // uneven skin
    double forehead = front * bump(p.x, 6.0, p.y - 53.0, 2.2);    // three soft creases
    h += forehead * 0.12 * std::sin((p.y - 53.0) * 2.4);
    double hair = hairMask(p, phi);
    return h * (1 - hair) + hair * 0.25 * hairStrands(theta, phi);
}

// ---- writers (temporary file + rename: an interrupted build leaves no truncated asset) ----

bool replaceFile(const fs::path& temp, const fs::path& target) {
    std::error_code ec;
    fs::rename(temp, target, ec);
    if (ec) {
        std::cerr << "generate_head: cannot write " << target << ": " << ec.message() << "\n";
        fs::remove(temp, ec);
        return false;
    }
    return true;
}

// Unique per process: two build folders over one source tree may run this at the same time.
fs::path temporaryFor(const fs::path& target) {
    fs::path temp = target;
    temp += ".tmp" + std::to_string(getpid());
    return temp;
}

bool savePng(FIBITMAP* bitmap, const fs::path& target) {
    const fs::path temp = temporaryFor(target);
    bool ok = FreeImage_Save(FIF_PNG, bitmap, temp.c_str(), PNG_DEFAULT);
    FreeImage_Unload(bitmap);
    if (!ok) {
        std::cerr << "generate_head: FreeImage could not write " << temp << "\n";
        std::error_code ec;
        fs::remove(temp, ec);
        return false;
    }
    return replaceFile(temp, target);
}

BYTE toByte(double c) { return BYTE(std::lround(255.0 * std::clamp(c, 0.0, 1.0))); }

bool writeMesh(const RingSpacing& rings, const fs::path& target) {
    // Seam columns and pole rows are duplicated with bit-identical positions and normals, so every face
    // can use one index for v/vt/vn (as the thesis's scan did) while the surface stays watertight.
    const int rowLen = kColumns + 1;
    std::vector<V3> positions(size_t(kRings + 1) * rowLen);
    for (int i = 0; i <= kRings; ++i) {
        double theta = rings.theta(double(i) / kRings);
        if (i == 0) theta = 0.0;
        if (i == kRings) theta = kPi;
        for (int j = 0; j <= kColumns; ++j) {
            double phi = phiFromU(double(j % kColumns) / kColumns);
            positions[size_t(i) * rowLen + j] = surfacePoint(theta, (i == 0 || i == kRings) ? 0.0 : phi).position;
        }
    }

    struct Tri {
        int a, b, c;
    };
    std::vector<Tri> tris;
    for (int i = 0; i < kRings; ++i)
        for (int j = 0; j < kColumns; ++j) {
            int a = i * rowLen + j, b = i * rowLen + j + 1, c = (i + 1) * rowLen + j + 1, d = (i + 1) * rowLen + j;
            // Counter-clockwise seen from outside: with u to the right and v up, rows go downwards.
            if (i != 0) tris.push_back({a, d, b});
            if (i != kRings - 1) tris.push_back({b, d, c});
        }

    // Area-weighted normals on the welded surface (seam column j == kColumns is column 0; a pole is one vertex).
    auto weld = [&](int idx) {
        int i = idx / rowLen, j = idx % rowLen;
        if (i == 0) return 0;
        if (i == kRings) return kRings * rowLen;
        return i * rowLen + (j % kColumns);
    };
    std::vector<V3> normals(positions.size());
    for (const Tri& t : tris) {
        V3 n = cross(positions[t.b] - positions[t.a], positions[t.c] - positions[t.a]);
        for (int v : {t.a, t.b, t.c}) normals[weld(v)] = normals[weld(v)] + n;
    }
    for (size_t v = 0; v < normals.size(); ++v) normals[v] = normalize(normals[weld(int(v))]);

    const fs::path temp = temporaryFor(target);
    {
        std::ofstream out(temp);
        out << "# head.obj: PROCEDURAL stand-in for the thesis's scanned head (ir-ltd.net, 14581 polygons), which\n"
               "# is not available. Written by scenes/assets/generate_head.cpp; textures head_diffuse.png and\n"
               "# head_normal.png (tangent-space, OpenGL convention) use these texture coordinates.\n"
               "# Closed surface, +Y up, face towards +Z, model units ~10x the scene's (crown y = 62, chin y = 27);\n"
               "# vt v = 0 is the bottom row of the image, u = 0.5 the face, the u seam runs down the back.\n"
            << "# " << positions.size() << " vertices, " << tris.size() << " triangles\n"
            << "g head\n";
        char line[128];
        for (const V3& p : positions) {
            std::snprintf(line, sizeof line, "v %.5f %.5f %.5f\n", p.x, p.y, p.z);
            out << line;
        }
        for (int i = 0; i <= kRings; ++i)
            for (int j = 0; j <= kColumns; ++j) {
                // At a pole each triangle gets its own copy of the pole, at the middle of its column: column
                // j's triangle uses top copy j + 1 and bottom copy j (see the loop that builds `tris`).
                double u = double(j) / kColumns;
                if (i == 0) u = (j - 0.5) / kColumns;
                if (i == kRings) u = (j + 0.5) / kColumns;
                std::snprintf(line, sizeof line, "vt %.6f %.6f\n", std::clamp(u, 0.0, 1.0), 1.0 - double(i) / kRings);
                out << line;
            }
        for (const V3& n : normals) {
            std::snprintf(line, sizeof line, "vn %.6f %.6f %.6f\n", n.x, n.y, n.z);
            out << line;
        }
        for (const Tri& t : tris) {
            std::snprintf(line, sizeof line, "f %d/%d/%d %d/%d/%d %d/%d/%d\n", t.a + 1, t.a + 1, t.a + 1, t.b + 1,
                          t.b + 1, t.b + 1, t.c + 1, t.c + 1, t.c + 1);
            out << line;
        }
        if (!out.flush()) {
            std::cerr << "generate_head: cannot write " << temp << "\n";
            return false;
        }
    }
    return replaceFile(temp, target);
}

bool writeTextures(const RingSpacing& rings, const fs::path& diffusePath, const fs::path& normalPath) {
    const int n = kTextureSize;
    // Texel centres; row j of FreeImage's bitmap (scanline 0 = bottom) is v = (j + 0.5) / n.
    std::vector<SurfacePoint> points(size_t(n) * n);
    std::vector<double> height(size_t(n) * n);
    std::vector<double> thetas(n);
    for (int j = 0; j < n; ++j) thetas[j] = rings.theta(1.0 - (j + 0.5) / n);

    FIBITMAP* diffuse = FreeImage_Allocate(n, n, 24);
    FIBITMAP* normal = FreeImage_Allocate(n, n, 24);
    if (!diffuse || !normal) {
        std::cerr << "generate_head: out of memory\n";
        return false;
    }
    for (int j = 0; j < n; ++j) {
        BYTE* line = FreeImage_GetScanLine(diffuse, j);
        for (int i = 0; i < n; ++i) {
            double phi = phiFromU((i + 0.5) / n);
            SurfacePoint sp = surfacePoint(thetas[j], phi);
            points[size_t(j) * n + i] = sp;
            height[size_t(j) * n + i] = detailHeight(sp, thetas[j], phi);
            Rgb c = albedo(sp, thetas[j], phi);
            line[3 * i + FI_RGBA_RED] = toByte(c.r);
            line[3 * i + FI_RGBA_GREEN] = toByte(c.g);
            line[3 * i + FI_RGBA_BLUE] = toByte(c.b);
        }
    }

    // Tangent-space normal from the height field's slope along T = dP/du and B = dP/dv (central
    // differences in texels, divided by the surface distance they span): n = normalize(-dh/dT, -dh/dB, 1),
    // stored as n·0.5 + 0.5 with green = +B (OpenGL convention).
    for (int j = 0; j < n; ++j) {
        BYTE* line = FreeImage_GetScanLine(normal, j);
        int j0 = std::max(j - 1, 0), j1 = std::min(j + 1, n - 1);
        for (int i = 0; i < n; ++i) {
            int i0 = (i + n - 1) % n, i1 = (i + 1) % n;  // u wraps around the head
            auto at = [&](int ii, int jj) { return size_t(jj) * n + ii; };
            double du = length(points[at(i1, j)].position - points[at(i0, j)].position);
            double dv = length(points[at(i, j1)].position - points[at(i, j0)].position);
            double slopeU = du > 1e-6 ? (height[at(i1, j)] - height[at(i0, j)]) / du : 0.0;
            double slopeV = dv > 1e-6 ? (height[at(i, j1)] - height[at(i, j0)]) / dv : 0.0;
            V3 nt = normalize({-slopeU, -slopeV, 1.0});
            line[3 * i + FI_RGBA_RED] = toByte(nt.x * 0.5 + 0.5);
            line[3 * i + FI_RGBA_GREEN] = toByte(nt.y * 0.5 + 0.5);
            line[3 * i + FI_RGBA_BLUE] = toByte(nt.z * 0.5 + 0.5);
        }
    }
    bool ok = savePng(diffuse, diffusePath);
    return savePng(normal, normalPath) && ok;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: generate_head <output folder>\n";
        return 2;
    }
    const fs::path dir = argv[1];
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) {
        std::cerr << "generate_head: folder " << dir << " does not exist\n";
        return 1;
    }
    FreeImage_Initialise(FALSE);
    const RingSpacing rings;
    bool ok = writeMesh(rings, dir / "head.obj");
    ok = writeTextures(rings, dir / "head_diffuse.png", dir / "head_normal.png") && ok;
    FreeImage_DeInitialise();
    return ok ? 0 : 1;
}

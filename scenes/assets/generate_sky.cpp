// generate_sky (build-time tool): writes sky.pfm, an equirectangular HDR sky for SPEC §7's EnvironmentMap: a blue
// gradient above the horizon, a small, very bright sun, and a dark ground below. Usage: generate_sky <output folder>
//
// 512 × 256 float RGB texels in the layout SPEC §7 reads (v = 0 the top row, u = 0.5 + atan2(x, −z)/(2π)). The sun
// is a disk of angular radius 1.5° (the real one is 0.27°; wider and dimmer, its caustics through glass are
// fireflies a tenth as bright) and radiance 3000·(1, 0.95, 0.85), centred at
// elevation 35° and u = 0.35, i.e. towards (−0.663, 0.574, −0.481) with EnvironmentRotation 0. Its disk is
// about 4 texels across, each texel near it holding the mean over 32 × 32 points of it, so the sun's power does not
// depend on where the grid falls: it gives about 90 % of a horizontal surface's irradiance (3.9 of 4.4).
// Deterministic: no noise, the same bytes on every run.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include <unistd.h>

namespace {

namespace fs = std::filesystem;

constexpr double kPi = 3.14159265358979323846;
constexpr int kWidth = 512, kHeight = 256;
// Points per texel side: many where the sun's disk may reach (its edge must not depend on the grid), few elsewhere.
constexpr int kSunSamples = 32, kSkySamples = 4;

constexpr double kSunElevation = 35.0 * kPi / 180.0;
constexpr double kSunU = 0.35;
constexpr double kSunRadius = 1.5 * kPi / 180.0;
constexpr double kSunRadiance = 3000.0;

struct Rgb {
    double r = 0, g = 0, b = 0;
};
Rgb operator+(Rgb a, Rgb b) { return {a.r + b.r, a.g + b.g, a.b + b.b}; }
Rgb operator*(Rgb a, double s) { return {a.r * s, a.g * s, a.b * s}; }
Rgb mix(Rgb a, Rgb b, double t) { return a * (1.0 - t) + b * t; }

struct Dir {
    double x, y, z;
};

// SPEC §7's inverse: the direction of map coordinates (u, v).
Dir directionAt(double u, double v) {
    const double theta = kPi * v, phi = 2.0 * kPi * (u - 0.5);
    return {std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi)};
}

const Dir kSun = directionAt(kSunU, 0.5 - kSunElevation / kPi);

// Radiance towards d: the sky's gradient by elevation (a whiter horizon, a deeper blue overhead), a faint
// aureole about the sun, the sun's disk, and a dark brown ground, the horizon a sharp edge.
Rgb radiance(Dir d) {
    const double cosSun = std::clamp(d.x * kSun.x + d.y * kSun.y + d.z * kSun.z, -1.0, 1.0);
    const double fromSun = std::acos(cosSun);
    if (d.y < 0.0) return {0.10, 0.085, 0.07};
    const Rgb horizon{0.75, 0.85, 1.0}, zenith{0.12, 0.28, 0.75};
    Rgb sky = mix(horizon, zenith, std::sqrt(d.y)) * 0.35;
    sky = sky + Rgb{1.0, 0.9, 0.7} * (2.0 * std::exp(-fromSun / (4.0 * kPi / 180.0)));
    if (fromSun <= kSunRadius) sky = sky + Rgb{1.0, 0.95, 0.85} * kSunRadiance;
    return sky;
}

// Texel (i, j), j = 0 the top row: the mean of radiance over a grid of points inside it.
Rgb texel(int i, int j) {
    const Dir centre = directionAt((i + 0.5) / kWidth, (j + 0.5) / kHeight);
    const double fromSun = std::acos(std::clamp(centre.x * kSun.x + centre.y * kSun.y + centre.z * kSun.z, -1.0, 1.0));
    const int n = fromSun < kSunRadius + 2.0 * kPi / kHeight ? kSunSamples : kSkySamples;
    Rgb sum;
    for (int a = 0; a < n; ++a)
        for (int b = 0; b < n; ++b)
            sum = sum + radiance(directionAt((i + (a + 0.5) / n) / kWidth, (j + (b + 0.5) / n) / kHeight));
    return sum * (1.0 / (n * n));
}

// Little-endian float bytes (PFM's scale −1), whatever the machine.
void putFloat(std::string& out, float f) {
    uint32_t bits;
    std::memcpy(&bits, &f, 4);
    for (int k = 0; k < 4; ++k) out.push_back(char((bits >> (8 * k)) & 0xff));
}

// PFM: "PF", the size, the scale (negative: little-endian), then the rows bottom first.
std::string pfm() {
    std::string out = "PF\n" + std::to_string(kWidth) + " " + std::to_string(kHeight) + "\n-1.0\n";
    for (int j = kHeight - 1; j >= 0; --j)
        for (int i = 0; i < kWidth; ++i) {
            const Rgb c = texel(i, j);
            putFloat(out, float(c.r));
            putFloat(out, float(c.g));
            putFloat(out, float(c.b));
        }
    return out;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: generate_sky <output folder>\n";
        return 2;
    }
    const fs::path target = fs::path(argv[1]) / "sky.pfm";
    // A temporary per process, then a rename: an interrupted build leaves no truncated sky, and two build
    // folders over one source tree may run this at the same time.
    fs::path temp = target;
    temp += ".tmp" + std::to_string(getpid());
    {
        const std::string bytes = pfm();
        std::ofstream out(temp, std::ios::binary);
        out.write(bytes.data(), std::streamsize(bytes.size()));
        if (!out.flush()) {
            std::cerr << "generate_sky: cannot write " << temp << "\n";
            return 1;
        }
    }
    std::error_code ec;
    fs::rename(temp, target, ec);
    if (ec) {
        std::cerr << "generate_sky: cannot write " << target << ": " << ec.message() << "\n";
        fs::remove(temp, ec);
        return 1;
    }
    return 0;
}

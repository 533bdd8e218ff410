// Formatting of render statistics as text and JSON.
#include "render_stats.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace trazo {

namespace {

std::string jsonString(const std::string& s) {
    std::string out = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') out += '\\', out += c;
        else if ((unsigned char)c < 0x20) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\u%04x", c);
            out += buf;
        } else out += c;
    }
    return out + "\"";
}

std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

}  // namespace

std::string formatStatsSummary(const RenderStats& s) {
    char buf[512];
    std::snprintf(buf, sizeof buf,
                  "scene creation %.4f s, upload %.4f s, render %.4f s\n"
                  "%u x %u, %u passes (full cycle %u), %llu rays, %.2f Mrays/s on %s (%s)\n",
                  s.parseSeconds, s.uploadSeconds, s.renderSeconds, s.width, s.height, s.spp, s.fullCycle,
                  (unsigned long long)s.rays, s.mraysPerSecond(), s.backend.c_str(), s.device.c_str());
    return buf;
}

std::string formatStatsJson(const RenderStats& s) {
    std::string j = "{\n";
    auto add = [&](const char* key, const std::string& value, bool last = false) {
        j += std::string("  \"") + key + "\": " + value + (last ? "\n" : ",\n");
    };
    add("scene", jsonString(s.scene));
    add("parse_s", number(s.parseSeconds));
    add("upload_s", number(s.uploadSeconds));
    add("render_s", number(s.renderSeconds));
    add("spp", std::to_string(s.spp));
    add("full_cycle_spp", std::to_string(s.fullCycle));
    add("rays", std::to_string(s.rays));
    add("mrays_per_s", number(s.mraysPerSecond()));
    add("backend", jsonString(s.backend));
    add("device", jsonString(s.device));
    add("width", std::to_string(s.width));
    add("height", std::to_string(s.height));
    add("seed", std::to_string(s.seed));
    add("features", jsonString(s.features), true);
    return j + "}\n";
}

bool writeTextFileAtomically(const std::string& path, const std::string& text, std::string& error) {
    const std::string temp = path + ".tmp-trazo";
    {
        std::ofstream f(temp, std::ios::binary);
        if (!(f << text) || !f.flush()) {
            error = "cannot write " + path + ": " + std::strerror(errno);
            f.close();
            std::remove(temp.c_str());
            return false;
        }
    }
    std::error_code ec;
    std::filesystem::rename(temp, path, ec);
    if (ec) {
        error = "cannot write " + path + ": " + ec.message();
        std::remove(temp.c_str());
        return false;
    }
    return true;
}

}  // namespace trazo

// Formatting of render statistics as text and JSON.
#include "render_stats.h"

#include <cmath>
#include <cstdio>

namespace trazo {

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

std::string jsonNumber(double v) {
    if (!std::isfinite(v)) return "null";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

std::string formatStatsSummary(const RenderStats& s) {
    char buf[768];
    std::snprintf(buf, sizeof buf,
                  "scene creation %.4f s (read %.4f s, build %.4f s), upload %.4f s, render %.4f s, peak memory %.0f MB\n"
                  "%u x %u, %u passes (full cycle %u; blocks %s%s), %llu rays, %.2f Mrays/s on %s (%s)\n",
                  s.parseSeconds, s.readSeconds, s.buildSeconds, s.uploadSeconds, s.renderSeconds, s.peakRssMb,
                  s.width, s.height, s.spp, s.fullCycle,
                  s.blocks.c_str(), s.fixedGrid ? ", the fixed grid" : "", (unsigned long long)s.rays,
                  s.mraysPerSecond(), s.backend.c_str(), s.device.c_str());
    std::string out = buf;
    if (std::isfinite(s.estimatedRelError)) {
        std::snprintf(buf, sizeof buf, "estimated relative error %.3g%%%s", 100.0 * s.estimatedRelError,
                      s.estimateBalanced ? "" : " (rough: passes not a multiple of 2 cycles)");
    } else {
        std::snprintf(buf, sizeof buf, "estimated relative error: n/a (needs 2 or more passes)");
    }
    out += buf;
    if (s.targetError > 0.0) {
        std::snprintf(buf, sizeof buf, "; target %.3g%% %s", 100.0 * s.targetError,
                      s.reachedTarget ? "reached" : "not reached (pass or time limit first)");
        out += buf;
    }
    return out + "\n";
}

std::string formatStatsJson(const RenderStats& s) {
    std::string j = "{\n";
    auto add = [&](const char* key, const std::string& value, bool last = false) {
        j += std::string("  \"") + key + "\": " + value + (last ? "\n" : ",\n");
    };
    add("scene", jsonString(s.scene));
    add("parse_s", jsonNumber(s.parseSeconds));
    add("read_s", jsonNumber(s.readSeconds));
    add("build_s", jsonNumber(s.buildSeconds));
    add("upload_s", jsonNumber(s.uploadSeconds));
    add("render_s", jsonNumber(s.renderSeconds));
    add("write_s", jsonNumber(s.writeSeconds));
    add("spp", std::to_string(s.spp));
    add("full_cycle_spp", std::to_string(s.fullCycle));
    add("rays", std::to_string(s.rays));
    add("mrays_per_s", jsonNumber(s.mraysPerSecond()));
    add("backend", jsonString(s.backend));
    add("device", jsonString(s.device));
    add("width", std::to_string(s.width));
    add("height", std::to_string(s.height));
    add("seed", std::to_string(s.seed));
    add("features", jsonString(s.features));
    add("fixed_grid", s.fixedGrid ? "true" : "false");
    add("blocks", jsonString(s.blocks));
    add("estimated_rel_error", jsonNumber(s.estimatedRelError));
    add("estimate_balanced", s.estimateBalanced ? "true" : "false");
    add("target_error", jsonNumber(s.targetError));
    add("reached_target", s.reachedTarget ? "true" : "false");
    add("peak_rss_mb", jsonNumber(s.peakRssMb), true);
    return j + "}\n";
}

}  // namespace trazo

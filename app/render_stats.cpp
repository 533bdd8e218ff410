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
    if (s.noSamplingNoise) {
        std::snprintf(buf, sizeof buf, "relative error 0 (no sampling noise: every pass is the same image)");
    } else if (std::isfinite(s.estimatedRelError) && s.probePixels > 0) {
        std::snprintf(buf, sizeof buf, "estimated relative error %.3g%% (error probe of %u pixels)",
                      100.0 * s.estimatedRelError, s.probePixels);
    } else if (std::isfinite(s.estimatedRelError)) {
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

void JsonObject::add(const char* key, const std::string& value) {
    if (!body_.empty()) body_ += ",\n";
    body_ += std::string("  \"") + key + "\": " + value;
}

std::string formatStatsJson(const RenderStats& s) {
    JsonObject j;
    j.add("scene", jsonString(s.scene));
    j.add("parse_s", jsonNumber(s.parseSeconds));
    j.add("read_s", jsonNumber(s.readSeconds));
    j.add("build_s", jsonNumber(s.buildSeconds));
    j.add("upload_s", jsonNumber(s.uploadSeconds));
    j.add("render_s", jsonNumber(s.renderSeconds));
    j.add("write_s", jsonNumber(s.writeSeconds));
    j.add("spp", std::to_string(s.spp));
    j.add("full_cycle_spp", std::to_string(s.fullCycle));
    j.add("rays", std::to_string(s.rays));
    j.add("mrays_per_s", jsonNumber(s.mraysPerSecond()));
    j.add("backend", jsonString(s.backend));
    j.add("device", jsonString(s.device));
    j.add("width", std::to_string(s.width));
    j.add("height", std::to_string(s.height));
    j.add("seed", std::to_string(s.seed));
    j.add("features", jsonString(s.features));
    j.add("fixed_grid", s.fixedGrid ? "true" : "false");
    j.add("blocks", jsonString(s.blocks));
    j.add("estimated_rel_error", jsonNumber(s.estimatedRelError));
    j.add("estimate_balanced", s.estimateBalanced ? "true" : "false");
    j.add("no_sampling_noise", s.noSamplingNoise ? "true" : "false");
    j.add("error_probe_pixels", std::to_string(s.probePixels));
    j.add("target_error", jsonNumber(s.targetError));
    j.add("reached_target", s.reachedTarget ? "true" : "false");
    j.add("peak_rss_mb", jsonNumber(s.peakRssMb));
    return j.text();
}

}  // namespace trazo

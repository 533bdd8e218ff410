// Parameter values (host): the reader's checks on one parameter line, and the viewer's edit ranges beside them
// so the two cannot drift apart.
#include "scene/param_check.h"

#include <algorithm>
#include <cfloat>
#include <charconv>
#include <climits>
#include <cmath>

#include "scene/did_you_mean.h"

namespace trazo {
namespace {

std::string kindWord(ValueKind kind, int count) {
    const bool plural = count != 1;
    switch (kind) {
        case ValueKind::Real: return plural ? "numbers" : "number";
        case ValueKind::Int: return plural ? "integers" : "integer";
        case ValueKind::Name: return plural ? "names" : "name";
        case ValueKind::Path: return plural ? "paths in double quotes" : "path in double quotes";
    }
    return "values";
}

bool isInteger(const std::string& text, double& out) {
    const char* first = text.data();
    const char* last = first + text.size();
    if (first != last && *first == '+') ++first;
    long long v = 0;
    auto [ptr, ec] = std::from_chars(first, last, v);
    if (ec != std::errc() || ptr != last || v < INT_MIN || v > INT_MAX) return false;
    out = double(v);
    return true;
}

// The checks bounded at render time are read as their sign check; checkRenderBounds does the rest.
ValueCheck readTimeCheck(ValueCheck check) {
    switch (check) {
        case ValueCheck::StrataQuality:
        case ValueCheck::ReflectionDepth: return ValueCheck::NonNegative;
        case ValueCheck::GridCells: return ValueCheck::Positive;
        default: return check;
    }
}

// Why x fails `check`: the words after the parameter's name, before ", got VALUE"; "" when it passes. Antialiasing
// and NonZeroComponents, whose messages differ, are checkRange's own.
std::string rangeProblem(ValueCheck check, double x) {
    using C = ValueCheck;
    switch (check) {
        case C::Positive: return x > 0 ? "" : " must be positive";
        case C::NonNegative: return x < 0 ? " must not be negative" : "";
        case C::RenderSize:
            return x < 1 || x > kMaxRenderSize ? " must be between 1 and " + std::to_string(kMaxRenderSize) : "";
        case C::UnitInterval: return x < 0 || x > 1 ? " must be between 0 and 1" : "";
        case C::FieldOfView: return x > 0 && x < 180 ? "" : " must be between 0 and 180 degrees (exclusive)";
        case C::ConeAngle: return x < 0 || x > 180 ? " must be between 0 and 180 degrees" : "";
        case C::Flag: return x != 0 && x != 1 ? " must be 0 or 1" : "";
        case C::Dispersion:
            return x < 0 || x > kMaxDispersion ? " must be between 0 and 20 (an Abbe number of at least 1)" : "";
        case C::BounceCount: return x < 0 ? " must not be negative" : "";
        case C::Stops:
            return std::fabs(x) > kMaxStops ? " must be between -64 and 64 stops" : "";
        case C::Radius:
            if (!(x > 0)) return " must be positive";
            // As stored: "1e19" is kMaxRadius.
            return float(x) > kMaxRadius ? " must be at most 1e19 (its square must stay inside single precision)" : "";
        case C::LightPosition:
            return std::fabs(float(x)) > kMaxLightCoordinate
                       ? " must be within 1e18 of the origin in each coordinate (the squared distance to the light "
                         "must stay inside single precision)"
                       : "";
        case C::Colour:
            return std::fabs(float(x)) > kMaxColour
                       ? " components must be within ±1e12 (so that a pixel's sums stay inside single precision)"
                       : "";
        default: return "";
    }
}

// The range check of `info` on checked values; reports and returns false when it fails (warnings pass).
bool checkRange(const ParamInfo& info, const ParameterLine& line, size_t offset, ParamValue& v,
                Diagnostics& diags) {
    using C = ValueCheck;
    const std::string name(info.name);
    const ValueCheck check = readTimeCheck(info.check);
    auto at = [&](int i) { return SourceLocation{v.at.file, line.line, line.values[offset + size_t(i)].column}; };
    auto text = [&](int i) { return line.values[offset + size_t(i)].text; };
    for (int i = 0; i < info.count; ++i) {
        const double x = v.numbers[size_t(i)];
        if (check == C::Antialiasing && x != 1 && x != 4 && x != 16) {
            diags.warning(at(i), name + " must be 1, 4 or 16, got " + text(i) + "; using 1");
            v.numbers[size_t(i)] = 1;
        }
        if (check == C::BounceCount && x > kMaxBounces) {
            diags.warning(at(i), name + " " + text(i) + " is more than " + std::to_string(kMaxBounces) +
                                     "; using " + std::to_string(kMaxBounces) +
                                     " (a path that nothing absorbs would run every bounce)");
            v.numbers[size_t(i)] = kMaxBounces;
        }
        if (check == C::NonZeroComponents && x == 0)
            return diags.error(at(i), name + " component must not be zero (a singular transform)"), false;
        if (const std::string why = rangeProblem(check, x); !why.empty())
            return diags.error(at(i), name + why + ", got " + text(i)), false;
    }
    if (check == C::NonZeroVector || check == C::RotationAxis) {
        if (v.numbers[0] == 0 && v.numbers[1] == 0 && v.numbers[2] == 0) {
            const std::string what = check == C::RotationAxis ? "Rotation axis" : name;
            return diags.error(at(0), what + " must not be a zero-length vector"), false;
        }
    }
    return true;
}

}  // namespace

std::string_view twoWordSynonym(std::string_view first, std::string_view second) {
    if (first == "Roll" && second == "Angle") return "RollAngle";
    if (first == "Reflection" && second == "Angle") return "ReflectionAngle";
    if (first == "Reflection" && second == "Amount") return "ReflectionAmount";
    return {};
}

int checkParameter(const Block& block, std::span<const ParamInfo* const> params, const ParameterLine& line,
                   ParamValue& value, bool& valid, Diagnostics& diags) {
    using K = ValueKind;
    valid = false;
    const std::string& file = block.where.file;
    value.at = {file, line.line, 0};
    auto find = [&](std::string_view name) {
        for (size_t k = 0; k < params.size(); ++k)
            if (params[k]->name == name) return int(k);
        return -1;
    };
    int k = find(line.name);
    size_t offset = 0;  // values consumed by a two-word name
    if (k < 0 && !line.values.empty() && line.values[0].kind == BlockValue::Kind::Name) {
        const std::string_view synonym = twoWordSynonym(line.name, line.values[0].text);
        if (!synonym.empty() && (k = find(synonym)) >= 0) offset = 1;
    }
    if (k < 0) {
        std::vector<std::string_view> names;
        for (const ParamInfo* p : params) names.push_back(p->name);
        diags.error(value.at, "unknown parameter '" + line.name + "' in " + block.identifier,
                    didYouMean(line.name, names));
        return -1;
    }
    const ParamInfo& info = *params[size_t(k)];
    const std::string name(info.name);
    const size_t given = line.values.size() - offset;
    if (given != size_t(info.count)) {
        diags.error(value.at, name + " takes " + std::to_string(info.count) + " " + kindWord(info.kind, info.count) +
                                  ", got " + std::to_string(given));
        return k;
    }
    for (size_t i = 0; i < given; ++i) {
        const BlockValue& bv = line.values[offset + i];
        const SourceLocation at{file, line.line, bv.column};
        switch (info.kind) {
            case K::Real:
            case K::Int:
                if (bv.kind != BlockValue::Kind::Number) {
                    diags.error(at, name + ": expected " + (info.kind == K::Int ? "an integer" : "a number") +
                                        ", got '" + bv.text + "'");
                    return k;
                }
                if (!std::isfinite(bv.number) || !std::isfinite(float(bv.number))) {
                    diags.error(at, name + ": '" + bv.text + "' is not a finite number");
                    return k;
                }
                if (info.kind == K::Int && !isInteger(bv.text, value.numbers[i])) {
                    diags.error(at, name + ": expected an integer, got '" + bv.text + "'");
                    return k;
                }
                if (info.kind == K::Real) value.numbers[i] = bv.number;
                break;
            case K::Name:
                if (bv.kind == BlockValue::Kind::Path) {
                    diags.error(at, name + ": expected a name, got a quoted path");
                    return k;
                }
                if (!info.choices.empty() &&
                    std::find(info.choices.begin(), info.choices.end(), bv.text) == info.choices.end()) {
                    std::string words;
                    for (std::string_view w : info.choices) words += (words.empty() ? "" : ", ") + std::string(w);
                    diags.error(at, name + " must be one of " + words + ", got '" + bv.text + "'",
                                didYouMean(bv.text, {info.choices.begin(), info.choices.end()}));
                    return k;
                }
                value.text = bv.text;
                break;
            case K::Path:
                if (bv.kind != BlockValue::Kind::Path) {
                    diags.error(at, name + ": expected a path in double quotes, got '" + bv.text + "'",
                                "write \"" + bv.text + "\"");
                    return k;
                }
                if (bv.text.empty()) {  // it would name the scene's own folder, or nothing
                    diags.error(at, name + ": empty path");
                    return k;
                }
                if (bv.text.find('\0') != std::string::npos) {  // the lexer refuses a NUL; this guards other Blocks
                    diags.error(at, name + ": the path contains a NUL byte");
                    return k;
                }
                value.text = bv.text;
                break;
        }
    }
    valid = checkRange(info, line, offset, value, diags);
    return k;
}

void reportMissingRequired(const Block& block, std::span<const ParamInfo* const> params, const std::vector<bool>& seen,
                           Diagnostics& diags) {
    if (!block.complete) return;  // a refused line may have held it: that line's error says enough
    for (size_t k = 0; k < params.size(); ++k) {
        if (params[k]->required && !seen[k]) {
            diags.error(block.where,
                        "missing required parameter '" + std::string(params[k]->name) + "' in " + block.identifier);
        }
    }
}

ValueRange editRange(const ParamInfo& info) {
    using C = ValueCheck;
    const bool real = info.kind == ValueKind::Real;
    const double lowest = real ? -double(FLT_MAX) : double(INT_MIN);
    const double highest = real ? double(FLT_MAX) : double(INT_MAX);
    // The nearest value the reader accepts above an exclusive 0: the smallest positive float, or 1.
    const double abovePositive = real ? double(std::nextafter(0.0f, 1.0f)) : 1.0;
    switch (info.check) {
        case C::Positive: return {abovePositive, highest};
        case C::NonNegative: return {0, highest};
        case C::RenderSize: return {1, kMaxRenderSize};
        case C::Antialiasing: return {1, 16};
        case C::UnitInterval: return {0, 1};
        case C::FieldOfView: return {abovePositive, double(std::nextafter(180.0f, 0.0f))};
        case C::ConeAngle: return {0, 180};
        case C::Flag: return {0, 1};
        case C::Dispersion: return {0, kMaxDispersion};
        case C::BounceCount: return {0, kMaxBounces};
        case C::Stops: return {-kMaxStops, kMaxStops};
        case C::StrataQuality: return {0, kMaxStrataQuality};
        case C::ReflectionDepth: return {0, double(kMaxReflectionSteps)};
        case C::GridCells: return {1, kMaxGridSide};
        case C::Radius: return {abovePositive, double(kMaxRadius)};
        case C::LightPosition: return {-double(kMaxLightCoordinate), double(kMaxLightCoordinate)};
        case C::Colour: return {-double(kMaxColour), double(kMaxColour)};
        case C::None:
        case C::NonZeroVector:
        case C::RotationAxis:
        case C::NonZeroComponents: break;
    }
    return {lowest, highest};
}

bool fitToCheck(const ParamInfo& info, ParamValue& value) {
    if (info.kind != ValueKind::Real && info.kind != ValueKind::Int) return true;
    const ValueRange range = editRange(info);
    for (int i = 0; i < info.count; ++i) {
        double& x = value.numbers[size_t(i)];
        if (std::isnan(x)) return false;
        x = std::clamp(x, range.min, range.max);
        if (info.kind == ValueKind::Real) x = double(float(x));  // what the scene stores, and the writer writes
        if (info.check == ValueCheck::NonZeroComponents && x == 0) return false;
        if (info.check == ValueCheck::Antialiasing) x = x >= 16 ? 16 : x >= 4 ? 4 : 1;
    }
    const bool vector = info.check == ValueCheck::NonZeroVector || info.check == ValueCheck::RotationAxis;
    return !(vector && value.numbers[0] == 0 && value.numbers[1] == 0 && value.numbers[2] == 0);
}

}  // namespace trazo

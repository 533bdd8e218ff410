// Parameter values (host): what one parameter line may hold (kind, count, range check), the check the readers
// apply to a line, and the edit range the viewer's widgets keep to so that they never make a value the reader
// refuses.
#pragma once

#include <array>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "scene/block_lexer.h"
#include "scene/diagnostic.h"
#include "scene/scene.h"

namespace trazo {

enum class ValueKind { Real, Int, Name, Path };

// Range checks the reader applies to a parameter's values before storing them (SPEC §2, docs/LIMITS.md).
enum class ValueCheck {
    None,
    Positive,           // every value > 0 (radius, height, size, refraction index)
    NonNegative,        // every value >= 0 (roughness, CSG indices)
    RenderSize,         // 1 … kMaxRenderSize
    Antialiasing,       // 1, 4 or 16; anything else is a warning and falls back to 1
    NonZeroVector,      // not of zero length (Direction, Axis)
    RotationAxis,       // the first three values (the axis) not of zero length
    NonZeroComponents,  // no zero component (Scale: a singular transform)
    UnitInterval,       // 0 … 1 (Opacity, ReflectionAmount)
    FieldOfView,        // strictly between 0 and 180 degrees
    ConeAngle,          // 0 … 180 degrees (ReflectionAngle is the full cone angle)
    Flag,               // 0 or 1 (Fresnel)
    Dispersion,         // 0 … kMaxDispersion
    BounceCount,        // MaxBounces: ≥ 0; above kMaxBounces a warning and kMaxBounces
    Stops,              // Exposure: −kMaxStops … kMaxStops
    // Bounded where the render is sized (checkRenderBounds); read as NonNegative / Positive.
    StrataQuality,      // q: 0 … kMaxStrataQuality (2·q² strata)
    ReflectionDepth,    // 0 … kMaxReflectionSteps
    GridCells,          // nx ny: each >= 1, nx·ny ≤ kMaxGridStrata
    // Magnitudes whose squares or products single precision must hold (docs/LIMITS.md, Geometry).
    Radius,             // 0 < r ≤ kMaxRadius
    LightPosition,      // every coordinate within ±kMaxLightCoordinate
    Colour,             // every component within ±kMaxColour
};

// r² ≤ 1e38 inside float's 3.4e38: the sphere's and cylinder's quadratics square the radius.
constexpr float kMaxRadius = 1e19f;
// A light within 1e18 of the origin in each coordinate is less than 1.8e19 from any point within 1e19 of
// it, so the squared distance to the light stays inside float.
constexpr float kMaxLightCoordinate = 1e18f;
// A light's colour times a material's (1e24), times the Cook–Torrance peak (≤ 3.2e3) and 2^24 samples
// summed in float (2^20 strata × 16 antialiasing positions), is 5.4e34: four decades inside float.
constexpr float kMaxColour = 1e12f;

// Dispersion D = 20/V (V the Abbe number): 20 is V = 1, far past any glass (dense flint V ≈ 30, D ≈ 0.7).
// Within it every channel's index (SPEC §6) stays below twice RefractionIndex (blue's factor is 1 + 0.92·D/20).
constexpr float kMaxDispersion = 20.0f;

// Exposure: 2^64 times a pixel of at most kMaxColour-scale sums stays far inside float.
constexpr float kMaxStops = 64.0f;

// How the viewer shows a Real parameter (its widget); the reader treats them all as numbers.
enum class ValueUnit { None, Color, Degrees, Radians };

struct ParamInfo {
    std::string_view name;
    ValueKind kind = ValueKind::Real;
    int count = 1;  // number of values on the line
    bool required = false;
    std::string_view doc{};  // one line
    ValueCheck check = ValueCheck::None;
    bool accumulates = false;  // transforms: every line adds a step instead of the later one winning
    ValueUnit unit = ValueUnit::None;
    std::span<const std::string_view> choices{};  // a Name that must be one of these words (Integrator)
    // The default as the scene writer would write it ("—" when required, "" when there is none). Made by the
    // tables from a default-constructed struct, so scene.h's initialisers are the only defaults.
    std::string defaultText{};
};

// A parameter line whose values passed the table's kind, count, finiteness and range checks.
struct ParamValue {
    SourceLocation at;                // the line, column of the parameter name
    std::array<double, 4> numbers{};  // Real and Int values in order
    std::string text;                 // the Name or Path value
    size_t step = 0;                  // accumulating parameters: the step's place among the block's steps
    Vec3 vec3() const { return {float(numbers[0]), float(numbers[1]), float(numbers[2])}; }
    float real(int i = 0) const { return float(numbers[size_t(i)]); }
    int integer(int i = 0) const { return int(numbers[size_t(i)]); }
};

// The two-word spellings of SPEC §1 ("Roll" "Angle" -> "RollAngle"); "" when the pair is not one.
std::string_view twoWordSynonym(std::string_view first, std::string_view second);

// Checks one parameter line against `params`: returns its index (-1 for an unknown name, reported), with
// `valid` false when its values were rejected (reported; the parameter still counts as given).
int checkParameter(const Block& block, std::span<const ParamInfo* const> params, const ParameterLine& line,
                   ParamValue& value, bool& valid, Diagnostics& diags);
void reportMissingRequired(const Block& block, std::span<const ParamInfo* const> params,
                           const std::vector<bool>& seen, Diagnostics& diags);

// The closed range of each value a widget may set: every value in it passes the reader (checkParameter)
// and the render's bounds (checkRenderBounds), and the reader refuses the next value outside it (for
// GridCells: each side, so that the largest square grid is the bound). Unbounded sides are ±FLT_MAX, the
// reader's finiteness check on floats.
struct ValueRange {
    double min = 0, max = 0;
};
ValueRange editRange(const ParamInfo& info);

// An edited value brought inside editRange and the other checks: clamped into the range, Antialiasing to
// one of its three values. False (leave the old value) when no clamp can make it valid: a zero vector.
bool fitToCheck(const ParamInfo& info, ParamValue& value);

}  // namespace trazo

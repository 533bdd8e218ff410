// Parameter rows (host): one row per parameter of a block says its name, kind, range, doc, how a checked line
// goes into the struct (apply) and how the struct's value comes back out (extract), which the scene writer
// formats and the viewer's widgets edit. Builders for the common rows, and the reader's loop over a table.
#pragma once

#include <functional>
#include <span>
#include <string_view>
#include <type_traits>
#include <vector>

#include "scene/param_check.h"
#include "scene/param_format.h"

namespace trazo {

template <class Target>
struct ParamSpec {
    ParamInfo info;
    std::function<void(Target&, const ParamValue&)> apply;
    // The lines that say the struct's value: none when it is not given (no material, no texture), one, or for
    // an accumulating parameter one per step (ParamValue::step orders them among the block's steps).
    std::function<void(const Target&, std::vector<ParamValue>&)> extract;
};

template <class Field>
struct FieldShape;  // the kind and count a struct field is read as
template <>
struct FieldShape<float> {
    static constexpr ValueKind kind = ValueKind::Real;
    static constexpr int count = 1;
};
template <>
struct FieldShape<int> {
    static constexpr ValueKind kind = ValueKind::Int;
    static constexpr int count = 1;
};
template <>
struct FieldShape<Vec3> {
    static constexpr ValueKind kind = ValueKind::Real;
    static constexpr int count = 3;
};

template <class Field>
void storeField(Field& field, const ParamValue& v) {
    if constexpr (std::is_same_v<Field, Vec3>) field = v.vec3();
    else if constexpr (std::is_same_v<Field, float>) field = v.real();
    else field = v.integer();
}

template <class Field>
ParamValue loadField(const Field& field) {
    ParamValue v;
    if constexpr (std::is_same_v<Field, Vec3>) v.numbers = {field.x, field.y, field.z, 0};
    else v.numbers[0] = double(field);
    return v;
}

// A row for one float, int or Vec3 member; `at`, when given, remembers the line for later messages.
template <class Target, class Field>
ParamSpec<Target> field(std::string_view name, Field Target::*member, std::string_view doc,
                        ValueCheck check = ValueCheck::None, ValueUnit unit = ValueUnit::None,
                        SourceLocation Target::*at = nullptr) {
    const ParamInfo info{.name = name,
                         .kind = FieldShape<Field>::kind,
                         .count = FieldShape<Field>::count,
                         .doc = doc,
                         .check = check,
                         .unit = unit};
    return {info,
            [member, at](Target& t, const ParamValue& v) {
                storeField(t.*member, v);
                if (at) t.*at = v.at;
            },
            [member, at](const Target& t, std::vector<ParamValue>& out) {
                out.push_back(loadField(t.*member));
                if (at) out.back().at = t.*at;
            }};
}

template <class Target>
ParamSpec<Target> colour(std::string_view name, Vec3 Target::*member, std::string_view doc) {
    return field(name, member, doc, ValueCheck::Colour, ValueUnit::Color);
}

// The rows of a struct nested in `Outer` (a shape inside its reader's draft), as rows of `Outer`.
template <class Outer, class Inner>
std::vector<ParamSpec<Outer>> lift(Inner Outer::*member, const std::vector<ParamSpec<Inner>>& rows) {
    std::vector<ParamSpec<Outer>> lifted;
    for (const ParamSpec<Inner>& row : rows) {
        lifted.push_back({row.info, [member, apply = row.apply](Outer& o, const ParamValue& v) { apply(o.*member, v); },
                          [member, extract = row.extract](const Outer& o, std::vector<ParamValue>& out) {
                              extract(o.*member, out);
                          }});
    }
    return lifted;
}

// Each row's default text, from a default-constructed Target: scene.h's initialisers are the defaults.
template <class Target>
std::vector<ParamSpec<Target>> withDefaults(std::vector<ParamSpec<Target>> rows) {
    const Target defaults{};
    for (ParamSpec<Target>& row : rows) {
        if (row.info.required) {
            row.info.defaultText = "—";
            continue;
        }
        std::vector<ParamValue> values;
        row.extract(defaults, values);
        for (const ParamValue& v : values) {
            if (!row.info.defaultText.empty()) row.info.defaultText += ' ';
            row.info.defaultText += formatValues(row.info, v, {});
        }
    }
    return rows;
}

template <class Target>
std::vector<const ParamInfo*> infosOf(std::span<const ParamSpec<Target>> table) {
    std::vector<const ParamInfo*> params;
    params.reserve(table.size());
    for (const ParamSpec<Target>& spec : table) params.push_back(&spec.info);
    return params;
}

// Reads every parameter line of `block` into `target` through `table`.
template <class Target>
void readParameters(const Block& block, std::span<const ParamSpec<Target>> table, Target& target,
                    Diagnostics& diags) {
    const std::vector<const ParamInfo*> params = infosOf(table);
    std::vector<bool> seen(params.size(), false);
    for (const ParameterLine& line : block.parameters) {
        ParamValue value;
        bool valid = false;
        const int k = checkParameter(block, params, line, value, valid, diags);
        if (k < 0) continue;
        seen[size_t(k)] = true;
        if (valid) table[size_t(k)].apply(target, value);
    }
    reportMissingRequired(block, params, seen, diags);
}

}  // namespace trazo

// The viewer's widget limits against the reader: for every row a panel edits, both ends of its widget's
// range (widgetFor) pass the reader's checks and the render's bounds, and the next value outside each end is
// refused (an error, or Antialiasing's warning). Cross-module: scene tables, ui/model/param_widget.h, render bounds.
#include <gtest/gtest.h>

#include <cmath>

#include "model/param_widget.h"
#include "render/strata_plan.h"
#include "scene/block_table.h"

namespace trazo {
namespace {

// Reads `value` in every position of the row's line, applies it to a scene's `target`, and asks the reader
// and checkRenderBounds: true when both accept it.
template <class Target>
bool accepted(std::span<const ParamSpec<Target>> table, size_t k, double value, Target& (*target)(Scene&)) {
    const ParamInfo& info = table[k].info;
    ParamValue v;
    for (int i = 0; i < info.count; ++i) v.numbers[size_t(i)] = value;
    const std::string text = "Block\n{\n    " + std::string(info.name) + " " + formatValues(info, v, {}) + "\n}\n";
    Diagnostics diags;
    const std::vector<Block> blocks = lexBlocks(text, "ranges.scene", diags);
    if (blocks.size() != 1 || blocks[0].parameters.size() != 1) return false;
    ParamValue read;
    bool valid = false;
    const int found = checkParameter(blocks[0], infosOf(table), blocks[0].parameters[0], read, valid, diags);
    EXPECT_EQ(found, int(k)) << text;
    if (!valid || !diags.items.empty()) return false;  // an error, or a warning that changes it
    Scene scene;
    scene.areaLights.resize(1);
    table[k].apply(target(scene), read);
    return checkRenderBounds(scene, diags);
}

double outside(const ParamInfo& info, double bound, double direction) {
    if (info.kind == ValueKind::Int) return bound + direction;
    return double(std::nextafter(float(bound), float(direction * INFINITY)));
}

template <class Target>
int expectWidgetLimitsAreTheReaders(std::span<const ParamSpec<Target>> table, Target& (*target)(Scene&)) {
    int widgets = 0;
    for (size_t k = 0; k < table.size(); ++k) {
        const ParamInfo& info = table[k].info;
        const ParamWidget w = widgetFor(info);
        // Numbers only: a word list's combo offers only its words (ParamWidget::Kind::Words).
        const bool numeric = info.kind == ValueKind::Real || info.kind == ValueKind::Int;
        if (w.kind == ParamWidget::Kind::None || !numeric) continue;
        ++widgets;
        const std::string name(info.name);
        EXPECT_TRUE(accepted(table, k, w.min, target)) << name << " at its widget's minimum " << w.min;
        EXPECT_TRUE(accepted(table, k, w.max, target)) << name << " at its widget's maximum " << w.max;
        EXPECT_FALSE(accepted(table, k, outside(info, w.min, -1), target)) << name << " below " << w.min;
        EXPECT_FALSE(accepted(table, k, outside(info, w.max, +1), target)) << name << " above " << w.max;
    }
    return widgets;
}

TEST(ParamRanges, EveryWidgetSpansExactlyWhatTheReaderAccepts) {
    // Every numeric row has a widget (a name or a path has its own editor).
    auto numericRows = [](auto table) {
        int rows = 0;
        for (const auto& row : table) rows += row.info.kind == ValueKind::Real || row.info.kind == ValueKind::Int;
        return rows;
    };
    int widgets =
        expectWidgetLimitsAreTheReaders<SceneSettings>(sceneSettingsTable(), [](Scene& s) -> auto& { return s.settings; }) +
        expectWidgetLimitsAreTheReaders<Camera>(cameraTable(), [](Scene& s) -> auto& { return s.camera; });
    int lightRows = 0;
#define TRAZO_X(Data, array, Kind, ...)                                                                              \
    widgets += expectWidgetLimitsAreTheReaders<Kind>(lightTable<Kind>(), [](Scene& s) -> auto& { return s.array.emplace_back(); }); \
    lightRows += numericRows(lightTable<Kind>());
    TRAZO_LIGHT_KINDS(TRAZO_X)
#undef TRAZO_X
    // Materials: the panel edits the reader's draft.
    static MaterialDraft draft;
    const int materialWidgets = expectWidgetLimitsAreTheReaders<MaterialDraft>(
        materialTable(), [](Scene&) -> auto& { return draft; });
    EXPECT_EQ(widgets, numericRows(sceneSettingsTable()) + numericRows(cameraTable()) + lightRows);
    EXPECT_EQ(materialWidgets, numericRows(materialTable()));
    EXPECT_GE(materialWidgets, 8);  // the colours and the scalars of SPEC §3
}

TEST(ParamRanges, RenderBoundedSettingsStopAtTheirLimits) {
    // Read by eye from docs/LIMITS.md: q ≤ 724, ReflectionSteps ≤ 65 536, a 1024 × 1024 light grid.
    auto maxOf = [](auto table, std::string_view name) {
        for (const auto& row : table)
            if (row.info.name == name) return widgetFor(row.info).max;
        return -1.0;
    };
    EXPECT_EQ(maxOf(sceneSettingsTable(), "IndirectQuality"), 724);
    EXPECT_EQ(maxOf(sceneSettingsTable(), "ReflectionQuality"), 724);
    EXPECT_EQ(maxOf(sceneSettingsTable(), "ReflectionSteps"), 65536);
    EXPECT_EQ(maxOf(sceneSettingsTable(), "RenderWidth"), 16384);
    EXPECT_EQ(maxOf(lightTable<AreaLight>(), "Subdivision"), 1024);
}

TEST(ParamRanges, FitToCheckKeepsEditsReadable) {
    ParamInfo direction{.name = "Direction", .count = 3, .check = ValueCheck::NonZeroVector};
    ParamValue zero;
    EXPECT_FALSE(fitToCheck(direction, zero));  // the panel keeps the old direction
    ParamInfo aa{.name = "Antialiasing", .kind = ValueKind::Int, .check = ValueCheck::Antialiasing};
    ParamValue five;
    five.numbers[0] = 5;
    ASSERT_TRUE(fitToCheck(aa, five));
    EXPECT_EQ(five.numbers[0], 4);
    ParamInfo opacity{.name = "Opacity", .check = ValueCheck::UnitInterval};
    ParamValue big;
    big.numbers[0] = 7;
    ASSERT_TRUE(fitToCheck(opacity, big));
    EXPECT_EQ(big.numbers[0], 1);
    ParamValue nan;
    nan.numbers[0] = NAN;
    EXPECT_FALSE(fitToCheck(opacity, nan));
}

}  // namespace
}  // namespace trazo

// Tests of the viewer's widget choice for SPEC §7's settings: word lists get a combo of their words (with an
// entry for ViewTransform's unwritten default), Antialiasing keeps its numeric choice, EnvironmentRotation is a
// turn that still takes every angle the reader takes.
#include "model/param_widget.h"

#include <gtest/gtest.h>

#include <cfloat>
#include <string>

#include "scene/block_table.h"

namespace trazo {
namespace {

const ParamSpec<SceneSettings>& settingsRow(std::string_view name) {
    for (const ParamSpec<SceneSettings>& row : sceneSettingsTable())
        if (row.info.name == name) return row;
    ADD_FAILURE() << "no SceneSettings row " << name;
    return sceneSettingsTable()[0];
}

TEST(ParamWidget, WordListsGetACombo) {
    using Kind = ParamWidget::Kind;
    for (const char* name : {"Integrator", "LightSampling", "ViewTransform"}) {
        const ParamWidget w = widgetFor(settingsRow(name).info);
        EXPECT_EQ(w.kind, Kind::Words) << name;
    }
    EXPECT_EQ(widgetFor(settingsRow("Integrator").info).defaultLabel, nullptr);  // always written
    EXPECT_EQ(widgetFor(settingsRow("LightSampling").info).defaultLabel, nullptr);
    const char* autoLabel = widgetFor(settingsRow("ViewTransform").info).defaultLabel;
    ASSERT_NE(autoLabel, nullptr);
    EXPECT_EQ(std::string(autoLabel).rfind("auto", 0), 0u);
    EXPECT_EQ(widgetFor(settingsRow("Antialiasing").info).kind, Kind::Choice);
    EXPECT_EQ(widgetFor(settingsRow("MaxBounces").info).kind, Kind::Integer);
    EXPECT_EQ(widgetFor(settingsRow("Exposure").info).kind, Kind::Slider);  // ±64 stops
    EXPECT_EQ(widgetFor(settingsRow("EnvironmentMap").info).kind, Kind::None);  // a path: its own field
}

TEST(ParamWidget, EveryWordOfTheComboIsTheValueTheRowKeeps) {
    for (const char* name : {"Integrator", "LightSampling", "ViewTransform"}) {
        const ParamSpec<SceneSettings>& row = settingsRow(name);
        ASSERT_FALSE(row.info.choices.empty()) << name;
        for (std::string_view word : row.info.choices) {
            SceneSettings s;
            ParamValue v;
            v.text = std::string(word);
            row.apply(s, v);
            std::vector<ParamValue> back;
            row.extract(s, back);
            ASSERT_EQ(back.size(), 1u) << name << " " << word;
            EXPECT_EQ(back[0].text, word) << name;
        }
    }
}

TEST(ParamWidget, TheAutoEntryPutsViewTransformBackToItsDefault) {
    const ParamSpec<SceneSettings>& row = settingsRow("ViewTransform");
    SceneSettings s;
    s.viewTransform = ViewTransform::Srgb;
    EXPECT_TRUE(resetToUnwrittenDefault(s, row.info));
    EXPECT_EQ(s.viewTransform, ViewTransform::Auto);
    std::vector<ParamValue> written;
    row.extract(s, written);
    EXPECT_TRUE(written.empty());  // the default is written as nothing: the combo shows its auto entry
    s.integrator = IntegratorKind::Thesis;
    EXPECT_FALSE(resetToUnwrittenDefault(s, settingsRow("Integrator").info));  // no such default
    Camera c;
    EXPECT_FALSE(resetToUnwrittenDefault(c, settingsRow("ViewTransform").info));  // only SceneSettings has one
}

TEST(ParamWidget, EnvironmentRotationIsATurnOverTheReadersWholeRange) {
    const ParamWidget w = widgetFor(settingsRow("EnvironmentRotation").info);
    EXPECT_EQ(w.kind, ParamWidget::Kind::Turn);
    EXPECT_EQ(w.min, -double(FLT_MAX));  // typed values are the reader's (any finite angle)
    EXPECT_EQ(w.max, double(FLT_MAX));
    EXPECT_EQ(kTurnDegrees, 180.0f);
    for (const ParamSpec<Camera>& row : cameraTable()) {
        if (row.info.name == "FOV") EXPECT_EQ(widgetFor(row.info).kind, ParamWidget::Kind::Slider);  // bounded
    }
}

}  // namespace
}  // namespace trazo

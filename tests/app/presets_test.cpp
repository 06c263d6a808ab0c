// Every embedded preset parses cleanly and derives within the default limits.
#include <gtest/gtest.h>

#include "app/presets.hpp"
#include "core/derive.hpp"

namespace sprout {
namespace {

TEST(Presets, EveryPresetParsesWithoutWarningsAndDerives) {
    ASSERT_FALSE(presetNames().empty());
    for (const auto& name : presetNames()) {
        auto text = presetText(name);
        ASSERT_TRUE(text) << name;
        ParseResult r = parse(*text);
        for (const auto& d : r.diagnostics) ADD_FAILURE() << formatDiagnostic(d, name + ".lsys");
        ASSERT_TRUE(r.ok()) << name;
        EXPECT_TRUE(text->starts_with("#")) << name << " should start with a comment naming its source";
        DeriveResult d = derive(r.grammar, r.grammar->settings.iterations);
        EXPECT_TRUE(d.outcome.ok()) << name << ": " << d.outcome.message;
        EXPECT_GT(d.string->size(), 0u) << name;
    }
}

TEST(Presets, DefaultPlantExists) {
    EXPECT_TRUE(presetText(kDefaultPreset).has_value());
    EXPECT_TRUE(presetText("fern").has_value());
    EXPECT_TRUE(presetText("koch").has_value());
    EXPECT_TRUE(presetText("bush").has_value());
}

}  // namespace
}  // namespace sprout

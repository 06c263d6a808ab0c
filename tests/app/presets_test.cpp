// Every embedded preset parses cleanly and derives within the default limits.
#include <gtest/gtest.h>

#include "app/plant/presets.hpp"
#include "core/derive/d0l.hpp"
#include "core/language/file_kind.hpp"
#include "core/derive/derive.hpp"
#include "core/turtle/turtle.hpp"
#include "lpy/lpy.hpp"
#include "tests/core/same_drawing.hpp"

namespace sprout {
namespace {

TEST(Presets, EveryPresetParsesWithoutWarningsAndDerives) {
    ASSERT_FALSE(presetNames().empty());
    int lpyPresets = 0;
    for (const auto& name : presetNames()) {
        auto text = presetText(name);
        ASSERT_TRUE(text) << name;
        EXPECT_TRUE(text->starts_with("#") || text->starts_with("/*")) << name << " should start with a comment naming its source";
        if (detectFileKind("", *text) == FileKind::Lpy) {  // an L-Py model: its Python runs
            if (!lpy::pythonAvailable()) continue;
            lpy::Model m = lpy::runModel(*text, {});
            for (const auto& d : m.diagnostics) ADD_FAILURE() << formatDiagnostic(d, name + ".lpy");
            ASSERT_TRUE(m.ok()) << name;
            EXPECT_GT(m.drawable->axiom.size(), 100u) << name;
            EXPECT_GE(m.stepsDone, 4) << name;
            ++lpyPresets;
            continue;
        }
        ParseResult r = parseDetected(*text);
        for (const auto& d : r.diagnostics) ADD_FAILURE() << formatDiagnostic(d, name + ".lsys");
        ASSERT_TRUE(r.ok()) << name;
        DeriveResult d = derive(r.grammar, r.grammar->settings.iterations);
        EXPECT_TRUE(d.outcome.ok()) << name << ": " << d.outcome.message;
        EXPECT_GT(d.string->size(), 0u) << name;
    }
    if (lpy::pythonAvailable()) {
        EXPECT_GE(lpyPresets, 4);
    }
}

// Every D0L preset, at the first step with 40,000 modules or more, draws the same from its
// derivation tree as from its string.
TEST(Presets, D0LPresetsDrawTheSameFromTheirDerivationTree) {
    int fromTree = 0;
    for (const auto& name : presetNames()) {
        ParseResult r = parseDetected(*presetText(name));
        if (!r.ok() || !D0LExpander::applicable(*r.grammar)) continue;
        Derivation d(r.grammar);
        int n = r.grammar->settings.iterations;
        for (; n < 40; ++n) {
            if (!d.deriveTo(n).ok() || d.step(n)->size() >= 40000) break;
        }
        if (!d.deriveTo(n).ok() || d.step(n)->size() < 40000 || d.step(n)->size() > 4'000'000) continue;
        Geometry fromString, tree;
        TurtleOptions o{n, d.seed(), nullptr};
        o.fromTree = false;
        interpret(*d.step(n), *r.grammar, o, fromString);
        o.fromTree = true;
        fromTree += interpret(*d.step(n), *r.grammar, o, tree).fromTree;
        test::expectSameDrawing(tree, fromString, name + " n=" + std::to_string(n));
    }
    EXPECT_GE(fromTree, 10);
}

TEST(Presets, DefaultPlantExists) {
    EXPECT_TRUE(presetText(kDefaultPreset).has_value());
    EXPECT_TRUE(presetText("fern").has_value());
    EXPECT_TRUE(presetText("koch").has_value());
    EXPECT_TRUE(presetText("bush").has_value());
}

}  // namespace
}  // namespace sprout

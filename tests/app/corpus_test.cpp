// Files written by other people for other tools, read as a user brings them (issue 38): each
// file of a collection in ../shared/corpus opens through the same reader as `sprout render`
// (app/plant/source.hpp: the kind by content and extension, Lparser and Fractint translated),
// derives and draws something; every failure is named with its first message, and the count
// that opens is held. Skipped where the shared corpus is not beside the project.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "app/plant/source.hpp"
#include "core/derive/derive.hpp"
#include "core/derive/draw.hpp"
#include "core/language/file_kind.hpp"

namespace fs = std::filesystem;
using namespace sprout;

namespace {

// Empty when the file opens and draws; else why not (its first error).
std::string opensAndDraws(const fs::path& file) {
    SourceText src = readSource(file.string());
    if (!src.error.empty()) return src.error;
    for (const Diagnostic& d : src.diagnostics)
        if (d.severity == Severity::Error) return formatDiagnostic(d, src.diagnosticsName);
    ParseResult r = parse(src.text, parseOptionsFor(src.kind, src.includePath));
    for (const Diagnostic& d : r.diagnostics)
        if (d.severity == Severity::Error) return formatDiagnostic(d, src.displayName);
    if (!r.ok()) return src.displayName + ": cannot be read";
    DeriveOptions o;
    o.limits.maxModules = 20'000'000;  // a test's share of the machine
    DeriveResult d = derive(r.grammar, r.grammar->settings.iterations, o);
    if (!d.outcome.ok()) return src.displayName + ": " + d.outcome.message;
    Geometry geo;
    interpret(*d.string, *r.grammar, {r.grammar->settings.iterations, r.grammar->settings.seed, nullptr}, geo);
    if (geo.cylinders.size() + geo.surfaces.size() + geo.polygons.indices.size() == 0) return src.displayName + ": draws nothing";
    return {};
}

}  // namespace

// L-system Explorer's example files (Lowclouds/lsystem): the web's ABOP / cpfg dialect.
TEST(Corpus, LowcloudsFilesOpenAndDraw) {
    const fs::path dir = fs::path(SPROUT_SHARED_DIR) / "corpus" / "lowclouds";
    if (!fs::is_directory(dir)) GTEST_SKIP() << dir << " is not here";
    std::vector<fs::path> files;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        if (e.is_regular_file() && (e.path().extension() == ".ls" || e.path().extension() == ".l")) files.push_back(e.path());
    std::sort(files.begin(), files.end());
    int drawn = 0;
    std::string failures;
    for (const fs::path& f : files) {
        const std::string why = opensAndDraws(f);
        if (why.empty()) ++drawn;
        else failures += "  " + fs::relative(f, dir).string() + ": " + why + "\n";
    }
    std::printf("L-system Explorer corpus: %d of %zu files open and draw\n%s", drawn, files.size(), failures.c_str());
    EXPECT_GE(drawn, 69) << failures;
}

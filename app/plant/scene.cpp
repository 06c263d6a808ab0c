#include "app/plant/scene.hpp"

#include <chrono>
#include <filesystem>

#include "app/plant/presets.hpp"
#include "app/plant/source.hpp"
#include "core/base/read_file.hpp"
#include "core/scene/ifs.hpp"

namespace sprout {

std::optional<std::string> speciesText(const std::string& name, const std::vector<std::filesystem::path>& folders) {
    for (const std::filesystem::path& folder : folders) {
        const std::filesystem::path p = folder / name;
        if (std::filesystem::exists(p)) return readFile(p).value_or("");
    }
    if (auto t = presetText(name)) return std::string(*t);
    return std::nullopt;
}

GrownScene growScene(const std::string& text, const std::string& path, std::optional<std::uint64_t> seed,
                     const GrammarSource& species, const DeriveLimits& limits, Geometry& geometry,
                     std::vector<ForestPlant>* plants) {
    GrownScene out;
    ForestParseResult parsed = parseForest(text, parseOptionsFor(FileKind::Forest, path).include);
    out.diagnostics = std::move(parsed.diagnostics);
    if (!parsed.forest) return out;
    out.parsed = true;
    if (seed) parsed.forest->seed = *seed;
    out.seed = parsed.forest->seed;
    out.environment = parsed.forest->environment;
    out.built = buildForest(*parsed.forest, species, geometry, out.stats, out.error, limits, plants);
    return out;
}

bool buildForestScene(const std::string& source, std::optional<std::uint64_t> seed, const DeriveLimits& limits,
                      Geometry& geometry, ForestStats& fs, std::string& text, const Report& report, Environment* environment,
                      std::uint64_t* usedSeed) {
    std::filesystem::path dir;
    std::string path;  // the scene's file: a mesh an environment names is read beside it
    if (std::filesystem::exists(source)) {
        text = readSourceOrChunk(source, "forest").value_or("");
        dir = std::filesystem::path(source).parent_path();
        path = source;
    } else if (auto preset = presetText(source)) {
        text = std::string(*preset);
    }
    auto species = [&](const std::string& name) { return speciesText(name, {dir}); };
    GrownScene grown = growScene(text, path, seed, species, limits, geometry);
    for (const auto& d : grown.diagnostics) report(formatDiagnostic(d, source));
    if (!grown.parsed) return false;
    if (environment) *environment = std::move(grown.environment);
    if (usedSeed) *usedSeed = grown.seed;
    fs = grown.stats;
    if (!grown.built) {
        report(source + ": " + grown.error);
        return false;
    }
    return true;
}

IfsPicture drawIfs(const std::string& text, std::optional<std::uint64_t> seed, int width, int height, int threads,
                   const std::atomic<bool>* cancel) {
    IfsPicture out;
    IfsParseResult parsed = parseIfs(text);
    out.diagnostics = std::move(parsed.diagnostics);
    if (!parsed.ifs) return out;
    out.parsed = true;
    Ifs ifs = *parsed.ifs;
    if (seed) ifs.seed = *seed;
    out.seed = ifs.seed;
    out.points = ifs.points;
    const auto t0 = std::chrono::steady_clock::now();
    Density density;
    if (!chaosGame(ifs, width, height, density, threads, cancel)) return out;
    out.gameMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    out.drawn = true;
    out.width = density.width;
    out.height = density.height;
    out.rgba = toneMap(density, ifs.colour, 0xF4F2EAFF);
    return out;
}

}  // namespace sprout

#pragma once
// Trust before code runs. An L-Py model is a Python program: the viewer runs the Python of a
// text that came from outside (a file, a PNG carrying a grammar, a dropped file, an autosave
// or a recovered text) only once the user has said so. The answer is kept by the SHA-256 of
// the text in one small file under the user's config folder, so a model is asked about once;
// a changed file is another text and is asked about again. Presets and what the user types
// need no answer: they are Sprout's own or the user's.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace sprout::viewer {

// What a model imports: the modules named by its `import` and `from ... import` lines.
struct PythonImport {
    int line = 0;
    std::string module;
};
std::vector<PythonImport> pythonImports(std::string_view text);

enum class TrustAnswer { None, Trusted, Refused };

class TrustStore {
public:
    // `file`: empty is $XDG_CONFIG_HOME/sprout/trusted-models (~/.config/sprout/...).
    explicit TrustStore(std::filesystem::path file = {});
    TrustAnswer answer(std::string_view text) const;
    // Keeps the answer for this text (written atomically); false with the reason.
    bool remember(std::string_view text, TrustAnswer answer, std::string& error);
    const std::filesystem::path& file() const { return m_file; }

private:
    std::filesystem::path m_file;
};

}  // namespace sprout::viewer

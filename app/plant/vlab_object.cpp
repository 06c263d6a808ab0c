#include "app/plant/vlab_object.hpp"

#include <filesystem>
#include <sstream>

#include <algorithm>
#include <cctype>
#include <cstdlib>

#include "core/base/read_file.hpp"
#include "core/language/vlab/colours.hpp"

namespace sprout {
namespace {

namespace fs = std::filesystem;

struct Word {
    std::string text;
    int col = 0;  // 1-based
};

std::vector<Word> wordsOf(const std::string& line) {
    std::vector<Word> out;
    for (size_t i = 0; i < line.size();) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
        const size_t begin = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
        if (i > begin) out.push_back({line.substr(begin, i - begin), int(begin) + 1});
    }
    return out;
}

// How many arguments cpfg's option takes (control.c, ReadCommandLine); -1: an option it refuses.
int argumentsOf(const std::string& option) {
    static const char* outputs[] = {"rgb", "png", "bmp", "gif", "jpg", "pbm", "tiff", "ras", "tga",
                                    "rle", "ray", "ps",  "str", "vv",  "strb", "gls", "obj"};
    const std::string name = option.substr(1);
    for (const char* o : outputs)
        if (name == o) return 1;  // an output file
    switch (name.empty() ? '\0' : name[0]) {
        case 'a': case 'c': case 'd': case 'g': case 'h': case 'p': case 's': case 'v': case 'V': return 0;
        case 'b': case 'C': case 'S': case 'e': case 'M': case 'P': return 1;
        case 'm': return name == "mb" ? 0 : 1;
        case 'r': return name == "rmode" ? 1 : 0;
        case 'w':
            if (name == "wt") return 1;
            if (name == "wnb" || name == "wnm") return 0;
            return 2;  // -wr, -wpr, -wp, and -w: two numbers
        default: return -1;
    }
}

// What the options that concern the picture say (vlab_view.cpp applies them): material sets,
// colour maps, the reference set, the window's size. False, with a warning, for a set number
// cpfg ignores or a size that is no number.
void recordPictureOption(VlabObject& out, const std::string& folder, const Word& option, const std::vector<Word>& args, int line) {
    const std::string& o = option.text;
    auto warn = [&](std::string m) { out.diagnostics.push_back({line, option.col, std::move(m), Severity::Warning}); };
    if ((o[1] == 'M' || o[1] == 'm') && o != "-mb") {
        std::optional<int> set = vlab::colourSetNumber(o);
        if (!set) return warn("'" + o + "': cpfg's colour sets are 0 to 11; ignored, as cpfg does");
        out.colourFiles.push_back({*set, o[1] == 'M', (fs::path(folder) / args[0].text).string(), line, args[0].col});
    } else if (o.size() > 2 && o[1] == 'c' && std::isdigit(static_cast<unsigned char>(o[2]))) {
        out.referenceSet = std::clamp(std::atoi(o.c_str() + 2), 0, 11);
    } else if (o == "-w") {
        const int w = std::atoi(args[0].text.c_str()), h = std::atoi(args[1].text.c_str());
        if (w >= 16 && h >= 16 && w <= 8192 && h <= 8192) out.width = w, out.height = h;
        else warn("'-w " + args[0].text + " " + args[1].text + "': a window's size is two numbers from 16 to 8192; ignored");
    }
}

}  // namespace

std::optional<VlabObject> readVlabObject(const std::string& folder) {
    const fs::path specifications = fs::path(folder) / "specifications";
    std::error_code ec;
    if (!fs::is_regular_file(specifications, ec)) return std::nullopt;
    VlabObject out;
    out.specifications = specifications.string();
    auto error = [&](int line, int col, std::string message) {
        out.diagnostics.push_back({line, col, std::move(message), Severity::Error});
    };
    std::istringstream in(readFile(specifications).value_or(""));
    std::string text;
    for (int number = 1; std::getline(in, text); ++number) {
        const std::vector<Word> words = wordsOf(text);
        if (words.empty() || words[0].text != "cpfg") continue;
        std::string* files[] = {&out.lsystem, &out.view, &out.animation};
        size_t positional = 0;
        for (size_t k = 1; k < words.size(); ++k) {
            const Word& w = words[k];
            if (w.text[0] == '-') {
                const int n = argumentsOf(w.text);
                if (n < 0) {
                    error(number, w.col, "cpfg has no option '" + w.text + "'");
                    return out;
                }
                if (n > 0 && k + size_t(n) >= words.size()) {
                    error(number, w.col, "cpfg's option '" + w.text + "' takes " + std::to_string(n) + " argument" + (n > 1 ? "s" : ""));
                    return out;
                }
                recordPictureOption(out, folder, w, {words.begin() + long(k) + 1, words.begin() + long(k) + 1 + n}, number);
                if (w.text == "-e") out.environment = (fs::path(folder) / words[k + 1].text).string();  // vlab_environment.hpp
                if (w.text == "-a") out.animate = true;  // the viewer opens playing the animation file's frames
                k += size_t(n);
            } else if (positional < 3) {
                *files[positional++] = (fs::path(folder) / w.text).string();
            } else {
                error(number, w.col, "cpfg takes an L-system, a view file and an animation file; '" + w.text + "' is one more");
                return out;
            }
        }
        if (out.lsystem.empty()) error(number, words[0].col, "cpfg's line names no L-system");
        return out;
    }
    error(0, 0, "no line of it runs cpfg: Sprout opens the VLab objects whose model cpfg draws");
    return out;
}

}  // namespace sprout

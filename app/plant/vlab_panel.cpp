#include "app/plant/vlab_panel.hpp"

#include <filesystem>
#include <sstream>

#include "core/base/read_file.hpp"

namespace sprout {
namespace {

namespace fs = std::filesystem;

std::string trimmed(std::string s) {
    const size_t a = s.find_first_not_of(" \t\r");
    if (a == std::string::npos) return "";
    return s.substr(a, s.find_last_not_of(" \t\r") - a + 1);
}

}  // namespace

VlabPanel readVlabPanel(std::string_view text, const std::string& fileName) {
    VlabPanel out;
    std::istringstream in{std::string(text)};
    std::string line, type;
    VlabPanelItem item;
    bool haveMessage = false;
    int itemLine = 0;
    auto finish = [&] {
        if ((type == "SLIDER" || type == "BUTTON") && haveMessage) {
            item.slider = type == "SLIDER";
            out.items.push_back(item);
        } else if ((type == "SLIDER" || type == "BUTTON") && !haveMessage) {
            out.problems.push_back(fileName + ":" + std::to_string(itemLine) + ": this " + type +
                                   " has no 'message: d NAME ...' line: it changes nothing");
        }
        type.clear();
        item = {};
        haveMessage = false;
    };
    for (int number = 1; std::getline(in, line); ++number) {
        line = trimmed(line);
        const size_t colon = line.find(':');
        if (line.empty() || colon == std::string::npos) continue;
        const std::string key = line.substr(0, colon), value = trimmed(line.substr(colon + 1));
        std::istringstream words(value);
        auto bad = [&](const std::string& expected) {
            out.problems.push_back(fileName + ":" + std::to_string(number) + ": expected " + expected + " after '" + key +
                                   ":', not '" + value + "'");
        };
        if (key == "panel name") out.name = value;
        else if (key == "type") finish(), type = value, itemLine = number;
        else if (key == "name" && !type.empty()) item.label = value;
        else if (key == "min/max" && type == "SLIDER") {
            if (!(words >> item.min >> item.max)) bad("two numbers");
        } else if (key == "value" && !type.empty()) {
            if (!(words >> item.value)) bad("a number");
        } else if (key == "message" && !type.empty()) {
            // `d NAME %d DIVISOR` (a slider: its value) or `d NAME VALUE DIVISOR` (a button).
            std::string d, name, shown;
            double divisor = 1;
            if (!(words >> d >> name >> shown) || d != "d") {
                bad("'d NAME %d DIVISOR'");
                continue;
            }
            if (!(words >> divisor) || divisor == 0) divisor = 1;
            item.define = name;
            item.divisor = divisor;
            if (type == "BUTTON") {
                std::istringstream v(shown);
                if (!(v >> item.value)) {
                    bad("'d NAME VALUE DIVISOR'");
                    continue;
                }
            }
            haveMessage = true;
        }
    }
    finish();
    for (VlabPanelItem& i : out.items) {
        i.min /= i.divisor;
        i.max /= i.divisor;
        i.value /= i.divisor;
    }
    return out;
}

std::vector<VlabPanel> vlabPanelsOf(const std::string& folder, const std::string& lsystemFile) {
    std::vector<VlabPanel> out;
    std::istringstream in(readFile(fs::path(folder) / "specifications").value_or(""));
    std::string line;
    while (std::getline(in, line)) {
        // `panel panel.l | awkped plant.l`: the panel file, then the L-system it edits.
        std::istringstream words(line);
        std::string word, panelFile, target;
        if (!(words >> word) || word != "panel" || !(words >> panelFile)) continue;
        bool piped = false;
        while (words >> word) {
            if (word == "|") piped = true;
            else if (piped && word != "awkped") target = word;
        }
        if (target != lsystemFile) continue;
        const std::optional<std::string> text = readFile(fs::path(folder) / panelFile);
        if (!text) continue;
        VlabPanel p = readVlabPanel(*text, panelFile);
        if (!p.items.empty() || !p.problems.empty()) out.push_back(std::move(p));
    }
    return out;
}

}  // namespace sprout

#include "ui/script.hpp"

#include <fstream>
#include <map>
#include <sstream>

#include "core/error.hpp"

namespace fxview::ui {

std::vector<ScriptAction> load_script(const std::string& path) {
    std::ifstream file(path);
    if (!file) throw Error(path + ": cannot open script");
    // Verb -> allowed argument counts (min, max).
    static const std::map<std::string, std::pair<size_t, size_t>> verbs = {
        {"set", {2, 2}},  {"technique", {1, 1}},  {"view", {1, 1}},       {"mesh", {1, 1}},
        {"select", {1, 2}}, {"rotate", {4, 4}},   {"pick", {2, 2}},       {"screenshot", {1, 1}},
        {"render-screenshot", {1, 1}}, {"frames", {1, 1}}, {"skybox", {1, 1}}, {"fit", {1, 1}}, {"plugin", {1, 1}}, {"plugin-start", {1, 1}}, {"plugin-wait", {0, 0}}, {"wait-effect", {1, 1}}, {"open-error", {1, 1}}, {"inspect-texture", {1, 4}}, {"inspect-texel", {2, 2}}, {"save-screenshot", {1, 1}}, {"tab", {1, 1}}, {"brdf-check", {0, 0}}, {"brdf-measured", {1, 1}}, {"brdf-view", {1, 1}}, {"brdf-keep", {0, 0}}, {"environment", {1, 1}}, {"light-spectrum", {1, 1}}, {"light-shape", {2, 3}}, {"light-intensity", {1, 1}}, {"exposure", {1, 1}}, {"tone-map", {1, 1}},
        {"allow-path", {1, 1}}, {"window", {2, 2}}, {"ui-state", {0, 0}}, {"wait-key", {1, 2}}};
    std::vector<ScriptAction> actions;
    std::string line;
    int number = 0;
    while (std::getline(file, line)) {
        ++number;
        const size_t hash = line.find('#');
        std::istringstream words(line.substr(0, hash));
        ScriptAction action;
        action.line = number;
        if (!(words >> action.verb)) continue;
        for (std::string word; words >> word;) action.arguments.push_back(word);
        const auto found = verbs.find(action.verb);
        const std::string where = path + ":" + std::to_string(number) + ": ";
        if (found == verbs.end()) throw UsageError(where + "unknown script action '" + action.verb + "'");
        const auto [low, high] = found->second;
        if (action.arguments.size() < low || action.arguments.size() > high)
            throw UsageError(where + action.verb + " takes " + std::to_string(low) + (low == high ? "" : "-" + std::to_string(high)) +
                             " argument(s), got " + std::to_string(action.arguments.size()));
        actions.push_back(std::move(action));
    }
    return actions;
}

}  // namespace fxview::ui

#include "legacy/pass_script.hpp"

#include "core/text.hpp"

namespace fxview::legacy {
namespace {

std::string trim(std::string s) {
    s.erase(0, s.find_first_not_of(" \t\r\n"));
    s.erase(s.find_last_not_of(" \t\r\n") + 1);
    return s;
}

}  // namespace

void apply_pass_script(effect::Pass& pass, const std::vector<effect::Annotation>& annotations, const effect::Effect& effect,
                       std::vector<std::string>& warnings) {
    for (const auto& a : annotations) {
        if (to_lower(a.name) != "script" || !a.value.is_string) continue;
        const std::string& script = a.value.text;
        size_t start = 0;
        for (size_t i = 0; i <= script.size(); ++i) {
            if (i < script.size() && script[i] != ';') continue;
            const std::string command = trim(script.substr(start, i - start));
            start = i + 1;
            if (command.empty()) continue;
            const size_t equals = command.find('=');
            const std::string key = to_lower(trim(command.substr(0, equals)));
            const std::string value = equals == std::string::npos ? "" : trim(command.substr(equals + 1));
            if (key.rfind("rendercolortarget", 0) == 0) {
                const std::string index_text = key.substr(17);
                const size_t index = index_text.empty() ? 0 : static_cast<size_t>(index_text[0] - '0');
                if (index > 3) continue;
                if (value.empty()) {  // back to the frame
                    if (pass.states.render_targets.size() > index) pass.states.render_targets.resize(index);
                    continue;
                }
                if (pass.states.render_targets.size() <= index) pass.states.render_targets.resize(index + 1);
                pass.states.render_targets[index] = value;
            } else if (key == "draw") {
                pass.states.draw_buffer = to_lower(value) == "buffer";
            } else if (key == "clear") {
                pass.states.clear = true;
            } else if (key == "clearsetcolor" || key == "clearsetdepth") {
                const effect::Parameter* p = effect.find_parameter(value);
                if (!p || !p->default_value) continue;
                const auto& n = p->default_value->numbers;
                if (key == "clearsetdepth" && !n.empty()) pass.states.clear_depth = static_cast<float>(n[0]);
                if (key == "clearsetcolor" && n.size() >= 3)
                    pass.states.clear_color = std::array<float, 4>{static_cast<float>(n[0]), static_cast<float>(n[1]), static_cast<float>(n[2]),
                                                                   n.size() > 3 ? static_cast<float>(n[3]) : 1.0f};
            } else if (key == "renderdepthstenciltarget" || key == "pass") {
                // every target has its own depth buffer; passes run in the order they are declared
            } else {
                warnings.push_back(a.where.str() + ": pass " + pass.name + ": script command " + excerpt(command) + " is not supported and ignored");
            }
        }
    }
    // A target named by the script but never declared as one: back to the frame, with a warning.
    for (auto& target : pass.states.render_targets) {
        const effect::TextureResource* texture = effect.find_texture(target);
        if (!texture || !texture->render_target) {
            warnings.push_back(pass.where.str() + ": pass " + pass.name + " renders into '" + excerpt(target) + "', which is no render target; it draws into the frame");
            pass.states.render_targets.clear();
            break;
        }
    }
}

}  // namespace fxview::legacy

#include "legacy/pass_script.hpp"

#include <algorithm>
#include <map>

#include "core/text.hpp"

namespace fxview::legacy {
namespace {

struct Command {
    std::string key, value;  // key lower case
    std::string text;        // as written, for messages
};

std::vector<Command> script_commands(const std::vector<effect::Annotation>& annotations) {
    std::vector<Command> commands;
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
            commands.push_back({to_lower(trim(command.substr(0, equals))), equals == std::string::npos ? "" : trim(command.substr(equals + 1)), command});
        }
    }
    return commands;
}

// Sets a render target slot from RenderColorTargetN=NAME (empty NAME: back to the frame).
void set_target(std::vector<std::string>& targets, const std::string& key, const std::string& value) {
    const std::string index_text = key.substr(17);
    const size_t index = index_text.empty() ? 0 : static_cast<size_t>(index_text[0] - '0');
    if (index > 3) return;
    if (value.empty()) {
        if (targets.size() > index) targets.resize(index);
        return;
    }
    if (targets.size() <= index) targets.resize(index + 1);
    targets[index] = value;
}

void set_clear_value(effect::RenderStates& states, const std::string& key, const std::string& value, const effect::Effect& effect) {
    const effect::Parameter* p = effect.find_parameter(value);
    if (!p || !p->default_value) return;
    const auto& n = p->default_value->numbers;
    if (key == "clearsetdepth" && !n.empty()) states.clear_depth = static_cast<float>(n[0]);
    if (key == "clearsetcolor" && n.size() >= 3)
        states.clear_color = std::array<float, 4>{static_cast<float>(n[0]), static_cast<float>(n[1]), static_cast<float>(n[2]),
                                                  n.size() > 3 ? static_cast<float>(n[3]) : 1.0f};
}

// A target named by a script but never declared as one: back to the frame, with a warning.
void check_targets(effect::Pass& pass, const effect::Effect& effect, std::vector<std::string>& warnings) {
    for (auto& target : pass.states.render_targets) {
        const effect::TextureResource* texture = effect.find_texture(target);
        if (!texture || !texture->render_target) {
            warnings.push_back(pass.where.str() + ": warning: pass " + pass.name + " renders into '" + excerpt(target) + "', which is no render target; it draws into the frame");
            pass.states.render_targets.clear();
            return;
        }
    }
}

}  // namespace

void apply_technique_script(effect::Technique& technique, const std::vector<bool>& pass_sets_targets, const effect::Effect& effect,
                            std::vector<std::string>& warnings) {
    const std::vector<Command> commands = script_commands(technique.annotations);
    if (std::none_of(commands.begin(), commands.end(), [](const Command& c) { return c.key == "pass"; })) return;
    constexpr size_t kMaxPasses = 256;
    constexpr int kMaxLoopCount = 64;
    std::vector<effect::Pass> ordered;
    std::vector<std::string> targets;  // the technique script's current targets
    effect::RenderStates clears;       // its pending Clear / ClearSet* for the next pass
    bool pending_clear = false;
    size_t pending_clear_depth = 0;  // the loops open when the Clear command came
    // A loop by a parameter is unrolled to the most it allows and its copies carry their iteration.
    struct Loop { size_t command; int left; int count; std::string parameter; };
    std::vector<Loop> loops;
    std::map<std::string, int> uses;
    size_t steps = 0;
    bool stopped_early = false;
    for (size_t i = 0; i < commands.size(); ++i) {
        if (++steps > 100000) {  // loops of loops: bounded work
            stopped_early = true;
            break;
        }
        const Command& c = commands[i];
        if (c.key.rfind("rendercolortarget", 0) == 0) {
            set_target(targets, c.key, c.value);
        } else if (c.key == "clearsetcolor" || c.key == "clearsetdepth") {
            set_clear_value(clears, c.key, c.value, effect);
        } else if (c.key == "clear") {
            pending_clear = true;
            pending_clear_depth = loops.size();
        } else if (c.key == "pass" || c.key == "scriptexternal") {
            if (ordered.size() >= kMaxPasses) {
                warnings.push_back(technique.where.str() + ": warning: technique " + technique.name + ": its script runs more than 256 passes; the rest are dropped");
                stopped_early = true;
                break;
            }
            effect::Pass pass;
            if (c.key == "scriptexternal") {
                pass.name = "ScriptExternal";
                pass.where = technique.where;
                pass.states.draw_scene = true;
                pass.states.render_targets = targets;
            } else {
                size_t found = technique.passes.size();
                for (size_t k = 0; k < technique.passes.size(); ++k)
                    if (technique.passes[k].name == c.value) found = k;
                if (found == technique.passes.size()) {
                    warnings.push_back(technique.where.str() + ": warning: technique " + technique.name + ": its script names no pass '" + excerpt(c.value) + "'");
                    continue;
                }
                pass = technique.passes[found];
                if (!pass_sets_targets[found]) pass.states.render_targets = targets;
            }
            if (const int n = ++uses[pass.name]; n > 1) pass.name += "#" + std::to_string(n);
            if (pending_clear) {
                pass.carries_clear = loops.size() > pending_clear_depth;
                pass.states.clear = true;
                if (!pass.states.clear_color) pass.states.clear_color = clears.clear_color;
                if (!pass.states.clear_depth) pass.states.clear_depth = clears.clear_depth;
                pending_clear = false;
            }
            for (const Loop& loop : loops)
                if (!loop.parameter.empty()) pass.runs_if.push_back({loop.parameter, loop.count - loop.left + 1});
            check_targets(pass, effect, warnings);
            ordered.push_back(std::move(pass));
        } else if (c.key == "loopbycount") {
            int count = 0;
            std::string parameter;
            const std::string where = technique.where.str() + ": warning: technique " + technique.name + ": LoopByCount=" + excerpt(c.value);
            if (const effect::Parameter* p = effect.find_parameter(c.value)) {
                // The user may change it: unrolled to its UIMax, else to at least 16 (and its default).
                const double largest = p->ui.max ? *p->ui.max
                                                 : std::max(16.0, p->default_value && !p->default_value->numbers.empty() ? p->default_value->numbers[0] : 0.0);
                count = static_cast<int>(std::clamp(largest, 0.0, static_cast<double>(kMaxLoopCount)));
                parameter = p->name;
                if (largest > kMaxLoopCount)
                    warnings.push_back(where + " runs at most " + std::to_string(kMaxLoopCount) + " times, whatever " + p->name + " says");
                else if (!p->ui.max)
                    warnings.push_back(where + ": " + p->name + " has no UIMax; the loop runs at most " + std::to_string(count) + " times");
            } else {
                try {
                    count = std::stoi(c.value);
                } catch (const std::exception&) {
                    warnings.push_back(where + " names no parameter and no number; it runs once");
                    count = 1;
                }
            }
            loops.push_back({i, std::clamp(count, 0, kMaxLoopCount), std::clamp(count, 0, kMaxLoopCount), parameter});
            if (loops.back().left == 0) {  // skip the body
                int depth = 1;
                while (depth > 0 && ++i < commands.size()) depth += commands[i].key == "loopbycount" ? 1 : commands[i].key == "loopend" ? -1 : 0;
                loops.pop_back();
            }
        } else if (c.key == "loopend") {
            if (loops.empty()) {
                warnings.push_back(technique.where.str() + ": warning: technique " + technique.name + ": LoopEnd without LoopByCount; ignored");
                continue;
            }
            if (--loops.back().left > 0) i = loops.back().command;
            else loops.pop_back();
        } else if (c.key == "renderdepthstenciltarget" || c.key == "loopgetindex") {
            // own depth per target; the loop index is not exposed to programs
        } else {
            warnings.push_back(technique.where.str() + ": warning: technique " + technique.name + ": script command " + excerpt(c.text) + " is not supported and ignored");
        }
    }
    if (!loops.empty() && !stopped_early)
        warnings.push_back(technique.where.str() + ": warning: technique " + technique.name + ": LoopByCount without LoopEnd; its passes run to the end");
    // Pass= commands decide which passes run, even when a loop of 0 leaves none.
    technique.passes = std::move(ordered);
}

bool apply_pass_script(effect::Pass& pass, const std::vector<effect::Annotation>& annotations, const effect::Effect& effect,
                       std::vector<std::string>& warnings) {
    bool sets_targets = false;
    for (const Command& c : script_commands(annotations)) {
        if (c.key.rfind("rendercolortarget", 0) == 0) {
            set_target(pass.states.render_targets, c.key, c.value);
            sets_targets = true;
        } else if (c.key == "draw") {
            pass.states.draw_buffer = to_lower(c.value) == "buffer";
        } else if (c.key == "clear") {
            pass.states.clear = true;
        } else if (c.key == "clearsetcolor" || c.key == "clearsetdepth") {
            set_clear_value(pass.states, c.key, c.value, effect);
        } else if (c.key == "renderdepthstenciltarget" || c.key == "pass") {
            // every target has its own depth buffer; passes run in the order they are declared
        } else {
            warnings.push_back(pass.where.str() + ": warning: pass " + pass.name + ": script command " + excerpt(c.text) + " is not supported and ignored");
        }
    }
    check_targets(pass, effect, warnings);
    return sets_targets;
}

}  // namespace fxview::legacy

#include "ui/parameter_panel.hpp"

#include <imgui.h>

#include <algorithm>
#include <string>
#include <vector>

#include "core/text.hpp"
#include "effect/parser.hpp"

namespace fxview::ui {
namespace {

bool is_colour(const effect::Parameter& p) {
    const std::string widget = to_lower(p.ui.widget);
    if (widget.find("color") != std::string::npos || widget.find("colour") != std::string::npos) return true;
    const std::string name = to_lower(p.name);
    return widget.empty() && (p.type == "vec3" || p.type == "vec4") &&
           (name.find("color") != std::string::npos || name.find("colour") != std::string::npos);
}

bool draw_value(const effect::Parameter& p, std::vector<double>& value) {
    const std::string label = (p.ui.label.empty() ? p.name : p.ui.label) + (p.ui.unit.empty() ? "" : " [" + p.ui.unit + "]") +
                              "##" + p.name;
    std::vector<float> f(value.begin(), value.end());
    std::vector<int> i(value.begin(), value.end());
    bool changed = false;
    const bool integer = p.type == "int" || p.type.rfind("ivec", 0) == 0 || p.type == "uint";
    const int n = effect::component_count(p.type);
    const float speed = p.ui.step ? static_cast<float>(*p.ui.step) : 0.01f;
    if (p.type == "bool") {
        bool b = value[0] != 0.0;
        changed = ImGui::Checkbox(label.c_str(), &b);
        value[0] = b ? 1.0 : 0.0;
        return changed;
    }
    if (integer && n == 1 && !p.ui.items.empty()) {
        int current = std::clamp(i[0], 0, static_cast<int>(p.ui.items.size()) - 1);
        if (ImGui::BeginCombo(label.c_str(), p.ui.items[static_cast<size_t>(current)].c_str())) {
            for (int k = 0; k < static_cast<int>(p.ui.items.size()); ++k)
                if (ImGui::Selectable(p.ui.items[static_cast<size_t>(k)].c_str(), k == current)) {
                    value[0] = k;
                    changed = true;
                }
            ImGui::EndCombo();
        }
        return changed;
    }
    if (integer) {
        if (n == 1 && p.ui.min && p.ui.max && to_lower(p.ui.widget) != "drag")
            changed = ImGui::SliderInt(label.c_str(), i.data(), static_cast<int>(*p.ui.min), static_cast<int>(*p.ui.max));
        else
            changed = ImGui::DragScalarN(label.c_str(), ImGuiDataType_S32, i.data(), n, std::max(speed, 0.1f));
        if (changed) std::copy(i.begin(), i.end(), value.begin());
        return changed;
    }
    if (n > 4) {  // matrices: shown, not edited
        ImGui::TextDisabled("%s: %s", p.name.c_str(), p.type.c_str());
        return false;
    }
    if (is_colour(p) && n == 3) changed = ImGui::ColorEdit3(label.c_str(), f.data(), ImGuiColorEditFlags_Float);
    else if (is_colour(p) && n == 4) changed = ImGui::ColorEdit4(label.c_str(), f.data(), ImGuiColorEditFlags_Float);
    else if (n == 1 && p.ui.min && p.ui.max && to_lower(p.ui.widget) != "drag")
        changed = ImGui::SliderFloat(label.c_str(), f.data(), static_cast<float>(*p.ui.min), static_cast<float>(*p.ui.max), "%.4g");
    else {
        const float low = p.ui.min ? static_cast<float>(*p.ui.min) : 0.0f, high = p.ui.max ? static_cast<float>(*p.ui.max) : 0.0f;
        changed = ImGui::DragScalarN(label.c_str(), ImGuiDataType_Float, f.data(), n, speed, p.ui.min ? &low : nullptr,
                                     p.ui.max ? &high : nullptr, "%.4g");
    }
    if (changed) std::copy(f.begin(), f.end(), value.begin());
    return changed;
}

}  // namespace

bool draw_parameter_panel(render::EffectSession& session) {
    const effect::Effect& effect = session.effect();
    effect::ParameterValues& values = session.values();
    // Defaults are computed only when a reset asks for them, not every frame.
    const auto default_of = [&effect](const std::string& name) { return effect::default_values(effect).numbers.at(name); };
    std::vector<const effect::Parameter*> shown;
    for (const auto& p : effect.parameters)
        if (p.semantic.empty() && !effect::is_sampler_type(p.type)) shown.push_back(&p);
    std::stable_sort(shown.begin(), shown.end(), [](const auto* a, const auto* b) {
        return a->ui.group != b->ui.group ? a->ui.group < b->ui.group : a->ui.order < b->ui.order;
    });
    bool changed = false;
    if (ImGui::Button("Reset all")) {
        values.numbers = effect::default_values(effect).numbers;
        changed = true;
    }
    std::string group = "\x01";
    bool open = true;
    for (const effect::Parameter* p : shown) {
        if (p->ui.group != group) {
            group = p->ui.group;
            open = ImGui::CollapsingHeader(group.empty() ? "Parameters" : group.c_str(), ImGuiTreeNodeFlags_DefaultOpen);
        }
        if (!open) continue;
        auto& value = values.numbers[p->name];
        ImGui::PushID(p->name.c_str());
        if (ImGui::SmallButton("R")) {
            value = default_of(p->name);
            changed = true;
        }
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Reset %s to its default", p->name.c_str());
        ImGui::SameLine();
        const int count = std::max(1, p->array_size), components = effect::component_count(p->type);
        for (int element = 0; element < count; ++element) {
            std::vector<double> part(value.begin() + element * components, value.begin() + (element + 1) * components);
            ImGui::PushID(element);
            if (draw_value(*p, part)) {
                std::copy(part.begin(), part.end(), value.begin() + element * components);
                effect::enforce_constraints(effect, values, p->name);  // e.g. Upper never below Lower
                changed = true;
            }
            ImGui::PopID();
        }
        if (!p->ui.help.empty() && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", p->ui.help.c_str());
        ImGui::PopID();
    }
    bool any_sampler = false;
    for (const auto& p : effect.parameters)
        if (effect::is_sampler_type(p.type)) {
            if (!any_sampler) {
                ImGui::Separator();
                ImGui::TextUnformatted("Textures");
            }
            any_sampler = true;
            ImGui::BulletText("%s: %s", p.name.c_str(), p.texture.c_str());
        }
    return changed;
}

}  // namespace fxview::ui

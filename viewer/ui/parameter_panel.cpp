#include "ui/parameter_panel.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "core/text.hpp"
#include "image/color_encoding.hpp"
#include "effect/parameter_values.hpp"
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

// One convention for colours in the UI and on the command line (docs/viewer.md): the numbers are
// linear (as `--set X=r,g,b`), the swatch, its picker and hex code are sRGB-encoded (as
// `--set X=#rrggbb`). A colour above 1 (where UIMax allows it) is shown as a colour times an
// intensity: the swatch holds the colour scaled to a peak of 1.
bool draw_colour(const effect::Parameter& p, const std::string& label, std::vector<float>& f) {
    // Measured before the swatch: a width relative to the line's end (-FLT_MIN) shrinks after it.
    const float numbers_width = std::max(ImGui::CalcItemWidth() - ImGui::GetFrameHeight() - ImGui::GetStyle().ItemInnerSpacing.x, 40.0f);
    const float peak = std::max({1.0f, f[0], f[1], f[2]});
    float encoded[4] = {image::srgb_encode(f[0] / peak), image::srgb_encode(f[1] / peak), image::srgb_encode(f[2] / peak), f.size() > 3 ? f[3] : 1.0f};
    const ImGuiColorEditFlags flags = ImGuiColorEditFlags_NoInputs | ImGuiColorEditFlags_NoLabel | ImGuiColorEditFlags_Uint8;
    bool changed = f.size() > 3 ? ImGui::ColorEdit4("##swatch", encoded, flags | ImGuiColorEditFlags_AlphaPreviewHalf) : ImGui::ColorEdit3("##swatch", encoded, flags);
    if (changed) {
        for (int c = 0; c < 3; ++c) f[static_cast<size_t>(c)] = image::srgb_decode(encoded[c]) * peak;
        if (f.size() > 3) f[3] = encoded[3];
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("sRGB #%02X%02X%02X x %.3g (as --set %s=#hex); the numbers are linear", static_cast<int>(std::lround(encoded[0] * 255)),
                          static_cast<int>(std::lround(encoded[1] * 255)), static_cast<int>(std::lround(encoded[2] * 255)), peak, p.name.c_str());
    ImGui::SameLine(0, ImGui::GetStyle().ItemInnerSpacing.x);
    const float high = p.ui.max ? static_cast<float>(*p.ui.max) : 1.0f;
    const float low = p.ui.min ? static_cast<float>(*p.ui.min) : 0.0f;
    const float speed = p.ui.step ? static_cast<float>(*p.ui.step) : 0.005f;
    ImGui::SetNextItemWidth(numbers_width);
    changed = ImGui::DragScalarN(label.c_str(), ImGuiDataType_Float, f.data(), static_cast<int>(f.size()), speed, &low, &high, "%.4g",
                                 ImGuiSliderFlags_AlwaysClamp) || changed;
    return changed;
}

std::string label_of(const effect::Parameter& p) {
    return (p.ui.label.empty() ? p.name : p.ui.label) + (p.ui.unit.empty() ? "" : " [" + p.ui.unit + "]");
}

// The width a row's widget needs to show its numbers whole (about "-0.0000" in every field, and the
// swatch of a colour); 0 for widgets that need no particular width.
float width_for_numbers(const effect::Parameter& p, int components) {
    if (p.type == "bool" || components < 2 || components > 4) return 0;
    const ImGuiStyle& style = ImGui::GetStyle();
    const float field = ImGui::CalcTextSize("-0.0000").x + 2 * style.FramePadding.x;
    float width = components * field + (components - 1) * style.ItemInnerSpacing.x;
    if (is_colour(p)) width += ImGui::GetFrameHeight() + style.ItemInnerSpacing.x;
    return width;
}

bool draw_widget(const effect::Parameter& p, const std::string& label, std::vector<double>& value) {
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
        // A file's range may exceed an int (1e30): clamped before the cast.
        const int low = p.ui.min ? static_cast<int>(std::ceil(std::clamp(*p.ui.min, -2147483648.0, 2147483647.0))) : 0;
        const int high = p.ui.max ? static_cast<int>(std::floor(std::clamp(*p.ui.max, -2147483648.0, 2147483647.0))) : 0;
        if (n == 1 && p.ui.min && p.ui.max && to_lower(p.ui.widget) != "drag")
            changed = ImGui::SliderInt(label.c_str(), i.data(), low, high, "%d", ImGuiSliderFlags_AlwaysClamp);
        else
            changed = ImGui::DragScalarN(label.c_str(), ImGuiDataType_S32, i.data(), n, std::max(speed, 0.1f), p.ui.min ? &low : nullptr,
                                         p.ui.max ? &high : nullptr, "%d", ImGuiSliderFlags_AlwaysClamp);
        if (changed) std::copy(i.begin(), i.end(), value.begin());
        return changed;
    }
    if (n > 4) {  // matrices: shown, not edited
        ImGui::TextDisabled("%s: %s", p.name.c_str(), p.type.c_str());
        return false;
    }
    if (is_colour(p) && (n == 3 || n == 4)) {
        changed = draw_colour(p, label, f);
    } else if (n == 1 && p.ui.min && p.ui.max && to_lower(p.ui.widget) != "drag")
        changed = ImGui::SliderFloat(label.c_str(), f.data(), static_cast<float>(*p.ui.min), static_cast<float>(*p.ui.max), "%.4g",
                                     ImGuiSliderFlags_AlwaysClamp);
    else {
        const float low = p.ui.min ? static_cast<float>(*p.ui.min) : 0.0f, high = p.ui.max ? static_cast<float>(*p.ui.max) : 0.0f;
        changed = ImGui::DragScalarN(label.c_str(), ImGuiDataType_Float, f.data(), n, speed, p.ui.min ? &low : nullptr,
                                     p.ui.max ? &high : nullptr, "%.4g", ImGuiSliderFlags_AlwaysClamp);
    }
    if (changed) std::copy(f.begin(), f.end(), value.begin());
    return changed;
}

// The label right of the widget; on a line of its own above a widget of the whole width when the
// widget would cut its numbers (a narrow panel, a large UI scale).
bool draw_value(const effect::Parameter& p, std::vector<double>& value) {
    const std::string label = label_of(p);
    if (ImGui::CalcItemWidth() >= width_for_numbers(p, effect::component_count(p.type))) return draw_widget(p, label + "##" + p.name, value);
    ImGui::TextUnformatted(label.c_str());
    ImGui::PushItemWidth(-FLT_MIN);
    const bool changed = draw_widget(p, "##" + p.name, value);
    ImGui::PopItemWidth();
    return changed;
}

// Parameters a plugin of the effect reads (named in its annotations): they matter even when no shader
// reads them (a film-fit plugin's target colour). What a plugin writes (brdf-fit's Targets, film-fit's
// Vary) matters only to the techniques that read it.
std::set<std::string> named_by_plugins(const effect::Effect& effect) {
    std::set<std::string> named;
    for (const auto& plugin : effect.plugins)
        for (const auto& annotation : plugin.annotations) {
            if (!annotation.value.is_string || annotation.name == "Targets" || annotation.name == "Vary") continue;
            std::stringstream in(annotation.value.text);
            for (std::string part; std::getline(in, part, ',');) {
                const size_t first = part.find_first_not_of(" \t"), last = part.find_last_not_of(" \t");
                if (first != std::string::npos && effect.find_parameter(part.substr(first, last - first + 1)))
                    named.insert(part.substr(first, last - first + 1));
            }
        }
    return named;
}

// Draws one parameter row (reset button and widget); true when its value changed.
bool draw_row(const effect::Effect& effect, effect::ParameterValues& values, const effect::Parameter& p) {
    bool changed = false;
    auto& value = values.numbers[p.name];
    ImGui::PushID(p.name.c_str());
    if (ImGui::SmallButton("R")) {
        value = effect::default_values(effect).numbers.at(p.name);  // computed only when asked for
        changed = true;
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Reset %s to its default", p.name.c_str());
    ImGui::SameLine();
    const int count = std::max(1, p.array_size), components = effect::component_count(p.type);
    for (int element = 0; element < count; ++element) {
        std::vector<double> part(value.begin() + element * components, value.begin() + (element + 1) * components);
        ImGui::PushID(element);
        if (draw_value(p, part)) {
            std::vector<double> edited = value;
            std::copy(part.begin(), part.end(), edited.begin() + element * components);
            // The one rule of every source (effect::value_problem): a typed value out of range or not
            // whole is not taken; the sliders clamp, so this catches typed-in text.
            if (!effect::value_problem(p, edited).empty()) {
                ImGui::PopID();
                continue;
            }
            value = std::move(edited);
            effect::enforce_constraints(effect, values, p.name);  // e.g. Upper never below Lower
            changed = true;
        }
        ImGui::PopID();
    }
    if (ImGui::IsItemHovered()) {
        // The whole label and the help: a narrow panel may have clipped the label.
        if (p.ui.help.empty()) ImGui::SetTooltip("%s (%s)", label_of(p).c_str(), p.name.c_str());
        else ImGui::SetTooltip("%s (%s)\n%s", label_of(p).c_str(), p.name.c_str(), p.ui.help.c_str());
    }
    ImGui::PopID();
    return changed;
}

// Rows grouped by UIGroup (collapsible headers), in UIOrder; `id` keeps the headers of two lists apart.
bool draw_groups(const effect::Effect& effect, effect::ParameterValues& values, const std::vector<const effect::Parameter*>& rows,
                 const char* id) {
    bool changed = false;
    std::string group = "\x01";
    bool open = true;
    // Widgets leave room for the longest label (up to 60 % of the panel), so labels are not cut.
    float label_width = 0;
    for (const effect::Parameter* p : rows)  // (a checkbox's label follows its box: no room to keep)
        if (p->type != "bool") label_width = std::max(label_width, ImGui::CalcTextSize(label_of(*p).c_str()).x);
    const float available = ImGui::GetContentRegionAvail().x;
    // (At least 30 % for the widget: a panel too narrow for a label clips it; its tooltip has it whole.)
    const float item_width = std::max(available * 0.3f, available - label_width - ImGui::GetFrameHeight() - 3 * ImGui::GetStyle().ItemSpacing.x);
    ImGui::PushItemWidth(item_width);
    for (const effect::Parameter* p : rows) {
        if (p->ui.group != group) {
            group = p->ui.group;
            const std::string header = (group.empty() ? std::string("Parameters") : group) + "##" + id;
            open = ImGui::CollapsingHeader(header.c_str(), ImGuiTreeNodeFlags_DefaultOpen);
        }
        if (open) changed = draw_row(effect, values, *p) || changed;
    }
    ImGui::PopItemWidth();
    return changed;
}

}  // namespace

bool draw_parameter_panel(render::EffectSession& session, const std::vector<std::string>& techniques) {
    const effect::Effect& effect = session.effect();
    effect::ParameterValues& values = session.values();
    std::set<std::string> read = named_by_plugins(effect);
    for (const std::string& technique : techniques) {
        const auto& reads = session.parameters_read(technique);
        read.insert(reads.begin(), reads.end());
    }
    std::vector<const effect::Parameter*> used, unused;
    for (const auto& p : effect.parameters)
        if (p.semantic.empty() && !effect::is_sampler_type(p.type)) (read.count(p.name) ? used : unused).push_back(&p);
    const auto by_group = [](const auto* a, const auto* b) { return a->ui.group != b->ui.group ? a->ui.group < b->ui.group : a->ui.order < b->ui.order; };
    std::stable_sort(used.begin(), used.end(), by_group);
    std::stable_sort(unused.begin(), unused.end(), by_group);
    bool changed = false;
    if (ImGui::Button("Reset all")) {
        values.numbers = effect::default_values(effect).numbers;
        changed = true;
    }
    changed = draw_groups(effect, values, used, "used") || changed;
    if (!unused.empty()) {
        ImGui::Spacing();
        std::string names;
        for (size_t i = 0; i < techniques.size(); ++i) {
            const effect::Technique* t = effect.find_technique(techniques[i]);
            names += (i ? ", " : "") + (t ? t->label() : techniques[i]);
        }
        const std::string header = "Not read by " + names + " (" + std::to_string(unused.size()) + ")##unused";
        if (ImGui::CollapsingHeader(header.c_str())) {
            ImGui::Indent();
            changed = draw_groups(effect, values, unused, "unused") || changed;
            ImGui::Unindent();
        }
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

// The viewer window's keys and panels: the tabs (Effect, Scene, Textures, Pick, View, Plugins,
// BRDF), the file-access prompt and the help overlay.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "core/error.hpp"
#include "effect/preset.hpp"
#include "ui/error_list.hpp"
#include "ui/parameter_panel.hpp"
#include "ui/viewer_window.hpp"

namespace fxview::ui {
namespace fs = std::filesystem;

void Viewer::draw_file_access() {
    if (!ImGui::CollapsingHeader("File access")) return;
    ImGui::TextWrapped("Effects read includes, textures and data only from their own folder and these folders:");
    for (const auto& folder : effect_.allowed_folders()) ImGui::BulletText("%s", folder.c_str());
    ImGui::InputText("##allow", allow_input_, sizeof allow_input_);
    ImGui::SameLine();
    if (ImGui::Button("Allow folder")) {
        try {
            const bool had_effect = session() != nullptr;
            effect_.allow_folder(allow_input_);
            if (!had_effect && session()) on_effect_opened();
        } catch (const std::exception& error) {
            status_ = error.what();
        }
    }
}

void Viewer::handle_keys() {
    const std::vector<int> presses = imgui_->take_key_presses();  // taps shorter than a frame too
    if (ImGui::GetIO().WantCaptureKeyboard) return;
    if (awaited_key_ != 0 && std::find(presses.begin(), presses.end(), awaited_key_) != presses.end()) awaited_key_ = 0;  // wait-key
    const bool shift = ImGui::GetIO().KeyShift;
    const auto pressed = [&presses](int key) { return std::find(presses.begin(), presses.end(), key) != presses.end(); };
    if (pressed(GLFW_KEY_SPACE)) paused_ = !paused_;
    if (pressed(GLFW_KEY_C)) view_.selected = Target::Camera;
    if (pressed(GLFW_KEY_L)) view_.selected = Target::Light;
    if (pressed(GLFW_KEY_O) && !view_.objects.empty()) view_.selected = Target::Object;
    if (pressed(GLFW_KEY_TAB) && !view_.objects.empty()) {
        view_.selected = Target::Object;
        view_.selected_object = (view_.selected_object + 1) % static_cast<int>(view_.objects.size());
    }
    if (pressed(GLFW_KEY_R)) {
        if (shift) {
            view_.reset_all();
        } else {
            view_.reset_selected();
        }
    }
    if (pressed(GLFW_KEY_V)) {
        vsync_ = !vsync_;
        glfwSwapInterval(vsync_ ? 1 : 0);
    }
    if (pressed(GLFW_KEY_G)) srgb_display_ = !srgb_display_;
    if (pressed(GLFW_KEY_H) || pressed(GLFW_KEY_F1)) show_help_ = !show_help_;
    if (pressed(GLFW_KEY_F11)) toggle_fullscreen();
    if (pressed(GLFW_KEY_F12)) save_screenshot();
}

void Viewer::toggle_fullscreen() {
    GLFWmonitor* monitor = glfwGetWindowMonitor(window_);
    if (monitor) {
        glfwSetWindowMonitor(window_, nullptr, windowed_pos_.x, windowed_pos_.y, windowed_size_.x, windowed_size_.y, 0);
        return;
    }
    GLFWmonitor* primary = glfwGetPrimaryMonitor();
    if (!primary) return;
    glfwGetWindowPos(window_, &windowed_pos_.x, &windowed_pos_.y);
    glfwGetWindowSize(window_, &windowed_size_.x, &windowed_size_.y);
    const GLFWvidmode* mode = glfwGetVideoMode(primary);
    glfwSetWindowMonitor(window_, primary, 0, 0, mode->width, mode->height, mode->refreshRate);
}

// A tab asked for by a script (`tab NAME`) is selected once, then the user's clicks rule again.
ImGuiTabItemFlags Viewer::tab_flags(const char* name) {
    if (requested_tab_ != name) return 0;
    requested_tab_.clear();
    return ImGuiTabItemFlags_SetSelected;
}

void Viewer::draw_ui(int window_width, int window_height) {
    // The panel is as wide as the user drags its right edge (first as wide as its widgets and tabs
    // need), a share of a window too small for that (panel_width.hpp), the full height.
    const float height = static_cast<float>(window_height), scale = imgui_->scale();
    const ImGuiStyle& style = ImGui::GetStyle();
    tab_bar_width_ = -style.ItemInnerSpacing.x;
    for (const char* name : kTabNames)  // as ImGui sizes a tab without a close button (TabItemCalcSize)
        tab_bar_width_ += ImGui::CalcTextSize(name).x + 2 * style.FramePadding.x + 1.0f + style.ItemInnerSpacing.x;
    if (!panel_width_.has_preferred()) {
        const float widgets = std::min(460.0f * scale, window_width * 0.45f);
        const float tabs = std::min(std::ceil(tab_bar_width_ + 2 * (style.WindowPadding.x + style.WindowBorderSize) + style.ScrollbarSize),
                                    window_width * PanelWidth::kMaxShare);
        panel_width_.prefer(std::max(widgets, tabs));
    }
    ImGui::SetNextWindowPos(ImVec2(0, 0));
    if (const auto width = panel_width_.impose(static_cast<float>(window_width))) ImGui::SetNextWindowSize(ImVec2(*width, height));
    ImGui::SetNextWindowSizeConstraints(ImVec2(std::min(240.0f * scale, window_width * 0.5f), height),
                                        ImVec2(std::max(240.0f * scale, window_width * 0.8f), height));
    // The scroll bar always shown: a status line that makes the panel overflow must not narrow every
    // widget under the pointer by the bar's width.
    ImGui::Begin("fxview", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_AlwaysVerticalScrollbar);
    const float panel_width = ImGui::GetWindowWidth();
    panel_width_.shown(panel_width);
    panel_shown_width_ = panel_width;
    // Widgets leave room for the longest label of the fixed panels (Scene, View, Textures), so that
    // labels are not cut; the parameter list sizes its own (parameter_panel.cpp).
    float label_width = 0;
    for (const char* label : {"camera distance", "sun temperature", "light position", "file (.png/.exr)", "screenshot size", "exposure (EV)"})
        label_width = std::max(label_width, ImGui::CalcTextSize(label).x);
    const float content_width = ImGui::GetContentRegionAvail().x;
    ImGui::PushItemWidth(std::max(content_width * 0.45f, content_width - label_width - style.ItemInnerSpacing.x - style.ScrollbarSize));
    ImGui::Text("%.1f FPS  frame %.1f ms  picture %.1f ms%s", frame_seconds_ > 0 ? 1.0 / frame_seconds_ : 0.0, frame_seconds_ * 1e3,
                schedule_.last_picture_seconds() * 1e3, paused_ ? "  (paused)" : "");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("frame: the UI's frame time; picture: what the last complete picture took to render (the view is "
                          "drawn only when something changed, slow pictures in strips across frames)");
    {
        // Always drawn, so that the widgets below keep their place when a picture starts refining.
        char text[96];
        const bool coarse = schedule_.pending() && preview_key_ == render_key(target_ ? target_->width() : 0, target_ ? target_->height() : 0);
        if (!schedule_.pending()) std::snprintf(text, sizeof text, "picture complete");
        else if (coarse) std::snprintf(text, sizeof text, "preview at 1/%d resolution, refining %.0f %%", preview_scale_, schedule_.progress() * 100);
        else std::snprintf(text, sizeof text, "refining %.0f %%", schedule_.progress() * 100);
        ImGui::ProgressBar(schedule_.pending() ? static_cast<float>(schedule_.progress()) : 1.0f, ImVec2(-1, 0), text);
    }
    if (imgui_->font_fallback())
        ImGui::TextDisabled("UI font %s missing (fonts-dejavu-core): Greek letters show as '?'", FXVIEW_UI_FONT);
    tabs_fit_ = ImGui::GetContentRegionAvail().x >= tab_bar_width_;
    // Tabs keep their whole names; a panel too narrow for all of them scrolls the tab bar.
    if (ImGui::BeginTabBar("tabs", ImGuiTabBarFlags_FittingPolicyScroll)) {
        if (ImGui::BeginTabItem("Effect", nullptr, tab_flags("Effect"))) {
            draw_effect_tab();
            ImGui::EndTabItem();
        }
        if (ImGui::BeginTabItem("Scene", nullptr, tab_flags("Scene"))) {
            std::string light_warnings;  // what the technique cannot show of the light, one per line
            if (session())
                for (const std::string& w : {session()->unused_light_radius_warning(view_.scene.light), session()->unused_light_intensity_warning(view_.scene.light)})
                    if (!w.empty()) light_warnings += (light_warnings.empty() ? "" : "\n") + w;
            draw_scene_panel(view_, session() ? session()->technique() : "", session() != nullptr, light_warnings, status_);
            draw_light_spectrum(view_.scene.light, session());
            environment_panel_.draw(view_.scene.environment, session());
            ImGui::EndTabItem();
        }
        if (ImGui::BeginTabItem("Textures", nullptr, tab_flags("Textures"))) {
            if (session()) texture_panel_->draw(*session(), skybox_name_, status_);
            else ImGui::TextUnformatted("No effect loaded.");
            ImGui::EndTabItem();
        }
        if (ImGui::BeginTabItem("Pick", nullptr, tab_flags("Pick"))) {
            pick_.draw(target_ ? render_key(target_->width(), target_->height()) : 0);
            ImGui::EndTabItem();
        }
        if (ImGui::BeginTabItem("View", nullptr, tab_flags("View"))) {
            draw_view_tab();
            ImGui::EndTabItem();
        }
        if (ImGui::BeginTabItem("Plugins", nullptr, tab_flags("Plugins"))) {
            plugin_panel_.draw(session());
            ImGui::EndTabItem();
        }
        if (ImGui::BeginTabItem("BRDF", nullptr, tab_flags("BRDF"))) {
            brdf_panel_.draw(session());
            ImGui::EndTabItem();
        }
        ImGui::EndTabBar();
    }
    if (!status_.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
        ImGui::TextWrapped("%s", status_.c_str());
        ImGui::PopStyleColor();
    }
    ImGui::PopItemWidth();
    ImGui::End();

    ImGui::SetNextWindowPos(ImVec2(panel_width, 0));
    ImGui::SetNextWindowSize(ImVec2(window_width - panel_width, static_cast<float>(window_height)));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
    ImGui::Begin("Render", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                                        ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoTitleBar);
    const ImVec2 available = ImGui::GetContentRegionAvail();
    view_size_ = glm::ivec2(static_cast<int>(available.x), static_cast<int>(available.y));
    // A fixed render size is shown scaled to fit, keeping its aspect.
    ImVec2 shown = available;
    if (target_) {
        const float scale = std::min(available.x / target_->width(), available.y / target_->height());
        shown = ImVec2(target_->width() * scale, target_->height() * scale);
    }
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    if (display_->texture())
        ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(display_->texture())), shown, ImVec2(0, 1), ImVec2(1, 0));
    else
        ImGui::Dummy(shown);
    if (const auto click = mouse_.handle(view_, origin, shown); click && target_)
        pick_at(static_cast<int>(click->x * target_->width()), static_cast<int>(click->y * target_->height()));
    draw_light_gizmo(view_, ImGui::GetWindowDrawList(), origin, shown);
    if (target_) {
        pick_.draw_marker(ImGui::GetWindowDrawList(), origin, shown, target_->width(), target_->height());
        if (ImGui::IsItemHovered() && !mouse_.dragging() && !ImGui::IsMouseDown(ImGuiMouseButton_Right))
            PickPanel::draw_hover_readout(*target_, origin, shown);
    }
    if (!effect_.error().empty()) {  // compile errors overlay; the last good effect keeps rendering
        ImGui::SetCursorScreenPos(ImVec2(origin.x + 8, origin.y + 8));
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
        ImGui::TextWrapped("%s", effect_.error().c_str());
        ImGui::PopStyleColor();
    }
    ImGui::End();
    ImGui::PopStyleVar();
    if (show_help_) draw_help();
}

// What the loader accepted but could not honour (unknown render states, skipped techniques,
// placeholder textures, a .brdf's skipped sections and renamed names): listed as places that open
// in the editor, as the errors are; the command line prints the same lines.
void Viewer::draw_effect_warnings() {
    std::string text;
    for (const std::string& warning : session()->warnings()) text += warning + "\n";
    if (text.empty()) return;
    const std::vector<ErrorLocation> places = error_locations(text);
    const size_t count = static_cast<size_t>(std::count(text.begin(), text.end(), '\n'));
    if (!ImGui::CollapsingHeader(("Warnings (" + std::to_string(count) + ")##warnings").c_str())) return;
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.8f, 0.45f, 1.0f));
    for (size_t i = 0; i < places.size(); ++i) {
        ImGui::PushID(static_cast<int>(i));
        if (ImGui::SmallButton("Open")) status_ = open_in_editor(places[i].file, places[i].line);
        ImGui::SameLine();
        ImGui::TextWrapped("%s", places[i].message.c_str());
        ImGui::PopID();
    }
    if (places.empty()) ImGui::TextWrapped("%s", text.c_str());  // warnings without a place
    ImGui::PopStyleColor();
}

void Viewer::draw_effect_tab() {
    ImGui::TextWrapped("Effect: %s", effect_.path().empty() ? "(none: built-in views)" : effect_.path().c_str());
    const std::vector<ErrorLocation>& errors = effect_.error_places();
    if (!errors.empty() && ImGui::CollapsingHeader(("Errors (" + std::to_string(errors.size()) + "): click to open in your editor").c_str(),
                                                   ImGuiTreeNodeFlags_DefaultOpen)) {
        for (size_t i = 0; i < errors.size(); ++i) {
            ImGui::PushID(static_cast<int>(i));
            if (ImGui::SmallButton("Open")) status_ = open_in_editor(errors[i].file, errors[i].line);
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("Open %s at line %d in $VISUAL / $EDITOR", errors[i].file.c_str(), errors[i].line);
            ImGui::SameLine();
            ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.55f, 0.5f, 1.0f));
            ImGui::TextWrapped("%s", errors[i].message.c_str());
            ImGui::PopStyleColor();
            ImGui::PopID();
        }
    }
    if (ImGui::Button("Open...")) ImGui::OpenPopup("Open effect");
    if (ImGui::BeginPopup("Open effect")) {
        if (const auto file = file_browser_.draw()) {
            if (effect_.open(*file)) on_effect_opened();
            ImGui::CloseCurrentPopup();
        }
        ImGui::EndPopup();
    }
    if (!session()) {
        if (!effect_.requested_path().empty()) {
            // The file is watched; Reload also retries after fixing an include or a texture.
            if (ImGui::Button("Reload") && effect_.retry()) on_effect_opened();
            ImGui::SameLine();
            ImGui::TextDisabled("%s failed to load (watched: saving it retries)", effect_.requested_path().c_str());
        }
        draw_file_access();
        return;
    }
    ImGui::SameLine();
    if (ImGui::Button("Reload")) {
        effect_.reload();
    }
    draw_effect_warnings();
    if (!view_.objects.empty()) {
        auto& object = view_.objects[static_cast<size_t>(view_.selected_object)];
        // A technique's UIName annotation, where it has one, is what the user reads; its name (for the
        // command line) is in the tooltip.
        const effect::Technique* current = session()->effect().find_technique(object.technique);
        if (ImGui::BeginCombo("technique", current ? current->label().c_str() : object.technique.c_str())) {
            for (const auto& t : session()->effect().techniques) {
                if (ImGui::Selectable((t.label() + "##" + t.name).c_str(), t.name == object.technique)) {
                    for (auto& o : view_.objects)
                        if (&o == &object || ImGui::GetIO().KeyShift) o.technique = t.name;
                }
                if (ImGui::IsItemHovered()) ImGui::SetTooltip("--technique %s", t.name.c_str());
            }
            ImGui::EndCombo();
        }
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Technique of the selected object (Shift: all objects): --technique %s", object.technique.c_str());
    }
    ImGui::InputText("preset", preset_input_, sizeof preset_input_);
    if (ImGui::Button("Save preset")) {
        try {
            effect::save_preset(preset_input_, session()->effect(), session()->technique(), session()->values());
            status_ = std::string("saved ") + preset_input_;
        } catch (const std::exception& e) {
            status_ = e.what();
        }
    }
    ImGui::SameLine();
    if (ImGui::Button("Load preset")) {
        try {
            effect::load_preset(preset_input_, session()->effect(), session()->values());
            session()->reload_textures();
            status_ = std::string("loaded ") + preset_input_;
        } catch (const std::exception& e) {
            status_ = e.what();
        }
    }
    draw_file_access();
    ImGui::Separator();
    std::vector<std::string> shown;  // the techniques on screen
    for (const auto& o : view_.objects) {
        const std::string& t = o.technique.empty() ? session()->technique() : o.technique;
        if (o.view == ViewMode::Effect && std::find(shown.begin(), shown.end(), t) == shown.end()) shown.push_back(t);
    }
    if (shown.empty()) shown.push_back(session()->technique());
    draw_parameter_panel(*session(), shown);
}

void Viewer::draw_view_tab() {
    ImGui::Checkbox("pause rendering (Space)", &paused_);
    if (ImGui::Checkbox("vsync (V)", &vsync_)) glfwSwapInterval(vsync_ ? 1 : 0);
    ImGui::Checkbox("sRGB display (G: legacy linear)", &srgb_display_);
    const char* sample_counts[] = {"off", "2", "4", "8"};
    int msaa = samples_ == 0 ? 0 : samples_ == 2 ? 1 : samples_ == 4 ? 2 : 3;
    if (ImGui::Combo("MSAA", &msaa, sample_counts, 4)) samples_ = msaa == 0 ? 0 : 1 << msaa;
    ImGui::SliderFloat("exposure", &display_settings_.exposure_ev, -10.0f, 10.0f, "%+.1f EV");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Scales the picture by 2^EV before tone mapping (the view and PNG screenshots; EXR stays linear)");
    const char* tone_maps[] = {"none (clip)", "ACES filmic (Hill's fit)", "Khronos PBR Neutral"};
    int tone_map = static_cast<int>(display_settings_.tone_map);
    if (ImGui::Combo("tone mapping", &tone_map, tone_maps, 3)) display_settings_.tone_map = static_cast<image::ToneMap>(tone_map);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("PBR Neutral keeps colours below 0.76 (less a toe offset of 0.04) and compresses highlights");
    if (ImGui::Button("Fullscreen (F11)")) toggle_fullscreen();
    ImGui::Separator();
    ImGui::Checkbox("screenshot at the view's size", &shot_at_view_size_);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Off: render the screenshot at a size of its own, in pieces, while the UI goes on");
    ImGui::BeginDisabled(shot_at_view_size_);
    ImGui::InputInt2("screenshot size", &shot_size_.x);
    ImGui::EndDisabled();
    shot_size_ = glm::clamp(shot_size_, glm::ivec2(1), glm::ivec2(16384));
    ImGui::InputText("file (.png/.exr)", shot_input_, sizeof shot_input_);
    ImGui::Checkbox("transparent background", &transparent_shots_);
    if (ImGui::Button("Save screenshot (F12)")) save_screenshot();
    if (shot_job_) {
        char text[64];
        std::snprintf(text, sizeof text, "screenshot %.0f %%", shot_job_->progress() * 100);
        ImGui::ProgressBar(static_cast<float>(shot_job_->progress()), ImVec2(-1, 0), text);
    }
}

void Viewer::draw_help() {
    ImGui::Begin("Keys", &show_help_, ImGuiWindowFlags_AlwaysAutoResize);
    ImGui::TextUnformatted(
        "Mouse (render view)\n"
        "  left drag      turn the selected camera / light / object (arcball)\n"
        "  right drag     move it in the view plane (camera: pan)\n"
        "  wheel          zoom (camera Z translation)\n"
        "  left click     pick the pixel\n"
        "Keys\n"
        "  C / L / O      select camera / light / object\n"
        "  Tab            next object\n"
        "  R              reset the selection     Shift+R  reset all\n"
        "  Space          pause rendering         V        vsync\n"
        "  G              sRGB / legacy display   F11      fullscreen\n"
        "  F12            save screenshot\n"
        "  H or F1        this help");
    ImGui::End();
}

}  // namespace fxview::ui

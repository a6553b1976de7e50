#include "ui/environment_panel.hpp"

#include <imgui.h>

#include <cstdio>

namespace fxview::ui {

void EnvironmentPanel::apply(scene::Environment& environment, const std::string& source, render::EffectSession* session) {
    scene::Environment candidate = environment;
    candidate.source = source == "none" ? "" : source;
    if (session) session->environment(candidate);  // throws for a bad source before anything changes
    environment = candidate;
}

void EnvironmentPanel::draw(scene::Environment& environment, render::EffectSession* session) {
    ImGui::Separator();
    ImGui::TextUnformatted("Environment");
    const std::string& source = environment.source;
    const bool is_sky = source == "sky" || source.rfind("sky:", 0) == 0;
    const char* kinds[] = {"none", "studio", "daylight sky", "white furnace", "image file"};
    int kind = source.empty() ? 0 : source == "studio" ? 1 : is_sky ? 2 : source == "furnace" ? 3 : 4;
    const auto set = [&](const std::string& wanted) {
        try {
            apply(environment, wanted, session);
            error_.clear();
        } catch (const std::exception& e) {
            error_ = e.what();  // the last good environment stays
        }
    };
    char sky[64];
    std::snprintf(sky, sizeof sky, "sky:%g,%g", sun_elevation_, sun_cct_);
    if (ImGui::Combo("environment", &kind, kinds, IM_ARRAYSIZE(kinds))) {
        if (kind == 0) set("none");
        else if (kind == 1) set("studio");
        else if (kind == 2) set(sky);
        else if (kind == 3) set("furnace");
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Lights effects that use image-based lighting (analytic.fx's PBR and Lambert, .brdf files) and the spectral effects "
                          "(an image's colours turned into spectra), and fills the background");
    if (kind == 2) {
        sky_edited_ |= ImGui::SliderFloat("sun elevation", &sun_elevation_, 0.0f, 90.0f, "%.0f deg");
        sky_edited_ |= ImGui::SliderFloat("sun temperature", &sun_cct_, 4000.0f, 25000.0f, "%.0f K");
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("The sun's colour: CIE daylight of this correlated colour temperature");
        if (sky_edited_ && !ImGui::IsAnyItemActive()) {  // made when the slider is let go (about a second)
            std::snprintf(sky, sizeof sky, "sky:%g,%g", sun_elevation_, sun_cct_);
            set(sky);
            sky_edited_ = false;
        }
    }
    if (kind == 4 || kind == 0) {
        ImGui::InputTextWithHint("##environment file", ".hdr/.exr equirectangular, cube cross or .dds", file_, sizeof file_);
        ImGui::SameLine();
        if (ImGui::Button("Load")) set(file_);
    }
    if (session)
        if (const std::string warning = session->unused_environment_warning(environment); !warning.empty())
            ImGui::TextColored(ImVec4(1.0f, 0.75f, 0.3f, 1.0f), "%s",
                               warning.find("point light only") == std::string::npos
                                   ? "This image's colours are more varied than its three spectra hold:\nwhere a film or grating filters saturated colours,\ncolours may be several CIEDE2000 units off."
                                   : "This technique is lit by the point light only:\nthe environment fills the background.");
    if (!error_.empty()) ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.35f, 1.0f), "%s", error_.c_str());
    if (!environment.source.empty()) {
        ImGui::SliderFloat("rotation", &environment.rotation_degrees, -180.0f, 180.0f, "%.0f deg");
        ImGui::SliderFloat("intensity", &environment.intensity, 0.0f, 8.0f, "%.2f", ImGuiSliderFlags_Logarithmic);
        if (kind == 3) ImGui::TextDisabled("uniform radiance 1: a white surface that conserves energy shows 1");
    }
}

}  // namespace fxview::ui

#include "ui/fit_panel.hpp"

#include <imgui.h>

#include <vector>

#include "core/error.hpp"
#include "fit/measurement.hpp"

namespace fxview::ui {
namespace {

constexpr const char* kTechnique = "AshikhminShirleyFit";

bool has_fit_parameters(const render::EffectSession& session) {
    const effect::Effect& e = session.effect();
    return e.find_parameter("FitDiffuse") && e.find_parameter("FitSpecular") && e.find_parameter("FitExponent");
}

}  // namespace

bool run_fit(FitPanelState& state, render::EffectSession* session) {
    try {
        const fit::BrdfGrid measured = fit::read_measurement(state.path);
        fit::FitResult result = fit::fit_ashikhmin_shirley(measured, state.options);
        if (session && has_fit_parameters(*session)) {
            auto& numbers = session->values().numbers;
            numbers["FitDiffuse"] = {result.cd[0], result.cd[1], result.cd[2]};
            numbers["FitSpecular"] = {result.cs[0], result.cs[1], result.cs[2]};
            numbers["FitExponent"] = {result.ns};
            session->select_technique(kTechnique);
            state.error.clear();
        } else {
            state.error = "fitted, but the effect has no FitDiffuse/FitSpecular/FitExponent to show it: load effects/brdf/analytic.fx";
        }
        state.result = std::move(result);
        return true;
    } catch (const std::exception& e) {
        state.error = e.what();  // the parameters and the previous result stay
        return false;
    }
}

void draw_fit_panel(FitPanelState& state, render::EffectSession* session) {
    ImGui::TextWrapped("Fit Ashikhmin-Shirley (seed 000 eq. 4.28) to a measured BRDF: a grid CSV or a MERL .binary file.");
    ImGui::InputText("File", state.path, sizeof state.path);
    float limit = static_cast<float>(state.options.limit_deg);
    if (ImGui::SliderFloat("Limit angle", &limit, 5.0f, 90.0f, "%.0f deg")) state.options.limit_deg = limit;
    ImGui::SliderInt("Iterations", &state.options.iterations, 1, 2000);
    float start_ns = static_cast<float>(state.options.start_ns);
    if (ImGui::DragFloat("Start ns", &start_ns, 1.0f, 1.0f, 10000.0f)) state.options.start_ns = start_ns;
    if (ImGui::Button("Fit")) run_fit(state, session);
    if (!state.error.empty()) ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.3f, 1.0f), "%s", state.error.c_str());
    if (!state.result) return;
    const fit::FitResult& r = *state.result;
    ImGui::Separator();
    ImGui::Text("ns %.3f   e (RGB) %.5g", r.ns, r.error_rgb);
    ImGui::Text("cd %.4f %.4f %.4f", r.cd[0], r.cd[1], r.cd[2]);
    ImGui::Text("cs %.4f %.4f %.4f", r.cs[0], r.cs[1], r.cs[2]);
    ImGui::Text("renderer: Rs %.4f  Rd %.4f %.4f %.4f", r.rs, r.rd_renderer[0], r.rd_renderer[1], r.rd_renderer[2]);
    std::vector<float> curve(r.error_per_iteration.begin(), r.error_per_iteration.end());
    if (!curve.empty())
        ImGui::PlotLines("e per iteration", curve.data(), static_cast<int>(curve.size()), 0, nullptr, FLT_MAX, FLT_MAX, ImVec2(0, 80));
}

}  // namespace fxview::ui

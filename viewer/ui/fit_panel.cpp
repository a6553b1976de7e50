#include "ui/fit_panel.hpp"

#include <glad/gl.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "fit/fit_preview.hpp"
#include "core/error.hpp"
#include "fit/measurement.hpp"
#include "image/color_encoding.hpp"

namespace fxview::ui {
namespace {

constexpr const char* kTechnique = "AshikhminShirleyFit";

bool has_fit_parameters(const render::EffectSession& session) {
    const effect::Effect& e = session.effect();
    return e.find_parameter("FitDiffuse") && e.find_parameter("FitSpecular") && e.find_parameter("FitExponent");
}

}  // namespace

// The preview image as an 8-bit sRGB texture for ImGui (the viewer's UI draws sRGB bytes).
void upload_preview(FitPanelState& state, const fit::BrdfGrid& measured, const fit::FitResult& result) {
    fit::PreviewOptions options;
    options.brighten = state.preview_brighten;
    options.limit_deg = state.options.limit_deg;
    const fit::FitPreview fit_preview = fit::fit_preview(measured, fit::evaluate_fit(measured, result), options);
    const image::FloatImage& preview = fit_preview.image;
    state.preview_difference_scale = fit_preview.difference_scale;
    std::vector<std::uint8_t> bytes(static_cast<size_t>(preview.width) * preview.height * 4);
    for (size_t i = 0; i < bytes.size(); ++i)
        bytes[i] = image::to_8bit(preview.data[i], i % 4 == 3 ? image::Encoding::Linear : image::Encoding::Srgb);
    state.preview = gl::create_texture(GL_TEXTURE_2D);
    glTextureStorage2D(state.preview.get(), 1, GL_RGBA8, preview.width, preview.height);
    glTextureSubImage2D(state.preview.get(), 0, 0, 0, preview.width, preview.height, GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
    glTextureParameteri(state.preview.get(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(state.preview.get(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    state.preview_width = preview.width;
    state.preview_height = preview.height;
}

bool run_fit(FitPanelState& state, render::EffectSession* session) {
    try {
        const fit::Measurement measurement = fit::read_measurement_for_fit(state.path);
        const fit::BrdfGrid& measured = measurement.grid;
        fit::FitResult result = fit::fit_ashikhmin_shirley(fit::observations(measurement, state.options.limit_deg), state.options);
        upload_preview(state, measured, result);
        if (session && has_fit_parameters(*session)) {
            auto& numbers = session->values().numbers;
            numbers["FitDiffuse"] = {result.cd[0], result.cd[1], result.cd[2]};
            numbers["FitSpecular"] = {result.cs[0], result.cs[1], result.cs[2]};
            numbers["FitExponent"] = {result.ns};
            // analytic.fx shows the fit with AshikhminShirleyFit; measured.fx keeps its technique
            // (Measured, Fitted or Difference), which reads the same parameters.
            if (session->effect().find_technique(kTechnique)) session->select_technique(kTechnique);
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
    int solver = state.options.solver == fit::Solver::Thesis ? 1 : 0;
    if (ImGui::Combo("Solver", &solver, "Global optimum (bounded)\0Thesis (seed 000's schedule)\0"))
        state.options.solver = solver == 1 ? fit::Solver::Thesis : fit::Solver::Global;
    if (state.options.solver == fit::Solver::Thesis) {
        ImGui::SliderInt("Iterations", &state.options.iterations, 1, 2000);
        float start_ns = static_cast<float>(state.options.start_ns);
        if (ImGui::DragFloat("Start ns", &start_ns, 1.0f, 1.0f, 10000.0f)) state.options.start_ns = start_ns;
    }
    if (ImGui::Button("Fit")) run_fit(state, session);
    if (!state.error.empty()) ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.3f, 1.0f), "%s", state.error.c_str());
    if (!state.result) return;
    const fit::FitResult& r = *state.result;
    ImGui::Separator();
    if (r.converged) ImGui::TextColored(ImVec4(0.5f, 0.9f, 0.5f, 1.0f), "Converged (%s solver)", r.solver.c_str());
    else ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.3f, 1.0f), "NOT converged (%s solver)", r.solver.c_str());
    ImGui::TextWrapped("%s", r.stop_reason.c_str());
    for (const std::string& warning : r.warnings) ImGui::TextColored(ImVec4(1.0f, 0.75f, 0.3f, 1.0f), "%s", warning.c_str());
    ImGui::Text("weighted cost %.5g (optimum %.5g)", r.cost, r.optimum_cost);
    ImGui::Text("ns %.3f   e (RGB) %.5g", r.ns, r.error_rgb);
    ImGui::Text("cd %.4f %.4f %.4f", r.cd[0], r.cd[1], r.cd[2]);
    ImGui::Text("cs %.4f %.4f %.4f", r.cs[0], r.cs[1], r.cs[2]);
    ImGui::Text("renderer: Rs %.4f  Rd %.4f %.4f %.4f", r.rs, r.rd_renderer[0], r.rd_renderer[1], r.rd_renderer[2]);
    // On a log axis: the error falls over decades; labelled with its range.
    std::vector<float> curve;
    for (const double e : r.error_per_iteration) curve.push_back(static_cast<float>(std::log10(std::max(e, 1e-300))));
    if (!curve.empty()) {
        const auto [low, high] = std::minmax_element(curve.begin(), curve.end());
        const std::string overlay = "e from 10^" + std::to_string(*high).substr(0, 5) + " to 10^" + std::to_string(*low).substr(0, 5);
        ImGui::PlotLines("log10 e per iteration", curve.data(), static_cast<int>(curve.size()), 0, overlay.c_str(), FLT_MAX, FLT_MAX,
                         ImVec2(0, 80));
    }
    if (state.preview.get() != 0) {
        ImGui::PushTextWrapPos(0.0f);  // wrap at the panel's edge instead of cutting the text off
        ImGui::TextDisabled("measured | model (x%.0f) | difference; rows: light angle blocks, view angle; columns: view azimuth, "
                            "mirror side in the centre; rows outside the fit greyed",
                            state.preview_brighten);
        ImGui::TextDisabled("difference: red = measured above the model, blue = below, full colour at %.3g 1/sr (bar below)",
                            state.preview_difference_scale);
        ImGui::PopTextWrapPos();
        // Fit the image to the panel's width, keeping its aspect.
        const float width = ImGui::GetContentRegionAvail().x;
        const float height = width * static_cast<float>(state.preview_height) / static_cast<float>(state.preview_width);
        ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(state.preview.get())), ImVec2(width, height));
    }
}

}  // namespace fxview::ui

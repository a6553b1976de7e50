#include "ui/brdf_panel.hpp"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <numbers>

#include "app/brdf_evaluation.hpp"

namespace fxview::ui {
namespace {

constexpr int kPlaneSamples = 361;  // every half degree

// The polar plot into the next `height` pixels of the window: radius ∝ f (or its logarithm over four
// decades), the mirror side on the left, the light's direction drawn in yellow.
void draw_polar(const std::vector<double>& values, const std::vector<double>& measured, float incidence, bool logarithmic, float height) {
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const float width = ImGui::GetContentRegionAvail().x;
    ImGui::Dummy(ImVec2(width, height));
    ImDrawList* list = ImGui::GetWindowDrawList();
    const float cx = origin.x + width * 0.5f, cy = origin.y + height - 6.0f, radius = std::max(10.0f, std::min(width * 0.5f - 6.0f, height - 12.0f));
    double peak = 0;
    for (const auto* series : {&values, &measured})
        for (const double v : *series)
            if (std::isfinite(v)) peak = std::max(peak, v);
    const double top = logarithmic ? std::ceil(std::log10(std::max(peak, 1e-30))) : (peak > 0 ? peak : 1.0);
    const auto to_radius = [&](double f) {
        const double t = logarithmic ? (f > 0 ? (std::log10(f) - (top - 4.0)) / 4.0 : 0.0) : f / top;
        return static_cast<float>(std::clamp(t, 0.0, 1.0)) * radius;
    };
    const auto point = [&](double degrees, float r) {
        const double a = degrees * std::numbers::pi / 180.0;
        return ImVec2(cx + r * static_cast<float>(std::sin(a)), cy - r * static_cast<float>(std::cos(a)));
    };
    const ImU32 grid = IM_COL32(90, 90, 90, 255), curve = IM_COL32(80, 170, 255, 255), light = IM_COL32(240, 190, 40, 255);
    for (int ring = 1; ring <= 4; ++ring) {
        const float r = radius * ring / 4.0f;
        for (int k = 0; k < 60; ++k) list->AddLine(point(-90.0 + 3.0 * k, r), point(-87.0 + 3.0 * k, r), grid);
    }
    for (int degrees = -90; degrees <= 90; degrees += 30) list->AddLine(ImVec2(cx, cy), point(degrees, radius), grid);
    list->AddLine(ImVec2(cx, cy), point(incidence, radius), light, 2.0f);
    const ImU32 measured_curve = IM_COL32(255, 140, 40, 255);
    for (const auto& [series, colour] : {std::pair{&values, curve}, std::pair{&measured, measured_curve}})
        for (size_t k = 0; k + 1 < series->size(); ++k) {
            const std::vector<double>& v = *series;
            if (!std::isfinite(v[k]) || !std::isfinite(v[k + 1])) continue;
            const double d0 = -90.0 + 180.0 * (k + 0.5) / v.size(), d1 = -90.0 + 180.0 * (k + 1.5) / v.size();
            list->AddLine(point(d0, to_radius(v[k])), point(d1, to_radius(v[k + 1])), colour, 2.0f);
        }
}

}  // namespace

void BrdfPanel::update_plane(render::EffectSession& session) {
    // The model follows the technique on screen: set when either changes, not every frame.
    if (followed_effect_ != &session.effect() || followed_technique_ != session.technique()) {
        app::follow_technique(session, session.technique());
        followed_effect_ = &session.effect();
        followed_technique_ = session.technique();
    }
    if (plotted_effect_ == &session.effect() && plotted_values_ == session.values().numbers && plotted_incidence_ == incidence_) return;
    plotted_effect_ = &session.effect();
    plotted_values_ = session.values().numbers;
    plotted_incidence_ = incidence_;
    plane_.clear();
    try {
        const image::FloatImage plane = app::evaluate_brdf_plane(session, incidence_, kPlaneSamples);
        for (int k = 0; k < kPlaneSamples; ++k) {
            const float* p = plane.pixel(k, 0);
            plane_.push_back((static_cast<double>(p[0]) + p[1] + p[2]) / 3.0);
        }
        error_.clear();
    } catch (const std::exception& e) {
        error_ = e.what();
    }
}

void BrdfPanel::load_measured(const std::string& path) {
    measured_ = fit::read_merl(path);
    measured_name_ = path;
    measured_incidence_ = -1.0f;  // recomputed at the next draw
    std::snprintf(measured_path_, sizeof measured_path_, "%s", path.c_str());
}

const app::BrdfCheck& BrdfPanel::check(render::EffectSession& session) {
    app::follow_technique(session, session.technique());
    check_ = app::analyse_brdf_grid(app::evaluate_brdf_grid(session, false), app::evaluate_brdf_grid(session, true));
    checked_values_ = session.values().numbers;
    return *check_;
}

void BrdfPanel::draw(render::EffectSession* session) {
    if (!session || !app::has_brdf_grid(*session)) {
        ImGui::TextWrapped("Open a .brdf file (BRDF Explorer's format) to plot its BRDF and check it for energy conservation and reciprocity.");
        return;
    }
    ImGui::SliderFloat("Incidence", &incidence_, 0.0f, 89.0f, "%.0f deg");
    ImGui::SameLine();
    ImGui::Checkbox("Log", &logarithmic_);
    update_plane(*session);
    if (!error_.empty()) {
        ImGui::TextWrapped("%s", error_.c_str());
        return;
    }
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
    ImGui::TextWrapped("f(l, v) in the plane of incidence (mean of R, G, B); mirror side left, light in yellow");
    ImGui::PopStyleColor();
    if (measured_ && measured_incidence_ != incidence_) {
        measured_plane_.clear();
        for (const auto& f : app::measured_plane(*measured_, incidence_, kPlaneSamples)) measured_plane_.push_back((f[0] + f[1] + f[2]) / 3.0);
        measured_incidence_ = incidence_;
    }
    draw_polar(plane_, measured_ ? measured_plane_ : std::vector<double>{}, incidence_, logarithmic_,
               std::min(ImGui::GetContentRegionAvail().x * 0.55f, 320.0f));
    ImGui::InputTextWithHint("##measured", "MERL .binary file to compare", measured_path_, sizeof measured_path_);
    ImGui::SameLine();
    if (ImGui::Button("Load measured")) {
        try {
            load_measured(measured_path_);
            measured_error_.clear();
        } catch (const std::exception& e) {
            measured_error_ = e.what();  // the last good measurement stays
        }
    }
    if (!measured_error_.empty()) ImGui::TextWrapped("%s", measured_error_.c_str());
    if (measured_) ImGui::TextWrapped("measured (orange): %s", measured_name_.c_str());
    if (ImGui::Button("Check energy and reciprocity")) {
        try {
            check(*session);
        } catch (const std::exception& e) {
            error_ = e.what();
        }
    }
    if (!check_) return;
    if (checked_values_ != session->values().numbers) ImGui::TextDisabled("(for earlier parameter values: check again)");
    std::vector<float> albedo;
    for (const auto& rgb : check_->albedo) albedo.push_back(static_cast<float>((rgb[0] + rgb[1] + rgb[2]) / 3.0));
    ImGui::PlotLines("##albedo", albedo.data(), static_cast<int>(albedo.size()), 0, "albedo, 1..89 deg", 0.0f,
                     std::max(1.1f, *std::max_element(albedo.begin(), albedo.end())), ImVec2(ImGui::GetContentRegionAvail().x, 90));
    ImGui::Text("largest albedo %.4f at %.0f deg: %s", check_->max_albedo, check_->max_albedo_degrees,
                check_->conserves_energy ? "energy conserving" : "reflects more than it receives");
    ImGui::Text("reciprocity: largest relative |f(l,v) - f(v,l)| %.3g: %s", check_->reciprocity,
                check_->reciprocal ? "reciprocal" : "not reciprocal");
    ImGui::Text("negative at %ld, NaN or infinite at %ld of %ld samples", check_->negative, check_->non_finite, check_->samples);
}

}  // namespace fxview::ui

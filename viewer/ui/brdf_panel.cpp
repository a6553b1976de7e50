#include "ui/brdf_panel.hpp"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <filesystem>
#include <numbers>

#include "app/brdf_evaluation.hpp"
#include "app/brdf_plot.hpp"
#include "core/error.hpp"

namespace fxview::ui {
namespace {

constexpr int kPlaneSamples = 361;  // every half degree

struct Curve {
    const std::vector<double>* values;
    ImU32 colour;
};

// The polar plot into the next `height` pixels of the window: radius ∝ f (or its logarithm over four
// decades), the mirror side on the left, the light's direction drawn in yellow.
void draw_polar(const std::vector<Curve>& curves, float incidence, bool logarithmic, float height) {
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const float width = ImGui::GetContentRegionAvail().x;
    ImGui::Dummy(ImVec2(width, height + ImGui::GetTextLineHeight()));  // the scale below the horizon
    ImDrawList* list = ImGui::GetWindowDrawList();
    const float cx = origin.x + width * 0.5f, cy = origin.y + height - 6.0f, radius = std::max(10.0f, std::min(width * 0.5f - 6.0f, height - 12.0f));
    double peak = 0;
    for (const Curve& curve : curves)
        for (const double v : *curve.values)
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
    const ImU32 grid = IM_COL32(90, 90, 90, 255), light = IM_COL32(240, 190, 40, 255);
    for (int ring = 1; ring <= 4; ++ring) {
        const float r = radius * ring / 4.0f;
        for (int k = 0; k < 60; ++k) list->AddLine(point(-90.0 + 3.0 * k, r), point(-87.0 + 3.0 * k, r), grid);
    }
    for (int degrees = -90; degrees <= 90; degrees += 30) list->AddLine(ImVec2(cx, cy), point(degrees, radius), grid);
    // The rings' values along the right-hand horizon: f in 1/sr (linear: quarters of the peak; log: decades).
    const ImU32 scale = IM_COL32(150, 150, 150, 255);
    for (int ring = 1; ring <= 4; ++ring) {
        char value[32];
        if (logarithmic) std::snprintf(value, sizeof value, "1e%+.0f", top - 4.0 + ring);
        else std::snprintf(value, sizeof value, "%.3g", top * ring / 4.0);
        const ImVec2 size = ImGui::CalcTextSize(value);
        list->AddText(ImVec2(std::min(cx + radius * ring / 4.0f - size.x * 0.5f, origin.x + width - size.x), cy + 1.0f), scale, value);
    }
    list->AddText(ImVec2(origin.x, origin.y), scale, logarithmic ? "f (1/sr), log scale" : "f (1/sr)");
    list->AddLine(ImVec2(cx, cy), point(incidence, radius), light, 2.0f);
    for (const Curve& curve : curves)
        for (size_t k = 0; k + 1 < curve.values->size(); ++k) {
            const std::vector<double>& v = *curve.values;
            if (!std::isfinite(v[k]) || !std::isfinite(v[k + 1])) continue;
            const double d0 = -90.0 + 180.0 * (k + 0.5) / v.size(), d1 = -90.0 + 180.0 * (k + 1.5) / v.size();
            list->AddLine(point(d0, to_radius(v[k])), point(d1, to_radius(v[k + 1])), curve.colour, 2.0f);
        }
}

// Colours of kept curves after the live one (blue) and the measured one (orange).
ImU32 kept_colour(size_t index) {
    static constexpr ImU32 colours[] = {IM_COL32(90, 200, 110, 255), IM_COL32(220, 90, 200, 255), IM_COL32(230, 80, 80, 255),
                                        IM_COL32(170, 170, 170, 255), IM_COL32(120, 220, 230, 255), IM_COL32(200, 200, 80, 255)};
    return colours[index % std::size(colours)];
}

ImVec4 to_vec4(ImU32 colour) { return ImGui::ColorConvertU32ToFloat4(colour); }

constexpr ImU32 kLiveColour = IM_COL32(80, 170, 255, 255), kMeasuredColour = IM_COL32(255, 140, 40, 255);

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

namespace {

std::string format_values(const std::vector<double>& values) {
    std::string text;
    for (const double v : values) {
        char number[32];
        std::snprintf(number, sizeof number, "%.4g", v);
        text += (text.empty() ? "" : ",") + std::string(number);
    }
    return text;
}

}  // namespace

void BrdfPanel::keep_curve(render::EffectSession& session) {
    update_plane(session);
    char label[96];
    std::snprintf(label, sizeof label, "#%zu %s, %s, θi %.0f°", kept_.size() + 1,
                  std::filesystem::path(session.effect().path).filename().string().c_str(), session.technique().c_str(), incidence_);
    std::string text = label;
    if (!kept_.empty()) {  // what changed since the curve kept before, so that curves of one file tell apart
        std::string changes;
        for (const auto& [name, value] : session.values().numbers) {
            const auto before = kept_.back().parameters.find(name);
            if (before != kept_.back().parameters.end() && before->second != value)
                changes += (changes.empty() ? "" : "; ") + name + " " + format_values(before->second) + " -> " + format_values(value);
        }
        if (!changes.empty()) text += ": " + changes;
    }
    kept_.push_back({text, plane_, session.values().numbers});
}

std::vector<std::string> BrdfPanel::kept_labels() const {
    std::vector<std::string> labels;
    for (const auto& k : kept_) labels.push_back(k.label);
    return labels;
}

// The lobe, slice or sphere for the current values, redrawn when the view, a value or an angle changes.
void BrdfPanel::update_picture(render::EffectSession& session) {
    if (picture_.empty() || pictured_view_ != view_ || picture_values_ != session.values().numbers || picture_effect_ != &session.effect() ||
        picture_incidence_ != incidence_ || picture_phi_d_ != phi_d_ || picture_technique_ != session.technique() || picture_log_ != logarithmic_) {
        pictured_view_ = view_;
        picture_values_ = session.values().numbers;
        picture_effect_ = &session.effect();
        picture_incidence_ = incidence_;
        picture_phi_d_ = phi_d_;
        picture_technique_ = session.technique();
        picture_log_ = logarithmic_;
    } else {
        return;
    }
    try {
        const std::string name = std::filesystem::path(session.effect().path).stem().string();
        if (view_ == View::Lobe) {
            const image::FloatImage hemisphere = app::evaluate_brdf_hemisphere(session, incidence_, 96, 40);
            picture_ = upload_ui_image(app::lobe_chart(hemisphere, name, incidence_, {640, 480}));
            picture_caption_ = "f(l, v) over the hemisphere for the light in yellow, seen from above and aside";
        } else if (view_ == View::Slice) {
            image::FloatImage slice = app::evaluate_brdf_slice(session, phi_d_, 128, 128);
            const float white = app::scale_slice_for_display(slice);
            if (logarithmic_)  // four decades below white
                for (float& v : slice.data) v = v > 0 ? std::clamp((std::log10(v) + 4.0f) / 4.0f, 0.0f, 1.0f) : 0.0f;
            picture_ = upload_ui_image(slice, true);
            char caption[200];
            std::snprintf(caption, sizeof caption, "theta_h 0-90 deg across, theta_d 90 (top) to 0 deg, phi_d %.0f deg; white: f = %.3g%s", phi_d_, white,
                          logarithmic_ ? ", black: 1e-4 of it" : "");
            picture_caption_ = caption;
        } else {
            const image::FloatImage sphere = app::render_lit_sphere(session, 256);
            picture_ = upload_ui_image(sphere);
            picture_caption_ = "technique " + session.technique() + " on a sphere, lit by the scene's default light";
        }
        error_.clear();
    } catch (const std::exception& e) {
        error_ = e.what();
    }
}

std::string BrdfPanel::show(View view, render::EffectSession& session) {
    view_ = view;
    update_plane(session);
    if (view_ != View::Polar) update_picture(session);
    if (!error_.empty()) throw Error(error_);
    return view_ == View::Polar ? "polar plot of the plane of incidence" : picture_caption_;
}

void BrdfPanel::load_measured(const std::string& path) {
    measured_ = fit::read_merl(path);
    measured_name_ = path;
    measured_incidence_ = -1.0f;  // recomputed at the next draw
    std::snprintf(measured_path_, sizeof measured_path_, "%s", path.c_str());
}

void BrdfPanel::start_check(render::EffectSession& session) {
    app::follow_technique(session, session.technique());
    checker_.start(session);
    check_.reset();
    checked_effect_ = &session.effect();
    checked_technique_ = session.technique();
    check_error_.clear();
}

void BrdfPanel::update(render::EffectSession* session) {
    if (!checker_.running()) return;
    if (!session || &session->effect() != checked_effect_ || session->technique() != checked_technique_) {
        checker_.cancel();
        check_error_ = "check dropped: the effect or its technique changed";
        return;
    }
    try {
        // About 30 ms of rendering a UI frame (the UI's own work comes on top).
        if (checker_.step(*session, 0.03)) {
            check_ = checker_.result();
            checked_values_ = checker_.values().numbers;
        }
    } catch (const std::exception& e) {
        checker_.cancel();
        check_error_ = e.what();
    }
}

void BrdfPanel::draw(render::EffectSession* session) {
    if (!session || !app::has_brdf_grid(*session)) {
        ImGui::TextWrapped("Open a .brdf file (BRDF Explorer's format) to plot its BRDF and check it for energy conservation and reciprocity.");
        return;
    }
    static const char* views[] = {"Polar plot", "3D lobe", "Slice (theta_h, theta_d)", "Lit sphere"};
    int view = static_cast<int>(view_);
    if (ImGui::Combo("View", &view, views, IM_ARRAYSIZE(views))) view_ = static_cast<View>(view);
    if (view_ == View::Slice) {
        ImGui::SliderFloat("phi_d", &phi_d_, 0.0f, 180.0f, "%.0f deg");
    } else if (view_ != View::Sphere) {
        ImGui::SliderFloat("Incidence", &incidence_, 0.0f, 89.0f, "%.0f deg");
    }
    if (view_ == View::Polar || view_ == View::Slice) {
        ImGui::SameLine();
        ImGui::Checkbox("Log", &logarithmic_);
    }
    update_plane(*session);
    if (view_ != View::Polar) update_picture(*session);
    if (!error_.empty()) {
        ImGui::TextWrapped("%s", error_.c_str());
        return;
    }
    if (view_ != View::Polar) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
        ImGui::TextWrapped("%s", picture_caption_.c_str());
        ImGui::PopStyleColor();
        picture_.draw();
    } else {
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
        ImGui::TextWrapped("f(l, v) in the plane of incidence (mean of R, G, B); mirror side left, light in yellow");
        ImGui::PopStyleColor();
        if (measured_ && measured_incidence_ != incidence_) {
            measured_plane_.clear();
            for (const auto& f : app::measured_plane(*measured_, incidence_, kPlaneSamples)) measured_plane_.push_back((f[0] + f[1] + f[2]) / 3.0);
            measured_incidence_ = incidence_;
        }
        std::vector<Curve> curves{{&plane_, kLiveColour}};
        if (measured_) curves.push_back({&measured_plane_, kMeasuredColour});
        for (size_t k = 0; k < kept_.size(); ++k) curves.push_back({&kept_[k].values, kept_colour(k)});
        draw_polar(curves, incidence_, logarithmic_, std::min(ImGui::GetContentRegionAvail().x * 0.55f, 320.0f));
        if (ImGui::Button("Keep curve")) keep_curve(*session);
        ImGui::SameLine();
        ImGui::TextDisabled("(to compare: change parameters or open another file)");
        ImGui::PushTextWrapPos(0.0f);
        for (size_t k = 0; k < kept_.size(); ++k) ImGui::TextColored(to_vec4(kept_colour(k)), "%s", kept_[k].label.c_str());
        ImGui::PopTextWrapPos();
        if (!kept_.empty() && ImGui::SmallButton("Clear kept curves")) kept_.clear();
    }
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
    if (checker_.running()) {
        ImGui::ProgressBar(static_cast<float>(checker_.progress()), ImVec2(-1, 0), "checking energy and reciprocity");
        if (ImGui::SmallButton("Cancel check")) checker_.cancel();
    } else if (ImGui::Button("Check energy and reciprocity")) {
        start_check(*session);
    }
    if (!check_error_.empty()) ImGui::TextWrapped("%s", check_error_.c_str());
    if (!check_) return;
    if (checked_values_ != session->values().numbers) ImGui::TextDisabled("(for earlier parameter values: check again)");
    // The first azimuth of incidence (0°), as the plot's caption says; the verdict covers every azimuth checked.
    std::vector<float> albedo;
    for (const app::AlbedoEstimate& e : check_->albedo)
        if (e.phi_i_degrees == check_->albedo.front().phi_i_degrees) albedo.push_back(static_cast<float>((e.rgb[0] + e.rgb[1] + e.rgb[2]) / 3.0));
    ImGui::PlotLines("##albedo", albedo.data(), static_cast<int>(albedo.size()), 0, "albedo, 1..89 deg (phi_i 0)", 0.0f,
                     std::max(1.1f, *std::max_element(albedo.begin(), albedo.end())), ImVec2(ImGui::GetContentRegionAvail().x, 90));
    ImGui::TextWrapped("largest albedo %.4f at %.0f deg (phi_i %g): %s", check_->max_albedo, check_->max_albedo_degrees, check_->max_albedo_phi_degrees,
                       check_->energy == app::BrdfCheck::Energy::Conserves  ? "energy conserving"
                       : check_->energy == app::BrdfCheck::Energy::Violates ? "reflects more than it receives"
                                                                            : "unresolved");
    if (check_->energy == app::BrdfCheck::Energy::Unresolved) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.75f, 0.3f, 1.0f));
        ImGui::TextWrapped("No verdict: %s.", check_->unresolved_reason.c_str());
        ImGui::PopStyleColor();
    }
    ImGui::Text("reciprocity: largest relative |f(l,v) - f(v,l)| %.3g: %s", check_->reciprocity,
                check_->reciprocal ? "reciprocal" : "not reciprocal");
    ImGui::Text("negative at %ld, NaN or infinite at %ld of %ld samples", check_->negative, check_->non_finite, check_->samples);
    if (check_->file_sampling) ImGui::TextWrapped("The file's own importance sampling (isFunc) took part.");
    if (!check_->file_sampling_note.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.75f, 0.3f, 1.0f));
        ImGui::TextWrapped("%s.", check_->file_sampling_note.c_str());
        ImGui::PopStyleColor();
    }
}

}  // namespace fxview::ui

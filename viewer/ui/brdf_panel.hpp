// The BRDF tab: for an effect with the BRDF grid (every .brdf file), BRDF Explorer's views live as
// parameters change: the polar plot of the plane of incidence (with kept curves of earlier parameter
// values or other files overlaid), the 3D lobe, Rusinkiewicz's (θh, θd) slice and the lit sphere;
// and on request the physics checks of brdf-check
// (directional albedo against incidence, reciprocity, negative and NaN values). Values come from the
// GPU through the viewer's own session (app/brdf_evaluation.hpp).
#pragma once
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "app/brdf_check.hpp"
#include "fit/merl.hpp"
#include "render/effect_session.hpp"
#include "ui/brdf_check_runner.hpp"
#include "ui/ui_image.hpp"

namespace fxview::ui {

class BrdfPanel {
public:
    void draw(render::EffectSession* session);
    // The checks at the current parameter values (the Check button; the script verb brdf-check),
    // spread over the frames that follow (update); a check of another effect or technique is
    // dropped when that changes.
    void start_check(render::EffectSession& session);
    void update(render::EffectSession* session);  // once a frame: a slice of a running check
    bool checking() const { return checker_.running(); }
    const std::optional<app::BrdfCheck>& last_check() const { return check_; }
    const std::string& check_error() const { return check_error_; }
    // A MERL file to overlay on the polar plot (the Measured field; the script verb brdf-measured).
    // Throws Error naming the file when it cannot be read.
    void load_measured(const std::string& path);
    // Keeps the current polar curve for comparison (the Keep curve button; the script verb brdf-keep).
    void keep_curve(render::EffectSession& session);
    size_t kept_curves() const { return kept_.size(); }
    // Each kept curve's label: its number, file, technique and incidence, and what differs from the
    // curve kept before it (the parameters changed, with their old and new values).
    std::vector<std::string> kept_labels() const;

    enum class View { Polar, Lobe, Slice, Sphere };
    // The view shown (the View combo; the script verb brdf-view polar|lobe|slice|sphere), drawn at
    // once: returns its caption; throws Error when the BRDF could not be evaluated.
    std::string show(View view, render::EffectSession& session);

private:
    struct KeptCurve {
        std::string label;
        std::vector<double> values;
        std::map<std::string, std::vector<double>> parameters;  // the values it was kept with
    };
    void update_plane(render::EffectSession& session);
    void update_picture(render::EffectSession& session);

    View view_ = View::Polar;
    float phi_d_ = 90.0f;
    std::vector<KeptCurve> kept_;
    UiImage picture_;  // lobe, slice or sphere
    View pictured_view_ = View::Polar;
    std::string picture_caption_;
    std::map<std::string, std::vector<double>> picture_values_;
    const void* picture_effect_ = nullptr;
    float picture_incidence_ = -1.0f, picture_phi_d_ = -1.0f;
    std::string picture_technique_;
    bool picture_log_ = false;

    float incidence_ = 30.0f;
    bool logarithmic_ = false;
    std::vector<double> plane_;  // mean of R, G, B across the plane of incidence
    const void* plotted_effect_ = nullptr;
    const void* followed_effect_ = nullptr;
    std::string followed_technique_;
    std::map<std::string, std::vector<double>> plotted_values_;
    float plotted_incidence_ = -1.0f;
    std::optional<app::BrdfCheck> check_;
    std::map<std::string, std::vector<double>> checked_values_;
    BrdfCheckRunner checker_;
    const void* checked_effect_ = nullptr;
    std::string checked_technique_, check_error_;
    std::string error_;
    std::optional<fit::MerlBrdf> measured_;
    std::string measured_name_, measured_error_;
    std::vector<double> measured_plane_;
    float measured_incidence_ = -1.0f;
    char measured_path_[1024] = "";
};

}  // namespace fxview::ui

#include "app/brdf_evaluation.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "app/brdf_check.hpp"
#include "core/error.hpp"
#include "effect/parameter_values.hpp"
#include "gl/render_target.hpp"
#include "scene/scene.hpp"

namespace fxview::app {

BrdfEvaluation::BrdfEvaluation(const EffectOptions& effect, const std::string& backend) {
    context::ContextOptions options;
    options.backend = context::parse_backend(backend);
    options.window_width = kGridWidth;
    options.window_height = kGridHeight;
    options.window_visible = false;
    context_ = context::create_context(options);
    EffectOptions without_technique = effect;
    without_technique.technique.clear();
    session_ = open_effect_session(without_technique);
    if (!has_brdf_grid(*session_)) throw UsageError(effect.path + " has no BrdfGrid technique: BRDF checks and plots work on .brdf files");
    if (!effect.technique.empty()) follow_technique(*session_, effect.technique);
}

BrdfEvaluation::~BrdfEvaluation() {
    session_.reset();  // GL objects go before their context
}

namespace {

image::FloatImage render_grid(render::EffectSession& session, int width, int height, const std::string& mode, bool swapped, double incidence,
                              double phi_d = 90.0) {
    const std::string technique = session.technique();
    const effect::ParameterValues saved = session.values();
    struct Restore {
        render::EffectSession& session;
        const std::string& technique;
        const effect::ParameterValues& values;
        ~Restore() {
            session.values() = values;
            session.select_technique(technique);
        }
    } restore{session, technique, saved};
    session.select_technique("BrdfGrid");
    effect::ParameterValues& values = session.values();
    effect::set_value_from_text(session.effect(), values, "FxGridMode=" + mode);
    effect::set_value_from_text(session.effect(), values, std::string("FxSwapArguments=") + (swapped ? "true" : "false"));
    effect::set_value_from_text(session.effect(), values, "FxIncidence=" + std::to_string(incidence));
    effect::set_value_from_text(session.effect(), values, "FxPhiD=" + std::to_string(phi_d));
    gl::RenderTarget target({width, height, 1, 0});
    session.render(scene::Scene{}, target);
    return target.read_color(0);
}

}  // namespace

bool has_brdf_grid(const render::EffectSession& session) {
    for (const auto& technique : session.effect().techniques)
        if (technique.name == "BrdfGrid") return true;
    return false;
}

void follow_technique(render::EffectSession& session, const std::string& technique) {
    const effect::Parameter* model = session.effect().find_parameter("BrdfModel");
    if (!model || std::find(model->ui.items.begin(), model->ui.items.end(), technique) == model->ui.items.end()) return;
    effect::set_value_from_text(session.effect(), session.values(), "BrdfModel=" + technique);
}

image::FloatImage evaluate_brdf_grid(render::EffectSession& session, bool swapped) {
    return render_grid(session, kGridWidth, kGridHeight, "0", swapped, 0.0);
}

image::FloatImage evaluate_brdf_plane(render::EffectSession& session, double incidence_degrees, int samples, bool swapped) {
    return render_grid(session, samples, 1, "1", swapped, incidence_degrees);
}

image::FloatImage evaluate_brdf_slice(render::EffectSession& session, double phi_d_degrees, int width, int height) {
    return render_grid(session, width, height, "2", false, 0.0, phi_d_degrees);
}

image::FloatImage evaluate_brdf_hemisphere(render::EffectSession& session, double incidence_degrees, int width, int height) {
    return render_grid(session, width, height, "3", false, incidence_degrees);
}

image::FloatImage render_lit_sphere(render::EffectSession& session, int size) {
    gl::RenderTarget target({size, size, 1, 4});
    session.render(scene::Scene{}, target);
    return target.read_color(0);
}

std::vector<std::array<double, 3>> measured_plane(const fit::MerlBrdf& merl, double incidence_degrees, int samples) {
    const double ti = incidence_degrees * std::numbers::pi / 180.0;
    const glm::dvec3 l(std::sin(ti), 0.0, std::cos(ti));
    std::vector<std::array<double, 3>> values;
    for (int k = 0; k < samples; ++k) {
        const double to = (-90.0 + 180.0 * (k + 0.5) / samples) * std::numbers::pi / 180.0;
        values.push_back(merl.lookup(l, glm::dvec3(std::sin(to), 0.0, std::cos(to))));
    }
    return values;
}

}  // namespace fxview::app

#include "app/brdf_evaluation.hpp"

#include "app/brdf_check.hpp"
#include "core/error.hpp"
#include "effect/parameter_values.hpp"
#include "gl/render_target.hpp"
#include "scene/scene.hpp"

namespace fxview::app {

BrdfEvaluation::BrdfEvaluation(const EffectOptions& effect, const std::string& backend) : path_(effect.path) {
    context::ContextOptions options;
    options.backend = context::parse_backend(backend);
    options.window_width = kGridWidth;
    options.window_height = kGridHeight;
    options.window_visible = false;
    context_ = context::create_context(options);
    EffectOptions without_technique = effect;
    without_technique.technique.clear();
    session_ = open_effect_session(without_technique);
    try {
        session_->select_technique("BrdfGrid");
    } catch (const UsageError&) {
        throw UsageError(effect.path + " has no BrdfGrid technique: BRDF checks and plots work on .brdf files");
    }
}

BrdfEvaluation::~BrdfEvaluation() {
    session_.reset();  // GL objects go before their context
}

image::FloatImage BrdfEvaluation::render(int width, int height, const std::string& mode, bool swapped, double incidence) {
    effect::ParameterValues& values = session_->values();
    effect::set_value_from_text(session_->effect(), values, "FxGridMode=" + mode);
    effect::set_value_from_text(session_->effect(), values, std::string("FxSwapArguments=") + (swapped ? "true" : "false"));
    effect::set_value_from_text(session_->effect(), values, "FxIncidence=" + std::to_string(incidence));
    gl::RenderTarget target({width, height, 1, 0});
    session_->render(scene::Scene{}, target);
    return target.read_color(0);
}

image::FloatImage BrdfEvaluation::grid(bool swapped) { return render(kGridWidth, kGridHeight, "0", swapped, 0.0); }

image::FloatImage BrdfEvaluation::plane(double incidence_degrees, int samples, bool swapped) {
    return render(samples, 1, "1", swapped, incidence_degrees);
}

}  // namespace fxview::app

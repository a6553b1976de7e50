#include "app/brdf_evaluation.hpp"
#include <glad/gl.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
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
    options.window_width = kGridTilesX * kSampleSide;
    options.window_height = kGridRows * kSampleSide;
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

// The BrdfGrid technique rendered into `target` with `values` and `settings` (NAME=VALUE of its grid
// parameters); the session's technique and values are put back afterwards.
void draw_grid(render::EffectSession& session, const effect::ParameterValues& values, const std::vector<std::string>& settings,
               const gl::RenderTarget& target) {
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
    session.values() = values;
    for (const std::string& setting : settings) effect::set_value_from_text(session.effect(), session.values(), setting);
    session.render(scene::Scene{}, target);
}

image::FloatImage render_grid(render::EffectSession& session, int width, int height, const std::vector<std::string>& settings) {
    gl::RenderTarget target({width, height, 1, 0});
    draw_grid(session, session.values(), settings, target);
    return target.read_color(0);
}

std::vector<std::string> grid_settings(int mode, bool swapped, double incidence, double phi_i, double phi_d = 90.0) {
    // %.17g: the directions must be the ones the CPU computes (std::to_string keeps 6 decimals).
    const auto number = [](double x) {
        char text[32];
        std::snprintf(text, sizeof text, "%.17g", x);
        return std::string(text);
    };
    return {"FxGridMode=" + std::to_string(mode), std::string("FxSwapArguments=") + (swapped ? "true" : "false"),
            "FxIncidence=" + number(incidence), "FxPhiI=" + number(phi_i), "FxPhiD=" + number(phi_d)};
}

std::vector<std::string> sample_settings(const SampleRequest& request) {
    const brdf::SampleSet& set = request.set;
    std::vector<std::string> settings = grid_settings(4, request.swapped, 0.0, set.phi_i_degrees);
    settings.push_back(std::string("FxSampleOutput=") + (request.directions ? "1" : "0"));
    char shift[96];
    std::snprintf(shift, sizeof shift, "FxSampleShift=%.17g,%.17g", set.shift.x, set.shift.y);
    settings.push_back(shift);
    settings.push_back("FxSampleStrategy=" + std::to_string(static_cast<int>(set.strategy)));
    settings.push_back("FxSampleSide=" + std::to_string(set.side));
    char alpha[48];
    std::snprintf(alpha, sizeof alpha, "FxSampleAlpha=%.17g", set.alpha);
    settings.push_back(alpha);
    return settings;
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

image::FloatImage evaluate_brdf_samples(render::EffectSession& session, const SampleRequest& request) {
    return render_grid(session, kGridTilesX * request.set.side, kGridRows * request.set.side, sample_settings(request));
}

bool has_file_sampler(const render::EffectSession& session) { return session.effect().find_parameter("FxFileSampler") != nullptr; }

void draw_brdf_samples_rows(render::EffectSession& session, const effect::ParameterValues& values, const SampleRequest& request,
                            const gl::RenderTarget& target, int first_row, int rows) {
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, first_row, target.width(), rows);
    draw_grid(session, values, sample_settings(request), target);
    glDisable(GL_SCISSOR_TEST);
}

SampleRenderer gpu_sample_renderer(render::EffectSession& session) {
    return [&session](const SampleRequest& request) { return evaluate_brdf_samples(session, request); };
}

SampleRenderer measured_sample_renderer(const fit::MerlBrdf& merl) {
    return [&merl](const SampleRequest& request) {
        const brdf::SampleSet& set = request.set;
        const bool swapped = request.swapped;  // measured data have no sampler of their own: never asked for directions
        image::FloatImage image(kGridTilesX * set.side, kGridRows * set.side, 4);
        for (int tile = 0; tile < kGridIncidences; ++tile) {
            const glm::dvec3 l = brdf::incident_direction(grid_incidence_degrees(tile), set.phi_i_degrees);
            for (int b = 0; b < set.side; ++b)
                for (int a = 0; a < set.side; ++a) {
                    const glm::dvec3 v = brdf::sampled_direction(set, l, a, b);
                    float* p = image.pixel((tile % kGridTilesX) * set.side + a, image.height - 1 - ((tile / kGridTilesX) * set.side + b));
                    if (v.z <= 0) continue;  // the image starts at 0: alpha 0, below the surface
                    const glm::dvec3 unit = glm::normalize(v);
                    const std::array<double, 3> f = swapped ? merl.lookup(unit, l) : merl.lookup(l, unit);
                    for (int c = 0; c < 3; ++c) p[c] = static_cast<float>(f[static_cast<size_t>(c)]);
                    p[3] = 1.0f;
                }
        }
        return image;
    };
}

image::FloatImage evaluate_brdf_plane(render::EffectSession& session, double incidence_degrees, int samples, bool swapped, double phi_i_degrees) {
    return render_grid(session, samples, 1, grid_settings(1, swapped, incidence_degrees, phi_i_degrees));
}

image::FloatImage evaluate_brdf_slice(render::EffectSession& session, double phi_d_degrees, int width, int height) {
    return render_grid(session, width, height, grid_settings(2, false, 0.0, 0.0, phi_d_degrees));
}

image::FloatImage evaluate_brdf_hemisphere(render::EffectSession& session, double incidence_degrees, int width, int height, double phi_i_degrees) {
    return render_grid(session, width, height, grid_settings(3, false, incidence_degrees, phi_i_degrees));
}

image::FloatImage render_lit_sphere(render::EffectSession& session, int size) {
    gl::RenderTarget target({size, size, 1, 4});
    session.render(scene::Scene{}, target);
    return target.read_color(0);
}

std::vector<std::array<double, 3>> measured_plane(const fit::MerlBrdf& merl, double incidence_degrees, int samples, double phi_i_degrees) {
    const glm::dvec3 l = brdf::incident_direction(incidence_degrees, phi_i_degrees);
    const double p = phi_i_degrees * std::numbers::pi / 180.0;
    std::vector<std::array<double, 3>> values;
    for (int k = 0; k < samples; ++k) {
        const double to = (-90.0 + 180.0 * (k + 0.5) / samples) * std::numbers::pi / 180.0;
        values.push_back(merl.lookup(l, glm::dvec3(std::sin(to) * std::cos(p), std::sin(to) * std::sin(p), std::cos(to))));
    }
    return values;
}

}  // namespace fxview::app

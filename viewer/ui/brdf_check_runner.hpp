// brdf-check in the viewer (the BRDF tab's Check button, the script verb brdf-check): the check's
// renders (app/brdf_check.hpp's job) drawn in bands of rows across UI frames, a few tens of
// milliseconds a frame, so that the UI never waits for a whole check (the largest renders hold
// 2304 x 1280 evaluations). The parameter values are those of the moment it started.
#pragma once
#include <memory>
#include <optional>

#include "app/brdf_check.hpp"
#include "effect/parameter_values.hpp"
#include "gl/render_target.hpp"
#include "render/effect_session.hpp"

namespace fxview::ui {

class BrdfCheckRunner {
public:
    void start(const render::EffectSession& session);
    // Draws for about `budget_seconds` (at least one band); true when the check completed in this call.
    bool step(render::EffectSession& session, double budget_seconds);
    bool running() const { return job_.has_value(); }
    double progress() const { return job_ ? job_->progress() : 1.0; }
    const effect::ParameterValues& values() const { return values_; }
    // The completed check (after step() returned true).
    const std::optional<app::BrdfCheck>& result() const { return result_; }
    void cancel() { job_.reset(), target_.reset(); }

private:
    std::optional<app::BrdfCheckJob> job_;
    std::optional<app::BrdfCheck> result_;
    effect::ParameterValues values_;
    std::unique_ptr<gl::RenderTarget> target_;  // the current request's picture, drawn band by band
    int next_row_ = 0, band_rows_ = 16;
};

}  // namespace fxview::ui

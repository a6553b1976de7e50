#include "ui/brdf_check_runner.hpp"

#include <glad/gl.h>

#include <algorithm>
#include <chrono>

#include "app/brdf_evaluation.hpp"

namespace fxview::ui {

void BrdfCheckRunner::start(const render::EffectSession& session) {
    values_ = session.values();
    app::BrdfCheckOptions options;
    options.file_sampler = app::has_file_sampler(session);
    job_.emplace(options);
    result_.reset();
    target_.reset();
    next_row_ = 0;
}

bool BrdfCheckRunner::step(render::EffectSession& session, double budget_seconds) {
    if (!job_) return false;
    const auto start = std::chrono::steady_clock::now();
    const auto elapsed = [&start] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    do {
        const std::optional<app::SampleRequest> request = job_->next();
        if (!request) {
            result_ = job_->result();
            job_.reset();
            target_.reset();
            return true;
        }
        const int width = app::kGridTilesX * request->set.side, height = app::kGridRows * request->set.side;
        if (!target_ || target_->width() != width || target_->height() != height)
            target_ = std::make_unique<gl::RenderTarget>(gl::RenderTargetDesc{width, height, 1, 0});
        const int rows = std::min(band_rows_, height - next_row_);
        const auto band_start = std::chrono::steady_clock::now();
        app::draw_brdf_samples_rows(session, values_, *request, *target_, next_row_, rows);
        glFinish();  // the band's cost sizes the next one
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - band_start).count();
        // Bands of about a third of the budget: rows scale with the measured time, by at most 2x.
        band_rows_ = std::clamp(static_cast<int>(band_rows_ * std::clamp(budget_seconds / 3.0 / std::max(seconds, 1e-6), 0.5, 2.0)), 4, 4096);
        next_row_ += rows;
        if (next_row_ >= height) {
            job_->deliver(target_->read_color(0));
            next_row_ = 0;
        }
    } while (elapsed() < budget_seconds);
    return false;
}

}  // namespace fxview::ui

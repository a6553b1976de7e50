#include "ui/render_schedule.hpp"

#include <algorithm>
#include <cmath>

namespace fxview::ui {
namespace {

// The first piece's covered pixels, before anything is measured: small enough for any shader.
constexpr double kProbePixels = 256;

}  // namespace

void RenderSchedule::update(std::uint64_t key, bool animated, bool progressive) {
    progressive_ = progressive;
    if (key != key_ || (animated && !dirty_)) {
        key_ = key;
        restart();
    }
}

double RenderSchedule::covered(int row, double fraction_of_width) const {
    const double full = static_cast<size_t>(row) < coverage_.size() ? coverage_[static_cast<size_t>(row)] : width_;
    return full * fraction_of_width;
}

RenderSchedule::Work RenderSchedule::next(int width, int height) {
    if (width != width_ || height != height_) {
        width_ = width;
        height_ = height;
        restart();
    }
    if (!dirty_ || height <= 0 || width <= 0) return {};
    if (!progressive_) return {0, 0, width, height};
    const double budget_pixels = per_pixel_ > 0 ? std::max(0.0, (budget_ - fixed_) / per_pixel_) : kProbePixels;
    if (next_column_ == 0) {
        // Whole rows while they fit the budget (at least one).
        double pixels = 0;
        int rows = 0;
        while (next_row_ + rows < height) {
            const double more = covered(next_row_ + rows);
            if (rows > 0 && pixels + more > budget_pixels) break;
            pixels += more;
            ++rows;
            if (pixels > budget_pixels) break;
        }
        // A first row that alone is over budget (and worth splitting) is drawn in column tiles instead.
        if (rows == 1 && pixels > 2 * budget_pixels && width >= 32) next_column_ = 0;
        else return {0, next_row_, width, rows};
    }
    // Column tiles of the row: the covered pixels are taken as spread evenly along it.
    const double row_pixels = std::max(covered(next_row_), 1.0);
    const int columns = std::clamp(static_cast<int>(width * budget_pixels / row_pixels), 16, width - next_column_);
    return {next_column_, next_row_, columns, 1};
}

void RenderSchedule::done(const Work& work, double seconds) {
    if (work.height <= 0) return;
    double pixels = 0;
    for (int r = work.y; r < work.y + work.height; ++r) pixels += covered(r, static_cast<double>(work.width) / std::max(width_, 1));
    // The model follows the measurements, rising at once and falling by halves (a cheap piece must
    // not make the next one too large).
    if (pixels < 1) {
        fixed_ = 0.5 * fixed_ + 0.5 * seconds;
    } else {
        const double measured = std::max(seconds - fixed_, 0.0) / pixels;
        per_pixel_ = per_pixel_ > 0 ? std::max(measured, 0.5 * (per_pixel_ + measured)) : measured;
    }
    picture_seconds_ += seconds;
    if (work.width < width_) {  // a column tile
        next_column_ = work.x + work.width;
        if (next_column_ < width_) return;
        next_column_ = 0;
    }
    next_row_ = work.y + work.height;
    if (next_row_ >= height_) {
        dirty_ = false;
        next_row_ = height_;
        last_picture_seconds_ = picture_seconds_;
        ++pictures_;
    }
}

}  // namespace fxview::ui

#include "ui/render_schedule.hpp"

#include <algorithm>
#include <cmath>

namespace fxview::ui {
namespace {

// The first piece's covered pixels, before anything is measured: small enough for any shader.
constexpr double kProbePixels = 64;
constexpr double kMaxPieceSeconds = 0.06;

// How an allowance follows a measured piece: up to half again what the piece used when it kept to
// the budget (never below what it allowed), scaled down by its overrun when it did not. Growth is
// from what was used, not from the allowance: pieces kept small by something else (a model that has
// not measured a pixel yet) are no evidence that larger ones would keep to the budget.
double follow(double allowance, double used, double seconds, double budget, double floor) {
    const double factor = std::min(1.5, budget / std::max(seconds, 1e-9));
    const double next = factor >= 1.0 ? std::max(allowance, used * factor) : used * factor;
    return std::max(floor, next);
}

}  // namespace

void RenderSchedule::update(std::uint64_t key, bool animated, bool progressive) {
    progressive_ = progressive;
    if (key != key_ || (animated && !dirty_)) {
        key_ = key;
        restart();
    }
}

double RenderSchedule::covered(int row) const {
    return static_cast<size_t>(row) < coverage_.size() ? coverage_[static_cast<size_t>(row)] : width_;
}

double RenderSchedule::covered_rows(int first, int end) const {
    double pixels = 0;
    for (int row = first; row < end; ++row) pixels += covered(row);
    return pixels;
}

// Bands are counted from the picture's bottom, where GL's rows start: all but the top one are whole
// blocks.
int RenderSchedule::band_end(int row) const {
    const int rest = (height_ - row) % kBlock;
    return std::min(height_, row + (rest ? rest : kBlock));
}

RenderSchedule::Work RenderSchedule::next(int width, int height) {
    if (width != width_ || height != height_) {
        width_ = width;
        height_ = height;
        restart();
    }
    if (!dirty_ || height <= 0 || width <= 0) return {};
    if (!progressive_) return {0, 0, width, height};
    // Small pieces cost more than their share: each pays a draw's fixed cost, and a software
    // rasteriser shades 4x4 blocks in 64x64 bins, one thread a bin, so a one-row strip of a few
    // dozen pixels wastes most of its work (MultiLayer with 16 layers: 16 s whole, 142 s in 14 ms
    // one-row pieces). Pieces are therefore bands of whole blocks, and the budget grows with the picture: 4x the fixed cost, and 1/150 of the
    // picture's predicted cost, up to 100 ms a piece, which keeps UI frames under a quarter second.
    double covered_total = 0;
    for (int row = 0; row < height; ++row) covered_total += covered(row);
    const double predicted_picture = per_pixel_ * covered_total;
    budget_used_ = std::clamp(std::max(4.0 * fixed_, predicted_picture / 150.0), budget_, std::max(budget_, kMaxPieceSeconds));
    double budget_pixels = per_pixel_ > 0 ? std::max(0.0, (budget_used_ - fixed_) / per_pixel_) : kProbePixels;
    // Bounded by what was measured, not by the model alone: the model proposes, the allowances
    // (grown by half again per piece that kept to the budget, scaled down by an overrun) dispose. The
    // model can be wrong (rim pixels cheaper than the middle, a fixed cost misjudged, which drove the
    // per-pixel estimate towards 0 and once made one piece of the rest of a 27-second picture).
    budget_pixels = std::min(budget_pixels, allowed_pixels_);
    if (next_column_ == 0) {
        // Whole bands of rows while they fit the budget (at least one), and never more rows than
        // allowed: rows the coverage estimate calls empty may not be (a thin part it missed).
        double pixels = 0;
        int end = next_row_;
        while (end < height) {
            const int band = band_end(end);
            if (end > next_row_ && band - next_row_ > allowed_rows_) break;
            const double more = covered_rows(end, band);
            if (end > next_row_ && pixels + more > budget_pixels) break;
            pixels += more;
            end = band;
            if (pixels > budget_pixels) break;
        }
        // A first band that alone is over budget (and worth splitting) is drawn in column tiles instead.
        if (!(end == band_end(next_row_) && pixels > 2 * budget_pixels && width >= 32)) return {0, next_row_, width, end - next_row_};
    }
    // Column tiles of the band: where along it the covered pixels lie is not known (a sphere's are
    // all in the middle), so a tile is sized as if all its pixels were covered. Taking them as spread
    // evenly made tiles over the object 2-3 times too costly (UI frames of 300 ms). Widths are whole
    // blocks (kBlock), so tiles start on block edges too.
    const int rows = band_end(next_row_) - next_row_;
    double wanted = std::clamp(budget_pixels / rows, double{kBlock}, static_cast<double>(width));
    wanted = std::min(wanted, std::max(double{kBlock}, allowed_columns_));
    const int columns = std::min(static_cast<int>(wanted) / kBlock * kBlock, width - next_column_);
    return {next_column_, next_row_, columns, rows};
}

void RenderSchedule::done(const Work& work, double seconds) {
    if (work.height <= 0) return;
    const bool tile = work.width < width_;
    double pixels = 0;  // a tile: as next() sized it, every pixel covered
    for (int r = work.y; r < work.y + work.height; ++r) pixels += tile ? std::min<double>(work.width, covered(r)) : covered(r);
    // The model follows the measurements, rising at once and falling by halves (a cheap piece must
    // not make the next one too large).
    // A piece that kept to the budget lets the next one hold at least a block more: growth by half
    // again alone rounds back down to whole blocks from small sizes (4 columns stayed 4 for good).
    const double more = seconds <= budget_used_ ? kBlock : 0.0;
    if (!tile) allowed_rows_ = std::max(follow(allowed_rows_, work.height, seconds, budget_used_, 1.0), work.height + more);
    else allowed_columns_ = std::max(follow(allowed_columns_, work.width, seconds, budget_used_, kBlock), work.width + more);
    if (pixels >= 1) allowed_pixels_ = std::max(follow(allowed_pixels_, pixels, seconds, budget_used_, 1.0), pixels + more * work.height);
    if (pixels < 1) {
        // An "empty" piece that took longer than any piece may was not empty (the coverage estimate
        // missed something): it must not teach the model a fixed cost.
        if (seconds <= 2.0 * kMaxPieceSeconds) fixed_ = 0.5 * fixed_ + 0.5 * seconds;
        // Nor may the estimate be trusted further: every pixel counts as covered from now on (until
        // the viewer measures the coverage again), so that the pieces shrink to tiles.
        if (seconds > 2.0 * budget_used_) coverage_.clear();
    } else {
        const double measured = std::max(seconds - fixed_, 0.0) / pixels;
        // A tile over the background is cheap without the object being so: tiles raise the estimate
        // at once but lower it only slowly (1 % a tile), so that the tiles a row starts with cannot make
        // the ones over the object much too wide (8 background tiles: 8 % under; 2 % a tile let a disc's
        // tiles reach 105 ms, test_ui_logic), while one slow tile (the machine busy for a moment) does
        // not keep every later piece small for good.
        if (tile) per_pixel_ = std::max(measured, 0.99 * per_pixel_ + 0.01 * measured);
        else per_pixel_ = per_pixel_ > 0 ? std::max(measured, 0.5 * (per_pixel_ + measured)) : measured;
    }
    picture_seconds_ += seconds;
    if (tile) {
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

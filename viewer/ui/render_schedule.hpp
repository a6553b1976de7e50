// When, and how much of, the render view is drawn (issue #13: a viewer that stays responsive on any
// machine). Nothing while the picture is current; the whole picture when it is quick; pieces across
// UI frames when it is slow (a progressive render: the new picture sweeps down over the old one, and
// the UI keeps its frame rate and its input). The pieces are sized from a cost model: a fixed cost
// per piece plus a cost per pixel the objects cover (where the fragment shader runs; background
// pixels are only cleared), measured as pieces complete; a band of rows too costly for one frame is
// split into column tiles.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

namespace fxview::ui {

// FNV-1a over the bytes of what is added: a picture's state key.
class StateHash {
public:
    StateHash& add_bytes(const void* data, size_t size) {
        const auto* bytes = static_cast<const unsigned char*>(data);
        for (size_t i = 0; i < size; ++i) hash_ = (hash_ ^ bytes[i]) * 1099511628211ull;
        return *this;
    }
    template <typename T>
        requires std::is_arithmetic_v<T>
    StateHash& add(T value) {
        return add_bytes(&value, sizeof value);
    }
    StateHash& add(const std::string& text) { return add(text.size()).add_bytes(text.data(), text.size()); }
    std::uint64_t value() const { return hash_; }

private:
    std::uint64_t hash_ = 14695981039346656037ull;
};

class RenderSchedule {
public:
    // Pieces are made of blocks of kBlock x kBlock pixels, aligned to the picture's bottom left (GL's
    // origin): a rasteriser shades whole blocks (llvmpipe 4x4), so a piece of one row pays for four.
    static constexpr int kBlock = 4;

    explicit RenderSchedule(double budget_seconds = 0.014) : budget_(budget_seconds) {}

    // Called once per UI frame with a hash of everything the picture depends on; a different hash
    // starts a new picture, and so does an animated effect once the last picture is complete.
    // `progressive` false: pieces are not allowed (multi-pass effects whose later passes read
    // neighbouring pixels of earlier ones).
    void update(std::uint64_t key, bool animated, bool progressive);
    void restart() { dirty_ = true, next_row_ = 0, next_column_ = 0, picture_seconds_ = 0; }

    // Pixels the objects cover in each row of the picture (top row first), e.g. from a cheap
    // coverage render; empty: every pixel counts as covered.
    void set_coverage(std::vector<double> covered_per_row) { coverage_ = std::move(covered_per_row); }

    struct Work {
        int x = 0, y = 0, width = 0, height = 0;  // y from the top; height 0: nothing to draw
    };
    // What to draw this UI frame into a picture of this size.
    Work next(int width, int height);
    // The work took `seconds` (measured after glFinish): updates the cost model.
    void done(const Work& work, double seconds);

    bool pending() const { return dirty_; }  // the picture shown is not the current one (yet)
    bool refining() const { return dirty_ && (next_row_ > 0 || next_column_ > 0); }
    double progress() const { return height_ > 0 ? static_cast<double>(next_row_) / height_ : 1.0; }
    double last_picture_seconds() const { return last_picture_seconds_; }  // the last complete picture's render time
    int pictures() const { return pictures_; }                            // complete pictures drawn so far

private:
    double covered(int row) const;
    double covered_rows(int first, int end) const;
    int band_end(int row) const;  // the row after the band of whole blocks that `row` starts
    double predicted(double covered_pixels) const { return fixed_ + per_pixel_ * covered_pixels; }

    double budget_;
    std::uint64_t key_ = 0;
    bool dirty_ = true, progressive_ = true;
    int width_ = 0, height_ = 0, next_row_ = 0, next_column_ = 0, pictures_ = 0;
    std::vector<double> coverage_;
    double fixed_ = 0, per_pixel_ = 0;  // the cost model; per_pixel_ 0: not measured yet
    // What a piece may hold, from the measured pieces before it (render_schedule.cpp): covered
    // pixels, whole rows, columns of a tile; and the budget the current piece was sized for.
    double allowed_pixels_ = 64, allowed_rows_ = 1, allowed_columns_ = 16, budget_used_ = 0;
    double picture_seconds_ = 0, last_picture_seconds_ = 0;
};

}  // namespace fxview::ui

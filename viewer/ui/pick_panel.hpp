// The Pick tab and what it draws on the render view: a picked pixel's values (float RGBA, the 8-bit
// value displayed, packed integer, as a normal, chromaticity) and a magnifier of its neighbourhood,
// both taken from the same snapshot of the picture, so they always show the same pixel at the same
// moment; a marker on the render view where it was picked; and a readout of the pixel under the
// cursor while hovering.
#pragma once
#include <imgui.h>

#include <array>
#include <cstdint>
#include <vector>

#include "gl/render_target.hpp"
#include "image/image.hpp"
#include "image/pixel_info.hpp"

namespace fxview::ui {

// xy of a linear sRGB colour (IEC 61966-2-1 primaries, D65).
std::array<double, 2> chromaticity_of(const std::array<float, 4>& rgb);

class PickPanel {
public:
    static constexpr int kRadius = 7;  // the magnifier shows (2 kRadius + 1)² pixels

    // Takes the snapshot of pixel (x, y) (origin top left) of `picture`; `key` identifies the
    // picture's state, to say later when the view no longer shows it.
    // False (and nothing changes) for a pixel off the picture.
    bool pick(const image::FloatImage& picture, int x, int y, bool srgb_display, std::uint64_t key);
    bool valid() const { return valid_; }
    const image::PixelInfo& info() const { return info_; }
    const std::array<double, 2>& chromaticity() const { return xy_; }

    // The tab's contents; `current_key` the state of the picture shown now.
    void draw(std::uint64_t current_key) const;
    // A cross on the render view at the picked pixel (the view shows `width` x `height` pixels in
    // the rectangle at `origin` of size `shown`).
    void draw_marker(ImDrawList* list, ImVec2 origin, ImVec2 shown, int width, int height) const;
    // While the cursor is over the render view: the float value under it in a line along the view's
    // bottom edge, read from the target's resolved colour texture.
    static void draw_hover_readout(const gl::RenderTarget& target, ImVec2 origin, ImVec2 shown);

private:
    bool valid_ = false;
    bool srgb_ = true;
    std::uint64_t key_ = 0;
    image::PixelInfo info_;
    std::array<double, 2> xy_{};
    std::vector<std::array<float, 4>> neighbourhood_;  // row by row from the top, off-picture pixels black
};

}  // namespace fxview::ui

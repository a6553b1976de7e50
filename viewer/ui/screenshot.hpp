// Screenshots: the whole window as the user sees it, the render view's picture, and a picture
// rendered at any size as the view shows it (uncovered pixels over the view's backdrop, or with
// alpha for those who want a transparent background). Parent folders are created.
#pragma once
#include <string>

#include "image/display_transform.hpp"
#include "image/image.hpp"

namespace fxview::ui {

// The window's back buffer (UI included) as a PNG of display values.
void write_window_png(const std::string& path, int width, int height);

// A linear picture as the view shows it: composited over the view's backdrop unless `transparent`.
void write_picture(const std::string& path, image::FloatImage picture, bool srgb_display, bool transparent, const image::DisplaySettings& display);

}  // namespace fxview::ui

// Screenshots: the whole window as the user sees it, the render view's picture, and a picture
// rendered at any size as the view shows it (uncovered pixels over the view's backdrop, or with
// alpha for those who want a transparent background). Parent folders are created.
#pragma once
#include <functional>
#include <memory>
#include <string>

#include "gl/render_target.hpp"
#include "ui/render_schedule.hpp"

#include "image/display_transform.hpp"
#include "image/image.hpp"

namespace fxview::ui {

// The window's back buffer (UI included) as a PNG of display values.
void write_window_png(const std::string& path, int width, int height);

// A linear picture as the view shows it: composited over the view's backdrop unless `transparent`.
void write_picture(const std::string& path, image::FloatImage picture, bool srgb_display, bool transparent, const image::DisplaySettings& display);

// A screenshot at a size of its own (larger than the view, say), rendered in pieces across UI
// frames like the view itself (render_schedule.hpp), so that the UI never blocks on it. The view's
// own screenshots need none: its picture is written once it is complete.
class ScreenshotJob {
public:
    ScreenshotJob(std::string path, int width, int height, int samples, bool transparent);
    // Draws the next piece: `render` draws the scene into the target (a scissor is set around the
    // piece); `progressive` false draws it whole. When the last piece is done the file is written and
    // true returned.
    bool step(const std::function<void(const gl::RenderTarget&)>& render, bool progressive, bool srgb_display,
              const image::DisplaySettings& display);
    double progress() const { return schedule_.progress(); }
    const std::string& path() const { return path_; }

private:
    std::string path_;
    bool transparent_;
    std::unique_ptr<gl::RenderTarget> target_;
    RenderSchedule schedule_;
};

}  // namespace fxview::ui

#include "ui/screenshot.hpp"

#include <glad/gl.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <vector>

#include "image/image_file.hpp"
#include "ui/display_pass.hpp"

namespace fxview::ui {
namespace {

void create_parent(const std::string& path) {
    const auto parent = std::filesystem::path(path).parent_path();
    if (!parent.empty()) std::filesystem::create_directories(parent);
}

}  // namespace

void write_window_png(const std::string& path, int width, int height) {
    std::vector<unsigned char> bytes(static_cast<size_t>(width) * height * 4);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
    image::FloatImage shot(width, height, 4);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < 4; ++c)  // the window already holds display values: store them unchanged
                shot.pixel(x, height - 1 - y)[c] = c == 3 ? 1.0f : bytes[(static_cast<size_t>(y) * width + x) * 4 + c] / 255.0f;
    create_parent(path);
    image::write_image(path, shot, image::Encoding::Linear);
}

void write_picture(const std::string& path, image::FloatImage picture, bool srgb_display, bool transparent, const image::DisplaySettings& display) {
    if (!transparent)
        for (size_t i = 0; i + 3 < picture.data.size(); i += 4) {
            const float alpha = std::clamp(picture.data[i + 3], 0.0f, 1.0f);
            for (size_t c = 0; c < 3; ++c) picture.data[i + c] = kDisplayBackdrop + (picture.data[i + c] - kDisplayBackdrop) * alpha;
            picture.data[i + 3] = 1.0f;
        }
    // PNG through the window's display transform; EXR and PFM keep scene-linear values.
    if (std::filesystem::path(path).extension() == ".png") image::apply_display_transform(picture, display);
    create_parent(path);
    image::write_image(path, picture, srgb_display ? image::Encoding::Srgb : image::Encoding::Linear);
}

ScreenshotJob::ScreenshotJob(std::string path, int width, int height, int samples, bool transparent)
    : path_(std::move(path)), transparent_(transparent), target_(std::make_unique<gl::RenderTarget>(gl::RenderTargetDesc{width, height, 1, samples})) {
    schedule_.update(1, false, true);
}

bool ScreenshotJob::step(const std::function<void(const gl::RenderTarget&)>& render, bool progressive, bool srgb_display,
                         const image::DisplaySettings& display) {
    const int width = target_->width(), height = target_->height();
    schedule_.update(1, false, progressive);
    const RenderSchedule::Work work = schedule_.next(width, height);
    if (work.height > 0) {
        const auto start = std::chrono::steady_clock::now();
        glEnable(GL_SCISSOR_TEST);
        glScissor(work.x, height - work.y - work.height, work.width, work.height);  // y from the top; GL's from the bottom
        render(*target_);
        glDisable(GL_SCISSOR_TEST);
        glFinish();
        schedule_.done(work, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    if (schedule_.pending()) return false;
    write_picture(path_, target_->read_color(0), srgb_display, transparent_, display);
    return true;
}

}  // namespace fxview::ui

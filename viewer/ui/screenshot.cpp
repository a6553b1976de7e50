#include "ui/screenshot.hpp"

#include <glad/gl.h>

#include <algorithm>
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

}  // namespace fxview::ui

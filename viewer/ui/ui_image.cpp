#include "ui/ui_image.hpp"

#include <imgui.h>

#include <cstdint>
#include <vector>

#include "image/color_encoding.hpp"

namespace fxview::ui {

UiImage upload_ui_image(const image::FloatImage& image, bool nearest) {
    std::vector<std::uint8_t> bytes(static_cast<size_t>(image.width) * image.height * 4);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const float* p = image.pixel(x, y);
            std::uint8_t* out = &bytes[(static_cast<size_t>(y) * image.width + x) * 4];
            for (int c = 0; c < 4; ++c) {
                const float v = c < image.channels ? p[c] : 1.0f;
                out[c] = image::to_8bit(v, c == 3 ? image::Encoding::Linear : image::Encoding::Srgb);
            }
        }
    UiImage ui;
    ui.texture = gl::create_texture(GL_TEXTURE_2D);
    glTextureStorage2D(ui.texture.get(), 1, GL_RGBA8, image.width, image.height);
    glTextureSubImage2D(ui.texture.get(), 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
    const GLint filter = nearest ? GL_NEAREST : GL_LINEAR;
    glTextureParameteri(ui.texture.get(), GL_TEXTURE_MIN_FILTER, filter);
    glTextureParameteri(ui.texture.get(), GL_TEXTURE_MAG_FILTER, filter);
    ui.width = image.width;
    ui.height = image.height;
    return ui;
}

void UiImage::draw() const {
    if (empty()) return;
    const float width = ImGui::GetContentRegionAvail().x;
    ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(texture.get())), ImVec2(width, width * static_cast<float>(height) / static_cast<float>(width > 0 ? this->width : 1)));
}

}  // namespace fxview::ui

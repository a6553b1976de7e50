// A float image (linear RGB) shown in the UI: uploaded as 8-bit sRGB, the encoding the UI draws.
#pragma once
#include "gl/objects.hpp"
#include "image/image.hpp"

namespace fxview::ui {

struct UiImage {
    gl::Texture texture;
    int width = 0, height = 0;

    bool empty() const { return texture.get() == 0; }
    // Drawn across the available width, keeping the aspect ratio (rows from the top).
    void draw() const;
};

// `nearest`: pixels stay sharp when enlarged (charts of values), else filtered.
UiImage upload_ui_image(const image::FloatImage& image, bool nearest = false);

}  // namespace fxview::ui

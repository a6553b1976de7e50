// Turns the linear float render into what the screen shows: an RGBA8 texture holding the
// exposed, tone-mapped (image/display_transform.hpp) and sRGB-encoded picture (or, with the legacy switch, the linear values as bytes, as the original
// ShaderViewer displayed them). The UI draws that texture; screenshots of the window see it too.
#pragma once
#include "gl/objects.hpp"
#include "image/display_transform.hpp"

namespace fxview::ui {

// The linear grey that uncovered (alpha 0) pixels show in the view, and screenshots get too.
inline constexpr float kDisplayBackdrop = 0.02f;

class DisplayPass {
public:
    DisplayPass();
    // Encodes `source` (RGBA32F) into the display texture through the display transform, resizing it as needed.
    void run(GLuint source, int width, int height, bool srgb, const image::DisplaySettings& display);
    GLuint texture() const { return texture_.get(); }

private:
    gl::Program program_;
    gl::VertexArray vertex_array_;
    gl::Texture texture_;
    gl::Framebuffer framebuffer_;
    int width_ = 0, height_ = 0;
};

}  // namespace fxview::ui

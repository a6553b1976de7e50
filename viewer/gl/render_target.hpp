// Off-screen render target: RGBA32F colour attachments (the first is the picture, the others carry
// extra per-pixel data such as a G-buffer) plus a 32-bit float depth buffer, optionally multisampled.
// Readback is exact: the float values the fragment shader wrote (after MSAA resolve, if any).
#pragma once
#include <vector>

#include "gl/objects.hpp"
#include "image/image.hpp"

namespace fxview::gl {

struct RenderTargetDesc {
    int width = 256;
    int height = 256;
    int color_attachments = 1;
    int samples = 0;  // 0 or 1: no MSAA
};

class RenderTarget {
public:
    explicit RenderTarget(const RenderTargetDesc& desc);

    // Binds for drawing, with every colour attachment enabled and the viewport covering the target.
    void bind_for_drawing() const;
    // Copies multisampled attachments to the single-sample textures; no-op without MSAA.
    void resolve() const;
    // Resolves if needed and reads attachment `index` as float RGBA, top row first.
    image::FloatImage read_color(int index = 0) const;

    GLuint color_texture(int index) const { return color_textures_.at(index).get(); }
    GLuint framebuffer() const { return resolved_framebuffer_.get(); }
    int width() const { return desc_.width; }
    int height() const { return desc_.height; }
    int color_attachment_count() const { return desc_.color_attachments; }
    bool multisampled() const { return desc_.samples > 1; }

private:
    RenderTargetDesc desc_;
    std::vector<Texture> color_textures_;  // single-sample, readable and sampleable
    Texture depth_texture_;
    Framebuffer resolved_framebuffer_;
    std::vector<Renderbuffer> msaa_color_;  // only with MSAA
    Renderbuffer msaa_depth_;
    Framebuffer msaa_framebuffer_;
};

}  // namespace fxview::gl

#include "gl/render_target.hpp"

#include <algorithm>
#include <cstdio>
#include <string>

#include "core/error.hpp"

namespace fxview::gl {
namespace {

void check_complete(GLuint framebuffer, const char* which) {
    const GLenum status = glCheckNamedFramebufferStatus(framebuffer, GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        throw Error(std::string("render target: ") + which + " framebuffer incomplete (status 0x" +
                    [status] {
                        char hex[8];
                        std::snprintf(hex, sizeof hex, "%04X", status);
                        return std::string(hex);
                    }() + ")");
}

std::vector<GLenum> draw_buffers(int count) {
    std::vector<GLenum> buffers;
    for (int i = 0; i < count; ++i) buffers.push_back(GL_COLOR_ATTACHMENT0 + i);
    return buffers;
}

}  // namespace

RenderTarget::RenderTarget(const RenderTargetDesc& desc) : desc_(desc) {
    GLint max_size = 0, max_attachments = 0, max_samples = 0;
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_size);
    glGetIntegerv(GL_MAX_COLOR_ATTACHMENTS, &max_attachments);
    glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
    if (desc.width < 1 || desc.height < 1 || desc.width > max_size || desc.height > max_size)
        throw Error("render target: size " + std::to_string(desc.width) + "x" + std::to_string(desc.height) +
                    " outside 1.." + std::to_string(max_size));
    if (desc.color_attachments < 1 || desc.color_attachments > max_attachments)
        throw Error("render target: " + std::to_string(desc.color_attachments) + " colour attachments, the driver allows 1.." +
                    std::to_string(max_attachments));
    if (desc.samples > max_samples)
        throw Error("render target: " + std::to_string(desc.samples) + " samples, the driver allows up to " +
                    std::to_string(max_samples));

    resolved_framebuffer_ = create_framebuffer();
    for (int i = 0; i < desc.color_attachments; ++i) {
        Texture texture = create_texture(GL_TEXTURE_2D);
        glTextureStorage2D(texture.get(), 1, GL_RGBA32F, desc.width, desc.height);
        glTextureParameteri(texture.get(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTextureParameteri(texture.get(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glNamedFramebufferTexture(resolved_framebuffer_.get(), GL_COLOR_ATTACHMENT0 + i, texture.get(), 0);
        color_textures_.push_back(std::move(texture));
    }
    depth_texture_ = create_texture(GL_TEXTURE_2D);
    glTextureStorage2D(depth_texture_.get(), 1, GL_DEPTH_COMPONENT32F, desc.width, desc.height);
    glNamedFramebufferTexture(resolved_framebuffer_.get(), GL_DEPTH_ATTACHMENT, depth_texture_.get(), 0);
    const auto buffers = draw_buffers(desc.color_attachments);
    glNamedFramebufferDrawBuffers(resolved_framebuffer_.get(), static_cast<GLsizei>(buffers.size()), buffers.data());
    check_complete(resolved_framebuffer_.get(), "resolve");

    if (multisampled()) {
        msaa_framebuffer_ = create_framebuffer();
        for (int i = 0; i < desc.color_attachments; ++i) {
            Renderbuffer buffer = create_renderbuffer();
            glNamedRenderbufferStorageMultisample(buffer.get(), desc.samples, GL_RGBA32F, desc.width, desc.height);
            glNamedFramebufferRenderbuffer(msaa_framebuffer_.get(), GL_COLOR_ATTACHMENT0 + i, GL_RENDERBUFFER,
                                           buffer.get());
            msaa_color_.push_back(std::move(buffer));
        }
        msaa_depth_ = create_renderbuffer();
        glNamedRenderbufferStorageMultisample(msaa_depth_.get(), desc.samples, GL_DEPTH_COMPONENT32F, desc.width,
                                              desc.height);
        glNamedFramebufferRenderbuffer(msaa_framebuffer_.get(), GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                                       msaa_depth_.get());
        glNamedFramebufferDrawBuffers(msaa_framebuffer_.get(), static_cast<GLsizei>(buffers.size()), buffers.data());
        check_complete(msaa_framebuffer_.get(), "multisample");
    }
}

void RenderTarget::bind_for_drawing() const {
    glBindFramebuffer(GL_FRAMEBUFFER, multisampled() ? msaa_framebuffer_.get() : resolved_framebuffer_.get());
    glViewport(0, 0, desc_.width, desc_.height);
}

void RenderTarget::resolve() const {
    if (!multisampled()) return;
    for (int i = 0; i < desc_.color_attachments; ++i) {
        glNamedFramebufferReadBuffer(msaa_framebuffer_.get(), GL_COLOR_ATTACHMENT0 + i);
        const GLenum target = GL_COLOR_ATTACHMENT0 + i;
        glNamedFramebufferDrawBuffers(resolved_framebuffer_.get(), 1, &target);
        glBlitNamedFramebuffer(msaa_framebuffer_.get(), resolved_framebuffer_.get(), 0, 0, desc_.width,
                               desc_.height, 0, 0, desc_.width, desc_.height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    }
    const auto buffers = draw_buffers(desc_.color_attachments);
    glNamedFramebufferDrawBuffers(resolved_framebuffer_.get(), static_cast<GLsizei>(buffers.size()), buffers.data());
}

image::FloatImage RenderTarget::read_color(int index) const {
    if (index < 0 || index >= desc_.color_attachments)
        throw Error("render target: no colour attachment " + std::to_string(index));
    resolve();
    image::FloatImage bottom_up(desc_.width, desc_.height, 4);
    glNamedFramebufferReadBuffer(resolved_framebuffer_.get(), GL_COLOR_ATTACHMENT0 + index);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, resolved_framebuffer_.get());
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, desc_.width, desc_.height, GL_RGBA, GL_FLOAT, bottom_up.data.data());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    // GL's rows run bottom to top; images run top to bottom.
    image::FloatImage image(desc_.width, desc_.height, 4);
    const size_t row = static_cast<size_t>(desc_.width) * 4;
    for (int y = 0; y < desc_.height; ++y)
        std::copy_n(bottom_up.data.begin() + static_cast<ptrdiff_t>((desc_.height - 1 - y) * row), row,
                    image.data.begin() + static_cast<ptrdiff_t>(y * row));
    return image;
}

}  // namespace fxview::gl

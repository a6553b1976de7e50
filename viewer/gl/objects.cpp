#include "gl/objects.hpp"

namespace fxview::gl {

Buffer create_buffer() {
    GLuint name = 0;
    glCreateBuffers(1, &name);
    return Buffer(name);
}

VertexArray create_vertex_array() {
    GLuint name = 0;
    glCreateVertexArrays(1, &name);
    return VertexArray(name);
}

Texture create_texture(GLenum target) {
    GLuint name = 0;
    glCreateTextures(target, 1, &name);
    return Texture(name);
}

Renderbuffer create_renderbuffer() {
    GLuint name = 0;
    glCreateRenderbuffers(1, &name);
    return Renderbuffer(name);
}

Framebuffer create_framebuffer() {
    GLuint name = 0;
    glCreateFramebuffers(1, &name);
    return Framebuffer(name);
}

Query create_query(GLenum target) {
    GLuint name = 0;
    glCreateQueries(target, 1, &name);
    return Query(name);
}

Sampler create_sampler() {
    GLuint name = 0;
    glCreateSamplers(1, &name);
    return Sampler(name);
}

}  // namespace fxview::gl

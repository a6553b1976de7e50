// RAII owners for OpenGL object names: one move-only type per kind of object, created with the
// GL 4.5 direct-state-access calls and deleted when the owner dies. A context must be current.
#pragma once
#include <glad/gl.h>

#include <utility>

namespace fxview::gl {

template <typename Traits>
class Object {
public:
    Object() = default;
    explicit Object(GLuint name) : name_(name) {}
    ~Object() { reset(); }
    Object(Object&& other) noexcept : name_(std::exchange(other.name_, 0)) {}
    Object& operator=(Object&& other) noexcept {
        if (this != &other) {
            reset();
            name_ = std::exchange(other.name_, 0);
        }
        return *this;
    }
    Object(const Object&) = delete;
    Object& operator=(const Object&) = delete;

    GLuint get() const { return name_; }
    explicit operator bool() const { return name_ != 0; }
    void reset() {
        if (name_ != 0) Traits::destroy(name_);
        name_ = 0;
    }

private:
    GLuint name_ = 0;
};

struct BufferTraits {
    static void destroy(GLuint name) { glDeleteBuffers(1, &name); }
};
struct VertexArrayTraits {
    static void destroy(GLuint name) { glDeleteVertexArrays(1, &name); }
};
struct TextureTraits {
    static void destroy(GLuint name) { glDeleteTextures(1, &name); }
};
struct RenderbufferTraits {
    static void destroy(GLuint name) { glDeleteRenderbuffers(1, &name); }
};
struct FramebufferTraits {
    static void destroy(GLuint name) { glDeleteFramebuffers(1, &name); }
};
struct ShaderTraits {
    static void destroy(GLuint name) { glDeleteShader(name); }
};
struct ProgramTraits {
    static void destroy(GLuint name) { glDeleteProgram(name); }
};
struct SamplerTraits {
    static void destroy(GLuint name) { glDeleteSamplers(1, &name); }
};
struct QueryTraits {
    static void destroy(GLuint name) { glDeleteQueries(1, &name); }
};

using Buffer = Object<BufferTraits>;
using VertexArray = Object<VertexArrayTraits>;
using Texture = Object<TextureTraits>;
using Renderbuffer = Object<RenderbufferTraits>;
using Framebuffer = Object<FramebufferTraits>;
using Shader = Object<ShaderTraits>;
using Program = Object<ProgramTraits>;
using Query = Object<QueryTraits>;
using Sampler = Object<SamplerTraits>;

Buffer create_buffer();
VertexArray create_vertex_array();
Texture create_texture(GLenum target);
Renderbuffer create_renderbuffer();
Framebuffer create_framebuffer();
Query create_query(GLenum target);
Sampler create_sampler();

}  // namespace fxview::gl

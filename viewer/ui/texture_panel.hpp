// The Textures tab: every texture of the effect (size, format, source, a thumbnail; cube maps as a
// cross that can become the skybox), an inspector for the one selected (zoom and pan, channel,
// exposure, mip level, cube face, 3D slice, the float value of the texel under the cursor), and
// assigning a file to a sampler.
#pragma once
#include <array>
#include <map>
#include <string>

#include <glm/glm.hpp>

#include "gl/objects.hpp"
#include "gl/render_target.hpp"
#include "render/effect_session.hpp"

namespace fxview::ui {

class TexturePanel {
public:
    TexturePanel();
    // `skybox` names the cube map drawn as the background ("" for none); `status` receives messages.
    void draw(render::EffectSession& session, std::string& skybox, std::string& status);
    // Opens the inspector on a texture (the script's `inspect-texture NAME [CHANNEL [EV]]`).
    void inspect(const std::string& name, int channel = 0, float exposure = 0) { selected_ = name, channel_ = channel, exposure_ = exposure; }

private:
    const std::array<gl::Texture, 6>& face_views(const render::GpuTexture& cube);
    void draw_inspector(const render::GpuTexture& texture);
    void render_preview(const render::GpuTexture& texture, int width, int height);

    gl::Program program_;
    gl::VertexArray vertex_array_;
    std::unique_ptr<gl::RenderTarget> preview_;  // 0: what is shown, 1: the raw texel values
    std::map<GLuint, std::array<gl::Texture, 6>> cube_views_;
    std::string selected_;
    int channel_ = 0, level_ = 0, face_ = 0, sampler_choice_ = 0;
    float exposure_ = 0, slice_ = 0.5f, zoom_ = 1;
    glm::vec2 centre_{0.5f};  // the texture coordinate in the middle of the preview
    bool srgb_ = true;
    char file_[512] = "textures/checker.png";
};

}  // namespace fxview::ui

// The Textures tab: every texture of the effect (size, format, source, a thumbnail; cube maps as a
// cross that can become the skybox), an inspector for the one selected (zoom and pan, channel,
// exposure, mip level, cube face, 3D slice, the float value of the texel under the cursor), and
// assigning a file to a sampler.
#pragma once
#include <array>
#include <map>
#include <optional>
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
    void inspect(const std::string& name, int channel = 0, float exposure = 0, int level = 0) {
        selected_ = name, channel_ = channel, exposure_ = exposure, level_ = level;
    }

    // The texel shown at a point of the inspector's preview, as its tooltip says: `at` runs from
    // (0, 0) at the preview's top left to (1, 1) at its bottom right. Texel rows count as GL's do,
    // from the bottom of the picture (texture coordinate t = 0) up; the preview shows the picture
    // upright, its file's first row on top. Empty when no preview was drawn or `at` is outside the
    // texture.
    struct Texel {
        int x = 0, y = 0, level = 0, levels = 1;
        bool generated_levels = false;
        glm::vec4 value{0.0f};  // as the shader reads it
    };
    std::optional<Texel> texel_at(glm::vec2 at) const;

private:
    const std::array<gl::Texture, 6>& face_views(const render::GpuTexture& cube);
    void draw_inspector(const render::GpuTexture& texture);
    void render_preview(const render::GpuTexture& texture, int width, int height);
    // The preview coordinates a preview of width x height spans at the current zoom.
    glm::vec2 preview_span(float width, float height, int texture_width, int texture_height) const;

    gl::Program program_;
    gl::VertexArray vertex_array_;
    std::unique_ptr<gl::RenderTarget> preview_;  // 0: what is shown, 1: the raw texel values
    std::map<GLuint, std::array<gl::Texture, 6>> cube_views_;
    std::string selected_;
    int channel_ = 0, level_ = 0, face_ = 0, sampler_choice_ = 0;
    float exposure_ = 0, slice_ = 0.5f, zoom_ = 1;
    glm::vec2 centre_{0.5f};  // the preview's coordinate (x right, y down the picture as shown) in its middle
    struct Shown {            // what the preview last showed, for texel_at
        int width = 0, height = 0, levels = 1;
        bool rows_up = true;  // GL's rows run up the picture (all but cube faces, which are stored top row first)
        bool generated_levels = false;
    };
    std::optional<Shown> shown_;
    bool srgb_ = true;
    char file_[512] = "textures/checker.png";
};

}  // namespace fxview::ui

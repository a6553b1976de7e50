#include "ui/texture_panel.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "effect/parser.hpp"
#include "gl/program.hpp"
#include "texture/texture_data.hpp"
#include "texture/texture_file.hpp"
#include "ui/ui_shaders.hpp"

namespace fxview::ui {
namespace {

// Texels by texelFetch (exact values, whatever the sampler state), the channel chosen, times 2^EV,
// sRGB-encoded for display; the raw value goes to the second target for the readout.
const std::string kFragment = std::string(R"(#version 450 core
in vec2 uv;
uniform sampler1D u_1d;
uniform sampler2D u_2d;
uniform sampler3D u_3d;
uniform int u_kind;  // 1, 2 or 3 dimensions
uniform int u_level, u_channel;
uniform float u_slice, u_scale;
uniform vec2 u_from, u_to;  // the preview's corners, y down the picture as shown
uniform bool u_rows_up;     // GL rows from the picture's bottom up (not cube faces)
uniform bool u_srgb;
layout(location = 0) out vec4 shown;
layout(location = 1) out vec4 raw;
)") + kSrgbEncodeGlsl + R"(
void main() {
    vec2 t = mix(u_from, u_to, vec2(uv.x, 1.0 - uv.y));  // the panel's top first
    if (u_rows_up) t.y = 1.0 - t.y;                      // the picture upright
    if (any(lessThan(t, vec2(0.0))) || any(greaterThanEqual(t, vec2(1.0)))) {
        shown = vec4(0.12, 0.12, 0.12, 1.0);
        raw = vec4(0.0);
        return;
    }
    vec4 v;
    if (u_kind == 1) {
        int size = textureSize(u_1d, u_level);
        v = texelFetch(u_1d, clamp(int(t.x * size), 0, size - 1), u_level);
    } else if (u_kind == 2) {
        ivec2 size = textureSize(u_2d, u_level);
        v = texelFetch(u_2d, clamp(ivec2(t * vec2(size)), ivec2(0), size - 1), u_level);
    } else {
        ivec3 size = textureSize(u_3d, u_level);
        v = texelFetch(u_3d, clamp(ivec3(vec3(t, u_slice) * vec3(size)), ivec3(0), size - 1), u_level);
    }
    raw = v;
    vec3 c = u_channel == 1 ? v.rrr : u_channel == 2 ? v.ggg : u_channel == 3 ? v.bbb : u_channel == 4 ? v.aaa : v.rgb;
    c *= u_scale;
    if (u_channel == 0) {  // RGBA: over a checkerboard where alpha < 1
        float check = 0.2 + 0.1 * mod(floor(gl_FragCoord.x / 8.0) + floor(gl_FragCoord.y / 8.0), 2.0);
        c = mix(vec3(check), c, clamp(v.a, 0.0, 1.0));
    }
    shown = vec4(u_srgb ? encode(c) : clamp(c, 0.0, 1.0), 1.0);
})";

ImTextureID image_id(GLuint texture) { return reinterpret_cast<ImTextureID>(static_cast<intptr_t>(texture)); }

const char* type_name(texture::TextureType type) {
    switch (type) {
        case texture::TextureType::Tex1D: return "1D";
        case texture::TextureType::Tex3D: return "3D";
        case texture::TextureType::Cube: return "cube";
        default: return "2D";
    }
}

}  // namespace

TexturePanel::TexturePanel()
    : program_(gl::link_program({{GL_VERTEX_SHADER, kFullscreenVertexShader, "texture inspector"}, {GL_FRAGMENT_SHADER, kFragment, "texture inspector"}})),
      vertex_array_(gl::create_vertex_array()) {}

// 2D views of a cube map's six faces (GL texture views), made once per texture.
const std::array<gl::Texture, 6>& TexturePanel::face_views(const render::GpuTexture& cube) {
    auto& views = cube_views_[cube.texture.get()];
    if (!views[0]) {
        GLint internal = 0;
        glGetTextureLevelParameteriv(cube.texture.get(), 0, GL_TEXTURE_INTERNAL_FORMAT, &internal);
        GLint levels = 1;
        glGetTextureParameteriv(cube.texture.get(), GL_TEXTURE_IMMUTABLE_LEVELS, &levels);
        for (GLuint face = 0; face < 6; ++face) {
            GLuint name = 0;
            glGenTextures(1, &name);  // a view needs an unbound, never-bound name
            glTextureView(name, GL_TEXTURE_2D, cube.texture.get(), static_cast<GLenum>(internal), 0, static_cast<GLuint>(std::max(levels, 1)), face, 1);
            views[face] = gl::Texture(name);
        }
    }
    return views;
}

glm::vec2 TexturePanel::preview_span(float width, float height, int texture_width, int texture_height) const {
    // At zoom 1 the whole texture fits, at its own aspect, centred on the axis with room to spare.
    const float r = height / std::max(width, 1.0f) * static_cast<float>(texture_width) / static_cast<float>(std::max(texture_height, 1));
    return glm::vec2(1.0f, r) / (zoom_ * std::min(1.0f, r));
}

void TexturePanel::render_preview(const render::GpuTexture& texture, int width, int height) {
    if (!preview_ || preview_->width() != width || preview_->height() != height)
        preview_ = std::make_unique<gl::RenderTarget>(gl::RenderTargetDesc{width, height, 2, 0});
    const GLuint source = texture.type == texture::TextureType::Cube ? face_views(texture)[static_cast<size_t>(face_)].get() : texture.texture.get();
    const int kind = texture.type == texture::TextureType::Tex1D ? 1 : texture.type == texture::TextureType::Tex3D ? 3 : 2;
    preview_->bind_for_drawing();
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glDisable(GL_SCISSOR_TEST);
    const GLuint p = program_.get();
    glUseProgram(p);
    const GLuint unit = static_cast<GLuint>(kind - 1);
    glBindTextureUnit(unit, source);
    glBindSampler(unit, 0);
    const auto at = [p](const char* name) { return glGetUniformLocation(p, name); };
    glProgramUniform1i(p, at("u_1d"), 0);
    glProgramUniform1i(p, at("u_2d"), 1);
    glProgramUniform1i(p, at("u_3d"), 2);
    glProgramUniform1i(p, at("u_kind"), kind);
    glProgramUniform1i(p, at("u_level"), level_);
    glProgramUniform1i(p, at("u_channel"), channel_);
    glProgramUniform1f(p, at("u_slice"), slice_);
    glProgramUniform1f(p, at("u_scale"), std::exp2(exposure_));
    const glm::vec2 half = 0.5f * preview_span(width, height, texture.width, texture.height);
    glProgramUniform2f(p, at("u_from"), centre_.x - half.x, centre_.y - half.y);
    glProgramUniform2f(p, at("u_to"), centre_.x + half.x, centre_.y + half.y);
    glProgramUniform1i(p, at("u_srgb"), srgb_ ? 1 : 0);
    glProgramUniform1i(p, at("u_rows_up"), texture.type != texture::TextureType::Cube ? 1 : 0);
    glBindVertexArray(vertex_array_.get());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void TexturePanel::draw_inspector(const render::GpuTexture& texture) {
    const char* channels[] = {"RGBA", "R", "G", "B", "A"};
    ImGui::Combo("channel", &channel_, channels, 5);
    ImGui::SliderFloat("exposure (EV)", &exposure_, -10.0f, 10.0f, "%.1f");
    if (texture.levels > 1) {
        ImGui::SliderInt("mip level", &level_, 0, texture.levels - 1);
        if (texture.generated_levels && ImGui::IsItemHovered()) ImGui::SetTooltip("levels 1-%d generated by the GL driver (the file has one)", texture.levels - 1);
    }
    level_ = std::clamp(level_, 0, std::max(texture.levels - 1, 0));
    if (texture.type == texture::TextureType::Cube) {
        const char* faces[] = {"+X", "-X", "+Y", "-Y", "+Z", "-Z"};
        ImGui::Combo("face", &face_, faces, 6);
    }
    GLint depth = 1;
    if (texture.type == texture::TextureType::Tex3D) {
        glGetTextureLevelParameteriv(texture.texture.get(), level_, GL_TEXTURE_DEPTH, &depth);
        int slice = std::clamp(static_cast<int>(slice_ * depth), 0, std::max(depth - 1, 0));
        if (ImGui::SliderInt("slice", &slice, 0, std::max(depth - 1, 0))) slice_ = (slice + 0.5f) / std::max(depth, 1);
    }
    ImGui::Checkbox("sRGB display", &srgb_);
    ImGui::SameLine();
    if (ImGui::Button("Fit")) zoom_ = 1, centre_ = glm::vec2(0.5f);
    ImGui::SameLine();
    ImGui::TextDisabled("zoom %.3gx the fitted size (wheel; drag to pan)", zoom_);

    const float side = std::max(64.0f, std::min(ImGui::GetContentRegionAvail().x, 512.0f));
    const float aspect = texture.type == texture::TextureType::Tex1D ? 0.25f : static_cast<float>(std::max(texture.height, 1)) / std::max(texture.width, 1);
    const ImVec2 size(side, std::clamp(side * aspect, 32.0f, side));
    render_preview(texture, static_cast<int>(size.x), static_cast<int>(size.y));
    shown_ = Shown{texture.width, texture.height, texture.levels, texture.type != texture::TextureType::Cube, texture.generated_levels};
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    ImGui::Image(image_id(preview_->color_texture(0)), size, ImVec2(0, 1), ImVec2(1, 0));
    if (!ImGui::IsItemHovered()) return;
    ImGuiIO& io = ImGui::GetIO();
    const glm::vec2 at((io.MousePos.x - origin.x) / size.x, (io.MousePos.y - origin.y) / size.y);
    const glm::vec2 span = preview_span(size.x, size.y, texture.width, texture.height);
    const glm::vec2 t = centre_ + (at - 0.5f) * span;  // the preview coordinate under the cursor
    if (io.MouseWheel != 0.0f) {  // zoom about the cursor
        const float factor = std::pow(1.25f, io.MouseWheel);
        zoom_ = std::clamp(zoom_ * factor, 0.25f, 512.0f);
        centre_ = t - (at - 0.5f) * span / factor;
    }
    if (ImGui::IsMouseDragging(ImGuiMouseButton_Left)) {
        centre_ -= glm::vec2(io.MouseDelta.x / size.x, io.MouseDelta.y / size.y) * span;
    }
    if (const auto texel = texel_at(at))
        ImGui::SetTooltip("texel %d, %d (level %d; rows count up from the bottom)\n%.6g %.6g %.6g %.6g", texel->x, texel->y, texel->level,
                          texel->value.r, texel->value.g, texel->value.b, texel->value.a);
}

std::optional<TexturePanel::Texel> TexturePanel::texel_at(glm::vec2 at) const {
    if (!shown_ || !preview_ || at.x < 0 || at.y < 0 || at.x >= 1 || at.y >= 1) return std::nullopt;
    const int width = preview_->width(), height = preview_->height();
    const glm::vec2 span = preview_span(width, height, shown_->width, shown_->height);
    glm::vec2 t = centre_ + (at - 0.5f) * span;
    if (t.x < 0 || t.y < 0 || t.x >= 1 || t.y >= 1) return std::nullopt;
    if (shown_->rows_up) t.y = 1.0f - t.y;
    Texel texel;
    texel.level = level_;
    texel.levels = shown_->levels;
    texel.generated_levels = shown_->generated_levels;
    const int level_width = std::max(1, shown_->width >> level_), level_height = std::max(1, shown_->height >> level_);
    texel.x = std::min(static_cast<int>(t.x * level_width), level_width - 1);
    texel.y = std::min(static_cast<int>(t.y * level_height), level_height - 1);
    // The value the shader wrote for the preview's pixel there (GL's rows run up the preview too).
    const int px = std::clamp(static_cast<int>(at.x * width), 0, width - 1), py = std::clamp(static_cast<int>(at.y * height), 0, height - 1);
    glGetTextureSubImage(preview_->color_texture(1), 0, px, height - 1 - py, 0, 1, 1, 1, GL_RGBA, GL_FLOAT, sizeof texel.value, &texel.value[0]);
    return texel;
}

void TexturePanel::draw(render::EffectSession& session, std::string& skybox, std::string& status) {
    const auto& textures = session.resources().textures();
    if (textures.empty()) ImGui::TextDisabled("The effect has no textures.");
    for (const auto& [name, texture] : textures) {
        ImGui::PushID(name.c_str());
        const std::string line = name + "  " + std::to_string(texture.width) + "x" + std::to_string(texture.height) + "  " +
                                 texture::format_name(texture.format) + "  " + type_name(texture.type) +
                                 (texture.levels > 1 ? "  " + std::to_string(texture.levels) + (texture.generated_levels ? " levels (generated)" : " levels") : "");
        if (ImGui::Selectable(line.c_str(), selected_ == name)) selected_ = selected_ == name ? "" : name;
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s\nclick to inspect", texture.source.c_str());
        if (texture.type == texture::TextureType::Cube) {
            // A horizontal cross: +Y above, -X +Z +X -Z in the middle row, -Y below.
            const auto& views = face_views(texture);
            const float cell = ImGui::GetFontSize() * 2.5f;
            const ImVec2 origin = ImGui::GetCursorScreenPos();
            const int cells[6][2] = {{2, 1}, {0, 1}, {1, 0}, {1, 2}, {1, 1}, {3, 1}};
            for (int face = 0; face < 6; ++face) {
                ImGui::SetCursorScreenPos(ImVec2(origin.x + cells[face][0] * cell, origin.y + cells[face][1] * cell));
                ImGui::Image(image_id(views[static_cast<size_t>(face)].get()), ImVec2(cell, cell));
            }
            ImGui::SetCursorScreenPos(ImVec2(origin.x, origin.y + 3 * cell + 4));
            bool sky = skybox == name;
            if (ImGui::Checkbox("skybox", &sky)) skybox = sky ? name : "";
        }
        if (selected_ == name) {
            ImGui::Indent();
            draw_inspector(texture);
            ImGui::Unindent();
        }
        ImGui::PopID();
    }
    ImGui::Separator();
    std::vector<std::string> samplers;
    for (const auto& p : session.effect().parameters)
        if (effect::is_sampler_type(p.type)) samplers.push_back(p.name);
    if (samplers.empty()) return;
    sampler_choice_ = std::min(sampler_choice_, static_cast<int>(samplers.size()) - 1);
    if (ImGui::BeginCombo("sampler", samplers[static_cast<size_t>(sampler_choice_)].c_str())) {
        for (int i = 0; i < static_cast<int>(samplers.size()); ++i)
            if (ImGui::Selectable(samplers[static_cast<size_t>(i)].c_str(), i == sampler_choice_)) sampler_choice_ = i;
        ImGui::EndCombo();
    }
    if (ImGui::BeginCombo("loaded file", "pick a loaded texture")) {
        for (const auto& [name, texture] : textures)
            if (texture.source.find('/') != std::string::npos && ImGui::Selectable(texture.source.c_str()))
                std::snprintf(file_, sizeof file_, "%s", texture.source.c_str());
        ImGui::EndCombo();
    }
    ImGui::InputText("texture file", file_, sizeof file_);
    if (ImGui::Button("Assign to sampler")) {
        const std::string sampler = samplers[static_cast<size_t>(sampler_choice_)];
        const auto before = session.values().textures;
        session.values().textures[sampler] = file_;
        try {
            session.reload_textures();
            status = "assigned " + std::string(file_) + " to " + sampler;
        } catch (const std::exception& e) {
            session.values().textures = before;  // keep what worked
            session.reload_textures();
            status = e.what();
        }
    }
}

}  // namespace fxview::ui

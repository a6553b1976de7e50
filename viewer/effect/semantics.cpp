#include "effect/semantics.hpp"

#include <map>
#include <optional>

#include <glm/gtc/type_ptr.hpp>

namespace fxview::effect {
namespace {

const std::vector<std::string> kMatrixBases = {"WORLDVIEWPROJECTION", "VIEWPROJECTION", "WORLDVIEW",
                                               "PROJECTION", "WORLD", "VIEW"};
const std::vector<std::string> kOthers = {"CAMERAPOSITION", "LIGHTPOSITION", "LIGHTDIRECTION", "VIEWPORTPIXELSIZE",
                                          "TIME", "FRAME", "ENVIRONMENTROTATION", "ENVIRONMENTINTENSITY",
                                          "VIEWLIGHTPOSITION", "LIGHTRADIUS", "LIGHTSHAPE",
                                          "LIGHTHALFSIZE", "LIGHTFRAME", "LIGHTRADIANCE"};

std::optional<glm::mat4> matrix_for(const std::string& semantic, const FrameContext& f) {
    for (const auto& base : kMatrixBases) {
        if (semantic.rfind(base, 0) != 0) continue;
        const std::string suffix = semantic.substr(base.size());
        glm::mat4 m = base == "WORLD" ? f.world
                    : base == "VIEW" ? f.view
                    : base == "PROJECTION" ? f.projection
                    : base == "WORLDVIEW" ? f.view * f.world
                    : base == "VIEWPROJECTION" ? f.projection * f.view
                                               : f.projection * f.view * f.world;
        if (suffix.empty()) return m;
        if (suffix == "INVERSE") return glm::inverse(m);
        if (suffix == "TRANSPOSE") return glm::transpose(m);
        if (suffix == "INVERSETRANSPOSE") return glm::transpose(glm::inverse(m));
    }
    return std::nullopt;
}

// A mat3 (or the mat4 holding it), column-major.
std::vector<float> mat3_value(const glm::mat3& m, int components) {
    if (components == 9) return {m[0][0], m[0][1], m[0][2], m[1][0], m[1][1], m[1][2], m[2][0], m[2][1], m[2][2]};
    return {m[0][0], m[0][1], m[0][2], 0.0f, m[1][0], m[1][1], m[1][2], 0.0f, m[2][0], m[2][1], m[2][2], 0.0f, 0.0f, 0.0f, 0.0f, 1.0f};
}

}  // namespace

bool is_known_semantic(const std::string& semantic) {
    for (const auto& other : kOthers)
        if (semantic == other) return true;
    FrameContext identity;
    return matrix_for(semantic, identity).has_value();
}

std::vector<float> semantic_value(const std::string& semantic, const FrameContext& f, int components) {
    if (const auto m = matrix_for(semantic, f)) {
        if (components == 9) {
            const glm::mat3 m3(*m);
            return {glm::value_ptr(m3), glm::value_ptr(m3) + 9};
        }
        return {glm::value_ptr(*m), glm::value_ptr(*m) + 16};
    }
    if (semantic == "CAMERAPOSITION") return {f.camera_position.x, f.camera_position.y, f.camera_position.z, 1.0f};
    if (semantic == "LIGHTPOSITION") return {f.light_position.x, f.light_position.y, f.light_position.z, 1.0f};
    if (semantic == "LIGHTRADIUS") return {f.light_radius};
    if (semantic == "LIGHTSHAPE") return {f.light_shape};
    if (semantic == "LIGHTHALFSIZE") return {f.light_half_size.x, f.light_half_size.y};
    if (semantic == "LIGHTRADIANCE") return {f.light_radiance};
    if (semantic == "LIGHTFRAME") return mat3_value(f.light_frame, components);
    if (semantic == "VIEWLIGHTPOSITION") {  // Cg's glstate.light[0].position: OpenGL keeps it in eye space
        const glm::vec4 p = f.view * glm::vec4(f.light_position, 1.0f);
        return {p.x, p.y, p.z, p.w};
    }
    if (semantic == "LIGHTDIRECTION") {
        // Direction the light travels, towards the origin it orbits.
        const glm::vec3 d = glm::length(f.light_position) > 0 ? -glm::normalize(f.light_position) : glm::vec3(0, 0, -1);
        return {d.x, d.y, d.z, 0.0f};
    }
    if (semantic == "VIEWPORTPIXELSIZE") return {f.viewport_size.x, f.viewport_size.y, 1.0f / f.viewport_size.x, 1.0f / f.viewport_size.y};
    if (semantic == "TIME") return {f.time};
    if (semantic == "ENVIRONMENTINTENSITY") return {f.environment_intensity};
    if (semantic == "ENVIRONMENTROTATION") return mat3_value(f.environment_rotation, components);
    if (semantic == "FRAME") return {static_cast<float>(f.frame)};
    return {};
}

}  // namespace fxview::effect

// Debug views from their definitions: a vector v shown as normalize(v) * 0.5 + 0.5 (eq. 55), the
// texture coordinate as (u, v, 0), and Plain as a Lambert surface with an ambient floor.
#include "reference/debug_reference.hpp"

#include <algorithm>

namespace fxview::reference {
namespace {

std::array<double, 4> mapped(const glm::dvec3& v) {
    const glm::dvec3 n = glm::normalize(v) * 0.5 + 0.5;
    return {n.x, n.y, n.z, 1.0};
}

Reference make(Shader shade) {
    Reference r;
    r.shade = std::move(shade);
    r.tolerance = 1e-5;
    r.why = "one float32 normalisation or dot product against double: a few ulps (measured below 1e-6)";
    return r;
}

}  // namespace

std::map<std::string, Reference> debug_references() {
    std::map<std::string, Reference> all;
    all.emplace("Normals", make([](const ShadingInput& in, const ReferenceContext&) { return mapped(in.normal); }));
    all.emplace("TexCoords", make([](const ShadingInput& in, const ReferenceContext&) {
                    return std::array<double, 4>{in.uv.x, in.uv.y, 0.0, 1.0};
                }));
    all.emplace("VectorToCamera",
                make([](const ShadingInput& in, const ReferenceContext&) { return mapped(in.camera - in.position); }));
    all.emplace("VectorToLight",
                make([](const ShadingInput& in, const ReferenceContext&) { return mapped(in.light - in.position); }));
    all.emplace("Plain", make([](const ShadingInput& in, const ReferenceContext& c) {
                    const auto& colour = c.values.numbers.at("PlainColor");
                    const double ambient = c.number("Ambient");
                    const double lambert = std::max(glm::dot(glm::normalize(in.normal), glm::normalize(in.light - in.position)), 0.0);
                    const double shade = ambient + (1.0 - ambient) * lambert;
                    return std::array<double, 4>{colour[0] * shade, colour[1] * shade, colour[2] * shade, 1.0};
                }));
    return all;
}

}  // namespace fxview::reference

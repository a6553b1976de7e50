// CheckerLambert: a texture-mapped Lambert surface; the texture is read with the CPU sampler from
// the same (sRGB-decoded, bilinearly filtered) data the GPU samples. Mirror reads the cube map the same
// way, with GL's face selection; at face edges the seamless filter's texels bound the value.
#include "reference/example_reference.hpp"

#include <algorithm>


namespace fxview::reference {

std::map<std::string, Reference> example_references() {
    std::map<std::string, Reference> all;
    Reference checker;
    checker.shade = [](const ShadingInput& in, const ReferenceContext& c) {
        const glm::dvec4 albedo = c.sample_2d("Checker", in.uv * c.number("Tiling"));
        const double ambient = c.number("Ambient");
        const double lambert = std::max(glm::dot(glm::normalize(in.normal), glm::normalize(in.light - in.position)), 0.0);
        const double shade = ambient + (1.0 - ambient) * lambert;
        return std::array<double, 4>{albedo.r * shade, albedo.g * shade, albedo.b * shade, 1.0};
    };
    checker.tolerance = 4e-3;
    checker.why = "GL leaves the precision of sRGB decoding and of bilinear weights to the implementation: llvmpipe "
                  "decodes 8-bit sRGB texels within about 1.1e-3 of the exact curve (measured: texel 230 reads "
                  "0.79014, exactly 0.79123) and filters with finite-precision weights; 4e-3 leaves margin and "
                  "stays within one 8-bit code";
    const std::string texture_why = checker.why;
    all.emplace("CheckerLambert", std::move(checker));

    // Mirror: the cube map in the reflected view direction, linearly filtered on the base level.
    Reference mirror;
    const auto sky = [](const ShadingInput& in, const ReferenceContext& c) {
        const glm::dvec3 v = glm::normalize(in.position - in.camera), n = glm::normalize(in.normal);
        return c.sample_cube("Sky", v - 2.0 * glm::dot(n, v) * n);
    };
    mirror.shade = [sky](const ShadingInput& in, const ReferenceContext& c) {
        const glm::dvec4 value = sky(in, c).value;
        return std::array<double, 4>{value.r, value.g, value.b, 1.0};
    };
    // At cube corners GL leaves one texel to the implementation: the range of the texels around.
    mirror.slack = [sky](const ShadingInput& in, const ReferenceContext& c) { return sky(in, c).seam_spread; };
    mirror.tolerance = 4e-3;
    mirror.why = texture_why;
    all.emplace("Mirror", std::move(mirror));
    return all;
}

}  // namespace fxview::reference

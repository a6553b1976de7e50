// Image-based lighting on the CPU, read from the same tables the GPU samples (render/environment_maps.hpp)
// through GL's filtering rules (cpu_sampler.hpp), in double precision: the reference of
// effects/lib/environment.glsl, written from its documented arithmetic.
#pragma once
#include <optional>

#include "brdf/models.hpp"
#include "reference/reference.hpp"
#include "render/environment_maps.hpp"

namespace fxview::reference {

class EnvironmentLookup {
public:
    // None where the scene has no environment (its term is then 0, as on the GPU).
    static std::optional<EnvironmentLookup> from(const ReferenceContext& c);

    // Prefiltered radiance towards world direction `d` for `roughness`; `seam` gets the spread of the
    // texels at a cube corner (where GL leaves the texel to the implementation).
    glm::dvec3 radiance(const glm::dvec3& d, double roughness, double* seam = nullptr) const;
    glm::dvec3 irradiance(const glm::dvec3& n) const;  // E / pi, at least 0
    glm::dvec2 dfg(double nv, double roughness) const;

private:
    const render::EnvironmentMaps* maps_ = nullptr;
    glm::dmat3 rotation_{1.0};
    double intensity_ = 0.0;
};

// metallic_roughness_environment() of environment.glsl.
glm::dvec3 metallic_roughness_environment(const EnvironmentLookup& environment, const brdf::Directions& d, const brdf::MetallicRoughness& m,
                                          bool compensation, double* seam = nullptr);

}  // namespace fxview::reference

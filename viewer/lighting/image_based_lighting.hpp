// Image-based lighting by the split-sum approximation (Karis 2013), with the energy compensation
// of multiple scattering (Fdez-Agüera 2019, as Filament uses it), for the metallic-roughness GGX model
// of effects/lib/brdf.glsl: D = GGX with alpha = roughness², Smith-Schlick G with k = (roughness+1)²/8,
// Schlick's Fresnel. GL-free; the GPU uploads these tables (render/environment_maps.hpp), the CPU
// references read the same numbers.
//   specular  the radiance convolved with the GGX lobe around the mirror direction (n = v = r),
//             one cube mip level per roughness step k / (levels - 1), level 0 the radiance itself
//   irradiance  order-2 spherical harmonics of the radiance, convolved with the clamped cosine
//   dfg       per (n·v, roughness): A, B with ∫ f_ss cos = F0 A + B for Schlick's Fresnel, and
//             G = ∫ (1 - v·h)⁵ (n·l)/π dl, with which the diffuse part (1 - F(v·h)) base/π reflects
//             (1 - F0)(1 - G) base of uniform light
#pragma once
#include <array>
#include <vector>

#include <glm/glm.hpp>

#include "lighting/cube_map.hpp"
#include "lighting/environment_sources.hpp"

namespace fxview::lighting {

struct PrefilteredEnvironment {
    std::vector<FloatCube> specular;      // level k for prefiltered_roughness(k, levels), without the discs
    std::array<glm::vec3, 9> irradiance;  // SH coefficients of E(n) / pi, the cosine-convolved radiance (without the discs)
    // The discs' irradiance in closed form (order-2 SH would ring badly about a low sun): E(n)/pi adds
    // max(n·direction, 0) times this for each, from their centre direction.
    std::vector<std::pair<glm::vec3, glm::vec3>> disc_irradiance;  // direction, radiance x solid angle / pi
};

// The roughness of prefiltered level k of `levels`: (k / (levels - 1))², so that the sharp lobes,
// whose edges show, get most levels (0, 0.04, 0.16, 0.36, 0.64, 1 for six); and the fractional
// level (mip LOD) for a roughness, between which two levels are mixed linearly.
double prefiltered_roughness(int level, int levels);
double prefiltered_lod(double roughness, int levels);

// `samples` GGX directions per texel of level 1, four times as many on wider lobes (level 0 is the
// radiance). The discs are in none of the levels: shading adds them in closed form (disc_lighting.hpp),
// which no prefiltered lobe centred as if n = v = r can do for a source this small and bright.
PrefilteredEnvironment prefilter(const Environment& environment, int levels, int samples = 128);
// Its two parts apart (the specular levels cost seconds; spectral effects need only the SH):
std::vector<FloatCube> prefilter_specular(const Environment& environment, int levels, int samples = 128);
PrefilteredEnvironment prefilter_irradiance(const Environment& environment);  // `specular` left empty

// E(n) / π for SH coefficients of prefilter(): the radiance a white Lambertian surface reflects.
glm::dvec3 evaluate_irradiance(const std::array<glm::vec3, 9>& sh, const glm::dvec3& n);
// The same with the discs: the SH (at least 0) plus each disc's closed form.
glm::dvec3 evaluate_irradiance(const PrefilteredEnvironment& environment, const glm::dvec3& n);

struct DfgTable {
    int size = 0;                 // size x size texels: n·v = i / (size - 1) across, roughness = j / (size - 1) up
    std::vector<glm::vec3> data;  // A, B, G; row j (roughness) first
    // Bilinear between the tabulated values, as GL samples the texture at (value (size - 1) + ½) / size.
    glm::dvec3 lookup(double nv, double roughness) const;
};
DfgTable make_dfg_table(int size, int samples = 512);

// The GGX half vector for uniform numbers u1, u2 and alpha (distribution of normals D(h) (n·h)).
glm::dvec3 sample_ggx(double u1, double u2, double alpha);
// Point i of n of the Hammersley set.
glm::dvec2 hammersley(unsigned i, unsigned n);
double ggx_d(double nh, double alpha);

}  // namespace fxview::lighting

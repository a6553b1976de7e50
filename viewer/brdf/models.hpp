// Analytic BRDF models (DOMAIN.md §7) as small parameter structs evaluated in double precision.
// Each returns f(l, v) per RGB channel (1/sr), zero below the horizon; the radiance a point light
// of irradiance E produces is f · E · (n·l). The CPU references and the BRDF fitter use them.
#pragma once
#include <glm/glm.hpp>

namespace fxview::brdf {

// Unit vectors in world space: normal, to the light, to the eye, and a tangent orthogonal to n
// (the anisotropy's u axis; v = n × t).
struct Directions {
    glm::dvec3 n, l, v, t;
};

struct Lambert {
    glm::dvec3 albedo{0.8};
};

// The metallic-roughness model of seed 004 (ch. 3, Listing 10): Lambert + Cook-Torrance with GGX,
// Smith-Schlick-GGX and Fresnel-Schlick; F0 = mix(0.04, base, metallic), kD = (1 − F)(1 − metallic).
struct MetallicRoughness {
    glm::dvec3 base_color{1.0, 0.71, 0.29};
    double metallic = 1.0;
    double roughness = 0.4;
    // Masking: Schlick-GGX with k = (roughness + 1)²/8 (seed 004, Karis' remap for analytic lights),
    // or height-correlated Smith with α = roughness² (image-based light, as the DFG table).
    bool correlated_smith = false;
};

// Energy-conserving Phong (seed 001): kd/π + ks (n + 2)/(2π) (r·v)ⁿ.
struct ModifiedPhong {
    glm::dvec3 kd{0.5};
    double ks = 0.4;
    double exponent = 40.0;
};

// Cook-Torrance of seed 001: kd/π + ks D G F / (4 (n·l)(n·v)), Beckmann D, V-cavity G, full Fresnel.
struct CookTorranceBeckmann {
    glm::dvec3 kd{0.4};
    double ks = 1.0;
    double m = 0.3;  // rms slope
    double eta = 1.5;
    bool printed_beckmann = false;  // seed 001's 1/(4m²cos⁴) instead of 1/(πm²cos⁴)
};

// Ashikhmin-Shirley (seed 000 eq. 4.11-4.14; 4.11's (n·l)² is a typo for n·l): anisotropic exponents
// nu along t and nv along n × t, Schlick Fresnel with Rs.
struct AshikhminShirley {
    glm::dvec3 rd{0.5}, rs{0.05};
    double nu = 100.0, nv = 100.0;
};

// The simplified isotropic model the thesis fits (seed 000 eq. 4.28):
// cd/π + (ns + 1)/(8π) (n·h)^ns / ((h·v) max(n·l, n·v)) cs.
struct AshikhminShirleyFit {
    glm::dvec3 cd{0.2}, cs{0.2};
    double ns = 50.0;
};

// Models the fitter offers besides the thesis' (fit/fit_models.cpp); each has a technique in
// effects/brdf/analytic.fx.
// Cook-Torrance with GGX: kd/π + D G F / (4 (n·l)(n·v)), D = GGX of width α (not roughness²), G the
// height-correlated Smith term of GGX (Heitz 2014), F Fresnel-Schlick with F0 per channel.
struct CookTorranceGGX {
    glm::dvec3 kd{0.1}, f0{0.04};
    double alpha = 0.2;
};

// Cook-Torrance as Cook and Torrance wrote it, with Schlick's F0: kd/π + D G F / (4 (n·l)(n·v)),
// normalised Beckmann D of rms slope m, the V-cavity G, Fresnel-Schlick.
struct CookTorranceBeckmannSchlick {
    glm::dvec3 kd{0.1}, f0{0.04};
    double m = 0.2;
};

// Normalised Blinn-Phong: kd/π + ks (n + 8)/(8π) (n·h)ⁿ.
struct BlinnPhong {
    glm::dvec3 kd{0.5}, ks{0.2};
    double exponent = 50.0;
};

// Ward's isotropic model (1992): kd/π + ks exp(−tan²θh / α²) / (4π α² √((n·l)(n·v))).
struct Ward {
    glm::dvec3 kd{0.5}, ks{0.1};
    double alpha = 0.15;
};

// The height-correlated Smith masking-shadowing of GGX: 1 / (1 + Λ(n·l) + Λ(n·v)),
// Λ(x) = (√(1 + α² (1 − x²)/x²) − 1) / 2.
double smith_ggx_correlated(double n_dot_l, double n_dot_v, double alpha);

glm::dvec3 evaluate(const Lambert& model, const Directions& d);
glm::dvec3 evaluate(const MetallicRoughness& model, const Directions& d);
glm::dvec3 evaluate(const ModifiedPhong& model, const Directions& d);
glm::dvec3 evaluate(const CookTorranceBeckmann& model, const Directions& d);
glm::dvec3 evaluate(const AshikhminShirley& model, const Directions& d);
glm::dvec3 evaluate(const AshikhminShirleyFit& model, const Directions& d);
glm::dvec3 evaluate(const CookTorranceGGX& model, const Directions& d);
glm::dvec3 evaluate(const CookTorranceBeckmannSchlick& model, const Directions& d);
glm::dvec3 evaluate(const BlinnPhong& model, const Directions& d);
glm::dvec3 evaluate(const Ward& model, const Directions& d);

}  // namespace fxview::brdf

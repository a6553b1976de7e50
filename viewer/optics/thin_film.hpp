// Exact reflectance of thin films and layer stacks (DOMAIN.md §3): the characteristic-matrix
// (transfer-matrix) method for any stack, and the closed forms for one film (Airy, eq. 47) and a
// free film such as a soap bubble (Sun, eq. 48/49). Lengths in nanometres, indices n + iκ.
#pragma once
#include <vector>

#include "optics/fresnel.hpp"

namespace fxview::optics {

struct Layer {
    Complex index;
    double thickness_nm = 0;
};

// Outer medium (where the light comes from), films from the top down, substrate (semi-infinite).
struct Stack {
    Complex outer{1.0, 0.0};
    std::vector<Layer> layers;
    Complex substrate{1.5, 0.0};
};

struct Response {
    double reflectance = 0;    // |r|²
    double transmittance = 0;  // power into the substrate (meaningful for a non-absorbing substrate)
};

// Characteristic matrices (Born & Wolf 1.6, Macleod 2.2) with tilted admittances n cosθ (s) and
// n / cosθ (p). `cos_outer` is cos θ0 in the outer medium, which must be lossless.
Response transfer_matrix(const Stack& stack, double wavelength_nm, double cos_outer, Polarisation polarisation);
// The mean of both polarisations (unpolarised light).
double transfer_matrix_reflectance(const Stack& stack, double wavelength_nm, double cos_outer);

// Airy's sum for one film of real index n1 between real n0 and n2, per polarisation (eq. 47):
// R = (r01² + r12² + 2 r01 r12 cos δ) / (1 + r01² r12² + 2 r01 r12 cos δ), δ = 4π n1 d cosθ1 / λ.
double airy_reflectance(double n0, double n1, double n2, double thickness_nm, double wavelength_nm, double cos0,
                        Polarisation polarisation);
double airy_reflectance(double n0, double n1, double n2, double thickness_nm, double wavelength_nm, double cos0);

// A free film of index n_film in a medium n_outer on both sides (eq. 48/49):
// R = 2r²(1 − cos δ) / (1 + r⁴ − 2r² cos δ) per polarisation, averaged.
double bubble_reflectance(double n_outer, double n_film, double thickness_nm, double wavelength_nm, double cos0);

}  // namespace fxview::optics

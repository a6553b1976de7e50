// Characteristic matrices (optics/thin_film.hpp) with everything that does not depend on the
// wavelength worked out once per stack and angle: each layer's n cos θ d and tilted admittances, the
// outer medium's and the substrate's. Per wavelength only the layers' phases remain, shared by both
// polarisations. For a lossless stack (real layer indices, no evanescent layer) every layer matrix
// [[cos δ, −i sin δ / η], [−i η sin δ, cos δ]] has a real diagonal and an imaginary off-diagonal, and
// so has any product of them: four real numbers per product instead of eight complex ones, and the
// repeated layers of a periodic stack (A, B, A, B, ...) share their cos δ and sin δ. What the CPU
// references of the multilayer films spend their time on.
#pragma once
#include <optional>
#include <utility>
#include <vector>

#include "optics/thin_film.hpp"

namespace fxview::optics {

class PreparedStack {
public:
    // Indices must not depend on the wavelength (prepare one stack per wavelength otherwise).
    PreparedStack(const Stack& stack, double cos_outer);
    Response response(double wavelength_nm, Polarisation polarisation) const;
    // Reflectance of s and p light at one wavelength.
    std::pair<double, double> reflectances(double wavelength_nm) const;

private:
    struct Layer {
        Complex path;           // n cos θ d: the phase thickness is 2π path / λ
        Complex eta_s, eta_p;   // tilted admittances n cos θ, n / cos θ
        int phase = 0;          // index into the distinct paths: repeated layers share cos δ, sin δ
        double inverse_eta_s = 0, inverse_eta_p = 0;  // lossless stacks: 1 / η, to multiply by
    };
    std::vector<Layer> layers_;
    std::vector<double> distinct_paths_;  // lossless stacks: the real paths of the distinct layers
    Complex eta0_s_, eta0_p_, eta_substrate_s_, eta_substrate_p_;
    bool lossless_ = true;
    std::optional<Response> grazing_;  // cos θ0 = 0: everything or nothing reflected
};

}  // namespace fxview::optics

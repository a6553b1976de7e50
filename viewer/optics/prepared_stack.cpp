#include "optics/prepared_stack.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace fxview::optics {
namespace {

using Matrix = std::array<Complex, 4>;  // row-major 2x2

Matrix multiply(const Matrix& a, const Matrix& b) {
    return {a[0] * b[0] + a[1] * b[2], a[0] * b[1] + a[1] * b[3], a[2] * b[0] + a[3] * b[2], a[2] * b[1] + a[3] * b[3]};
}

// A lossless product [[a, −i b], [−i e, d]] (a, b, e, d real) times a layer's [[c, −i s/η], [−i η s, c]].
struct Lossless {
    double a = 1, b = 0, e = 0, d = 1;
    void multiply(double c, double s_over_eta, double eta_s) {
        const double na = a * c - b * eta_s, nb = a * s_over_eta + b * c, ne = e * c + d * eta_s, nd = d * c - e * s_over_eta;
        a = na, b = nb, e = ne, d = nd;
    }
    Matrix matrix() const { return {Complex(a, 0.0), Complex(0.0, -b), Complex(0.0, -e), Complex(d, 0.0)}; }
};

Response finish(const Matrix& product, Complex eta0, Complex eta_substrate) {
    const Complex b = product[0] + product[1] * eta_substrate, c = product[2] + product[3] * eta_substrate;
    const Complex denominator = eta0 * b + c;
    Response response;
    response.reflectance = std::norm((eta0 * b - c) / denominator);
    response.transmittance = 4.0 * eta0.real() * eta_substrate.real() / std::norm(denominator);
    return response;
}

}  // namespace

PreparedStack::PreparedStack(const Stack& stack, double cos_outer) {
    // Grazing incidence reflects everything (r -> -1 in both polarisations) as soon as the stack has
    // any interface; an index-matched stack has none and transmits everything. The p admittance
    // n / cos would divide by zero there.
    if (cos_outer <= 0.0) {
        bool matched = stack.substrate == Complex(stack.outer);
        for (const optics::Layer& layer : stack.layers) matched = matched && layer.index == Complex(stack.outer);
        grazing_ = matched ? Response{0.0, 1.0} : Response{1.0, 0.0};
        return;
    }
    eta0_s_ = stack.outer * cos_outer;
    eta0_p_ = stack.outer / cos_outer;
    for (const optics::Layer& layer : stack.layers) {
        const Complex cos_j = refracted_cos(stack.outer, layer.index, cos_outer);
        // With n̂ = n + iκ and fields ~ exp(i(kz − ωt)) a layer's phase thickness has Im δ ≥ 0 and the
        // matrix carries −i (Born & Wolf's sign); Macleod's +i belongs to n − iκ.
        layers_.push_back({layer.index * cos_j * layer.thickness_nm, layer.index * cos_j, layer.index / cos_j});
        lossless_ = lossless_ && layer.index.imag() == 0.0 && cos_j.imag() == 0.0;
    }
    for (Layer& layer : layers_) {
        layer.inverse_eta_s = 1.0 / layer.eta_s.real();
        layer.inverse_eta_p = 1.0 / layer.eta_p.real();
        const auto same = std::find(distinct_paths_.begin(), distinct_paths_.end(), layer.path.real());
        layer.phase = static_cast<int>(same - distinct_paths_.begin());
        if (same == distinct_paths_.end()) distinct_paths_.push_back(layer.path.real());
    }
    const Complex cos_substrate = refracted_cos(stack.outer, stack.substrate, cos_outer);
    eta_substrate_s_ = stack.substrate * cos_substrate;
    eta_substrate_p_ = stack.substrate / cos_substrate;
}

std::pair<double, double> PreparedStack::reflectances(double wavelength_nm) const {
    if (grazing_) return {grazing_->reflectance, grazing_->reflectance};
    const double k = 2.0 * std::numbers::pi / wavelength_nm;
    if (lossless_) {
        // cos δ and sin δ of each distinct layer (a few: without an allocation per wavelength).
        constexpr size_t kCached = 8;
        std::array<double, kCached> cosines{}, sines{};
        const bool cached = distinct_paths_.size() <= kCached;
        if (cached)
            for (size_t i = 0; i < distinct_paths_.size(); ++i) {
                cosines[i] = std::cos(k * distinct_paths_[i]);
                sines[i] = std::sin(k * distinct_paths_[i]);
            }
        Lossless s, p;
        for (const Layer& layer : layers_) {
            const size_t i = static_cast<size_t>(layer.phase);
            const double c = cached ? cosines[i] : std::cos(k * layer.path.real()), sine = cached ? sines[i] : std::sin(k * layer.path.real());
            s.multiply(c, sine * layer.inverse_eta_s, layer.eta_s.real() * sine);
            p.multiply(c, sine * layer.inverse_eta_p, layer.eta_p.real() * sine);
        }
        return {finish(s.matrix(), eta0_s_, eta_substrate_s_).reflectance, finish(p.matrix(), eta0_p_, eta_substrate_p_).reflectance};
    }
    Matrix s{1.0, 0.0, 0.0, 1.0}, p = s;
    const Complex minus_i(0.0, -1.0);
    for (const Layer& layer : layers_) {
        const Complex delta = k * layer.path, c = std::cos(delta), sine = std::sin(delta);
        s = multiply(s, {c, minus_i * sine / layer.eta_s, minus_i * layer.eta_s * sine, c});
        p = multiply(p, {c, minus_i * sine / layer.eta_p, minus_i * layer.eta_p * sine, c});
    }
    return {finish(s, eta0_s_, eta_substrate_s_).reflectance, finish(p, eta0_p_, eta_substrate_p_).reflectance};
}

Response PreparedStack::response(double wavelength_nm, Polarisation polarisation) const {
    if (grazing_) return *grazing_;
    const bool s_light = polarisation == Polarisation::S;
    const Complex k = 2.0 * std::numbers::pi / wavelength_nm, minus_i(0.0, -1.0);
    Matrix product{1.0, 0.0, 0.0, 1.0};
    for (const Layer& layer : layers_) {
        const Complex delta = k * layer.path, c = std::cos(delta), sine = std::sin(delta), eta = s_light ? layer.eta_s : layer.eta_p;
        product = multiply(product, {c, minus_i * sine / eta, minus_i * eta * sine, c});
    }
    return finish(product, s_light ? eta0_s_ : eta0_p_, s_light ? eta_substrate_s_ : eta_substrate_p_);
}

}  // namespace fxview::optics

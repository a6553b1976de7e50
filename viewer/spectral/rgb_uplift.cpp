#include "spectral/rgb_uplift.hpp"

#include <algorithm>
#include <cmath>
#include <thread>

#include "spectral/generators.hpp"
#include "spectral/level_of_detail.hpp"

namespace fxview::spectral {

namespace {

double sigmoid(double x) {
    if (std::isinf(x)) return x > 0 ? 1.0 : 0.0;
    return 0.5 + x / (2.0 * std::sqrt(1.0 + x * x));
}

double smoothstep(double x) { return x * x * (3.0 - 2.0 * x); }

// Solves the 3x3 system a x = b by Cramer's rule; false where a is singular.
bool solve3(const std::array<Vec3, 3>& a, const Vec3& b, Vec3& x) {
    const auto det = [](const Vec3& c0, const Vec3& c1, const Vec3& c2) {
        return c0[0] * (c1[1] * c2[2] - c1[2] * c2[1]) - c1[0] * (c0[1] * c2[2] - c0[2] * c2[1]) + c2[0] * (c0[1] * c1[2] - c0[2] * c1[1]);
    };
    // a given by columns.
    const double d = det(a[0], a[1], a[2]);
    if (!(std::abs(d) > 1e-300)) return false;
    x = {det(b, a[1], a[2]) / d, det(a[0], b, a[2]) / d, det(a[0], a[1], b) / d};
    return std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]);
}

Vec3 srgb_to_xyz(const Vec3& rgb) {
    // The inverse of eq. 9's matrix (colorimetry.cpp), D65 white.
    return {0.412453 * rgb[0] + 0.357580 * rgb[1] + 0.180423 * rgb[2], 0.212671 * rgb[0] + 0.715160 * rgb[1] + 0.072169 * rgb[2],
            0.019334 * rgb[0] + 0.119193 * rgb[1] + 0.950227 * rgb[2]};
}

}  // namespace

double SigmoidPolynomial::operator()(double nm) const {
    const double t = (nm - UpliftFit::kFirstNm) / double(UpliftFit::kLastNm - UpliftFit::kFirstNm);
    return sigmoid((c0 * t + c1) * t + c2);
}

UpliftFit::UpliftFit(const Observer& observer) {
    const Spectrum d65 = cie_daylight(6504.0);
    double ybar = 0.0, luminance = 0.0;
    for (int nm = kFirstNm; nm <= kLastNm; ++nm) {
        ybar += observer.y.at(nm);
        luminance += observer.y.at(nm) * d65.at(nm);
    }
    for (int nm = kFirstNm; nm <= kLastNm; ++nm) {
        const double light = d65.at(nm) * ybar / luminance;
        illuminant_.push_back(light);
        t_.push_back((nm - kFirstNm) / double(kLastNm - kFirstNm));
        to_xyz_[0].push_back(observer.x.at(nm) * light / ybar);
        to_xyz_[1].push_back(observer.y.at(nm) * light / ybar);
        to_xyz_[2].push_back(observer.z.at(nm) * light / ybar);
    }
    white_ = srgb_to_xyz({1.0, 1.0, 1.0});
}

Vec3 UpliftFit::lab(const SigmoidPolynomial& s) const {
    Vec3 xyz{0.0, 0.0, 0.0};
    for (size_t i = 0; i < t_.size(); ++i) {
        const double r = sigmoid((s.c0 * t_[i] + s.c1) * t_[i] + s.c2);
        for (int k = 0; k < 3; ++k) xyz[static_cast<size_t>(k)] += r * to_xyz_[static_cast<size_t>(k)][i];
    }
    return xyz_to_lab(xyz, white_);
}

Vec3 UpliftFit::rgb(const SigmoidPolynomial& s) const {
    Vec3 xyz{0.0, 0.0, 0.0};
    for (size_t i = 0; i < t_.size(); ++i)
        for (int k = 0; k < 3; ++k) xyz[static_cast<size_t>(k)] += s(kFirstNm + static_cast<double>(i)) * to_xyz_[static_cast<size_t>(k)][i];
    return xyz_to_linear_srgb_unclipped(xyz);
}

Vec3 UpliftFit::lab_of_rgb(const Vec3& rgb) const { return xyz_to_lab(srgb_to_xyz(rgb), white_); }

SigmoidPolynomial UpliftFit::fit(const Vec3& rgb, SigmoidPolynomial c, double* residual_left) const {
    const Vec3 target = lab_of_rgb(rgb);
    const auto residual = [&](const SigmoidPolynomial& s) {
        const Vec3 l = lab(s);
        return Vec3{l[0] - target[0], l[1] - target[1], l[2] - target[2]};
    };
    const auto norm = [](const Vec3& r) { return std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]); };
    Vec3 r = residual(c);
    for (int step = 0; step < 15 && norm(r) >= 1e-6; ++step) {
        // Jacobian by central differences (rgb2spec_opt's step).
        constexpr double h = 1e-5;
        std::array<Vec3, 3> jacobian{};
        for (int j = 0; j < 3; ++j) {
            SigmoidPolynomial up = c, down = c;
            (j == 0 ? up.c0 : j == 1 ? up.c1 : up.c2) += h;
            (j == 0 ? down.c0 : j == 1 ? down.c1 : down.c2) -= h;
            const Vec3 a = residual(up), b = residual(down);
            for (int k = 0; k < 3; ++k) jacobian[static_cast<size_t>(j)][static_cast<size_t>(k)] = (a[static_cast<size_t>(k)] - b[static_cast<size_t>(k)]) / (2 * h);
        }
        Vec3 delta;
        if (!solve3(jacobian, r, delta)) break;
        // The Gauss-Newton step, halved until it lowers the residual: the saturated corners (pure
        // blue at full brightness) otherwise oscillate between two states of the bound below.
        bool improved = false;
        for (double t = 1.0; t > 1e-3 && !improved; t *= 0.5) {
            SigmoidPolynomial next{c.c0 - t * delta[0], c.c1 - t * delta[1], c.c2 - t * delta[2]};
            // Keep the coefficients bounded (rgb2spec_opt): saturated corners would otherwise run away.
            const double largest = std::max({next.c0, next.c1, next.c2});
            if (largest > 200.0) next = {next.c0 * 200.0 / largest, next.c1 * 200.0 / largest, next.c2 * 200.0 / largest};
            const Vec3 next_r = residual(next);
            if (norm(next_r) < norm(r)) {
                c = next;
                r = next_r;
                improved = true;
            }
        }
        if (!improved) break;
    }
    if (residual_left) *residual_left = norm(r);
    return c;
}

UpliftTable make_uplift_table(const UpliftFit& fit, int resolution) {
    UpliftTable table;
    table.resolution = resolution;
    for (int k = 0; k < resolution; ++k) table.scale.push_back(static_cast<float>(smoothstep(smoothstep(k / double(resolution - 1)))));
    const size_t n = static_cast<size_t>(resolution);
    table.coefficients.assign(3 * n * n * n * 3, 0.0f);
    std::vector<std::vector<double>> worst(3 * n, std::vector<double>(n, 0.0));  // per task, per scale node
    const auto row = [&](size_t task) {
        const int largest = static_cast<int>(task / n), j = static_cast<int>(task % n);
        const double y = j / double(resolution - 1);
        for (int i = 0; i < resolution; ++i) {
            const double x = i / double(resolution - 1);
            const int start = resolution / 5;
            // Up from a fifth of the scale, then down from it, each node starting from the last.
            for (int direction : {1, -1}) {
                SigmoidPolynomial c;
                for (int k = start; k >= 1 && k < resolution; k += direction) {
                    const double b = table.scale[static_cast<size_t>(k)];
                    Vec3 rgb{};
                    rgb[static_cast<size_t>(largest)] = b;
                    rgb[static_cast<size_t>((largest + 1) % 3)] = x * b;
                    rgb[static_cast<size_t>((largest + 2) % 3)] = y * b;
                    double residual = 0.0;
                    c = fit.fit(rgb, c, &residual);
                    worst[task][static_cast<size_t>(k)] = std::max(worst[task][static_cast<size_t>(k)], residual);
                    for (int node : {k, k == 1 ? 0 : k}) {  // black (node 0) has no colour to fit: node 1's shape
                        const size_t at = (((static_cast<size_t>(largest) * n + static_cast<size_t>(node)) * n + static_cast<size_t>(j)) * n + static_cast<size_t>(i)) * 3;
                        table.coefficients[at] = static_cast<float>(c.c0);
                        table.coefficients[at + 1] = static_cast<float>(c.c1);
                        table.coefficients[at + 2] = static_cast<float>(c.c2);
                    }
                }
            }
        }
    };
    const size_t tasks = 3 * n, cores = std::max(1u, std::thread::hardware_concurrency());
    {
        std::vector<std::jthread> workers;
        for (size_t t = 0; t < cores; ++t)
            workers.emplace_back([&, t] {
                for (size_t task = t; task < tasks; task += cores) row(task);
            });
    }
    table.worst_residual.assign(n, 0.0);
    for (const auto& per_task : worst)
        for (size_t k = 0; k < n; ++k) table.worst_residual[k] = std::max(table.worst_residual[k], per_task[k]);
    return table;
}

SigmoidPolynomial UpliftTable::lookup(const Vec3& input) const {
    Vec3 rgb{};
    for (size_t k = 0; k < 3; ++k) rgb[k] = std::isnan(input[k]) ? 0.0 : std::clamp(input[k], 0.0, 1.0);
    if (rgb[0] == rgb[1] && rgb[1] == rgb[2]) {
        // A grey is the constant reflectance S(c2) = rgb (Jakob & Hanika, as pbrt-v4).
        const double v = rgb[0];
        if (v <= 0.0 || v >= 1.0) return {0.0, 0.0, v <= 0.0 ? -INFINITY : INFINITY};
        return {0.0, 0.0, (v - 0.5) / std::sqrt(v * (1.0 - v))};
    }
    if (!(std::max({rgb[0], rgb[1], rgb[2]}) > 0.0)) return {0.0, 0.0, -INFINITY};
    const size_t largest = rgb[0] >= rgb[1] ? (rgb[0] >= rgb[2] ? 0 : 2) : (rgb[1] >= rgb[2] ? 1 : 2);
    const double z = rgb[largest], last = resolution - 1;
    const double x = rgb[(largest + 1) % 3] / z * last, y = rgb[(largest + 2) % 3] / z * last;
    const int xi = std::min(static_cast<int>(x), resolution - 2), yi = std::min(static_cast<int>(y), resolution - 2);
    const int zi = std::clamp(static_cast<int>(std::upper_bound(scale.begin(), scale.end(), static_cast<float>(z)) - scale.begin()) - 1, 0, resolution - 2);
    const double dx = x - xi, dy = y - yi;
    const double dz = std::clamp((z - scale[static_cast<size_t>(zi)]) / (scale[static_cast<size_t>(zi) + 1] - scale[static_cast<size_t>(zi)]), 0.0, 1.0);
    const size_t n = static_cast<size_t>(resolution);
    const auto at = [&](int k, int j, int i, int c) {
        return double(coefficients[(((largest * n + static_cast<size_t>(k)) * n + static_cast<size_t>(j)) * n + static_cast<size_t>(i)) * 3 + static_cast<size_t>(c)]);
    };
    std::array<double, 3> c{};
    for (int channel = 0; channel < 3; ++channel) {
        const auto lerp = [](double a, double b, double t) { return a + (b - a) * t; };
        const auto plane = [&](int k) {
            return lerp(lerp(at(k, yi, xi, channel), at(k, yi, xi + 1, channel), dx), lerp(at(k, yi + 1, xi, channel), at(k, yi + 1, xi + 1, channel), dx), dy);
        };
        c[static_cast<size_t>(channel)] = lerp(plane(zi), plane(zi + 1), dz);
    }
    return {c[0], c[1], c[2]};
}

UpliftedRadiance uplift_radiance(const Vec3& input, const UpliftTable& table) {
    const Vec3 rgb{std::max(input[0], 0.0), std::max(input[1], 0.0), std::max(input[2], 0.0)};
    const double m = std::max({rgb[0], rgb[1], rgb[2]});
    if (!(m > 0.0) || !std::isfinite(m)) return {};
    const double scale = 2.0 * m;
    return {scale, table.lookup({rgb[0] / scale, rgb[1] / scale, rgb[2] / scale})};
}

}  // namespace fxview::spectral

#include "fit/merl.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "core/error.hpp"
#include "core/limits.hpp"

namespace fxview::fit {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr size_t kCount = static_cast<size_t>(kMerlThetaH) * kMerlThetaD * kMerlPhiD;
constexpr std::array<double, 3> kScale{1.0 / 1500.0, 1.15 / 1500.0, 1.66 / 1500.0};

// Rotation of v about a unit axis by angle (Rodrigues), as BRDFRead.cpp's rotate_vector.
glm::dvec3 rotate(const glm::dvec3& v, const glm::dvec3& axis, double angle) {
    const double c = std::cos(angle), s = std::sin(angle);
    return v * c + axis * glm::dot(v, axis) * (1.0 - c) + glm::cross(axis, v) * s;
}

}  // namespace

std::array<int, 3> merl_bins(const glm::dvec3& l, const glm::dvec3& v) {
    const glm::dvec3 half = glm::normalize(l + v);
    const double theta_half = std::acos(std::clamp(half.z, -1.0, 1.0));
    const double phi_half = std::atan2(half.y, half.x);
    const glm::dvec3 diff = rotate(rotate(l, {0, 0, 1}, -phi_half), {0, 1, 0}, -theta_half);
    const double theta_diff = std::acos(std::clamp(diff.z, -1.0, 1.0));
    double phi_diff = std::atan2(diff.y, diff.x);
    if (phi_diff < 0) phi_diff += kPi;  // reciprocity: φd and φd + π are the same sample
    int h = 0;
    if (theta_half > 0) h = static_cast<int>(std::sqrt(theta_half / (kPi / 2) * kMerlThetaH * kMerlThetaH));
    const int d = static_cast<int>(theta_diff / (kPi / 2) * kMerlThetaD);
    const int p = static_cast<int>(phi_diff / kPi * kMerlPhiD);
    return {std::clamp(h, 0, kMerlThetaH - 1), std::clamp(d, 0, kMerlThetaD - 1), std::clamp(p, 0, kMerlPhiD - 1)};
}

std::array<double, 3> MerlBrdf::bin(int h, int d, int p) const {
    const size_t index = static_cast<size_t>(p) + static_cast<size_t>(d) * kMerlPhiD + static_cast<size_t>(h) * kMerlPhiD * kMerlThetaD;
    std::array<double, 3> rgb{};
    for (size_t c = 0; c < 3; ++c) rgb[c] = data[index + c * kCount] * kScale[c];
    return rgb;
}

std::array<double, 3> MerlBrdf::lookup(const glm::dvec3& l, const glm::dvec3& v) const {
    const auto [h, d, p] = merl_bins(l, v);
    std::array<double, 3> rgb = bin(h, d, p);
    for (double& c : rgb) c = std::max(c, 0.0);  // negative: not measured
    return rgb;
}

MerlBrdf read_merl(const std::string& path, const ResourceLimits& limits) {
    std::error_code error;
    if (std::filesystem::is_directory(path, error)) throw Error(path + ": is a folder, not a MERL file");
    checked_file_size(path, limits);
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(path + ": cannot open");
    std::int32_t dims[3] = {};
    in.read(reinterpret_cast<char*>(dims), sizeof dims);
    // Each dimension is checked on its own first: their product of three int32 overflows even int64.
    if (!in || dims[0] != kMerlThetaH || dims[1] != kMerlThetaD || dims[2] != kMerlPhiD)
        // The header's bytes are not quoted: any file's first bytes (environment text of
        // /proc/self/environ, a key file) would reach the message as integers.
        throw Error(path + ": not a MERL BRDF (its header does not give the dimensions 90 x 90 x 180)");
    MerlBrdf merl;
    merl.data.resize(3 * kCount);
    in.read(reinterpret_cast<char*>(merl.data.data()), static_cast<std::streamsize>(merl.data.size() * sizeof(double)));
    if (!in) throw Error(path + ": truncated (a MERL BRDF holds 3 x 1 458 000 doubles after the header)");
    if (in.peek() != std::char_traits<char>::eof()) throw Error(path + ": holds more bytes than a MERL BRDF (3 x 1 458 000 doubles after the header)");
    for (double v : merl.data)
        if (!std::isfinite(v)) throw Error(path + ": holds a value that is not a finite number");
    return merl;
}

void write_merl(const MerlBrdf& merl, const std::string& path) {
    std::ofstream out(path, std::ios::binary);
    const std::int32_t dims[3] = {kMerlThetaH, kMerlThetaD, kMerlPhiD};
    out.write(reinterpret_cast<const char*>(dims), sizeof dims);
    out.write(reinterpret_cast<const char*>(merl.data.data()), static_cast<std::streamsize>(merl.data.size() * sizeof(double)));
    if (!out) throw Error(path + ": cannot write");
}

BinDirections merl_bin_centre(int h, int d, int p) {
    const double theta_h = std::pow((h + 0.5) / kMerlThetaH, 2.0) * kPi / 2;
    const double theta_d = (d + 0.5) / kMerlThetaD * kPi / 2, phi_d = (p + 0.5) / kMerlPhiD * kPi;
    const glm::dvec3 half(std::sin(theta_h), 0.0, std::cos(theta_h));
    // The difference vector (θd, φd) about the half vector, turned by θh about y.
    const glm::dvec3 diff(std::sin(theta_d) * std::cos(phi_d), std::sin(theta_d) * std::sin(phi_d), std::cos(theta_d));
    const glm::dvec3 l = rotate(diff, {0, 1, 0}, theta_h);
    return {l, 2.0 * glm::dot(l, half) * half - l, theta_h, theta_d};
}

MerlBrdf tabulate_merl(const std::function<std::array<double, 3>(const glm::dvec3& l, const glm::dvec3& v)>& f) {
    MerlBrdf merl;
    merl.data.assign(3 * kCount, -1.0);  // below the horizon: unmeasured, as in the database
    for (int h = 0; h < kMerlThetaH; ++h)
        for (int d = 0; d < kMerlThetaD; ++d)
            for (int p = 0; p < kMerlPhiD; ++p) {
                const BinDirections b = merl_bin_centre(h, d, p);
                if (b.l.z <= 0 || b.v.z <= 0) continue;
                const std::array<double, 3> value = f(b.l, b.v);
                const size_t index = static_cast<size_t>(p) + static_cast<size_t>(d) * kMerlPhiD + static_cast<size_t>(h) * kMerlPhiD * kMerlThetaD;
                for (size_t c = 0; c < 3; ++c) merl.data[index + c * kCount] = value[c] / kScale[c];
            }
    return merl;
}

BrdfGrid merl_to_grid(const MerlBrdf& merl, const BrdfGrid& grid) {
    return tabulate(grid, [&](const glm::dvec3& l, const glm::dvec3& v) { return merl.lookup(l, v); });
}

}  // namespace fxview::fit

#include "spectral/color_difference.hpp"

#include <cmath>
#include <numbers>

namespace fxview::spectral {
namespace {

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

// Hue angle in degrees, 0..360; 0 for a neutral colour (Sharma's convention).
double hue_degrees(double b, double a_prime) {
    if (a_prime == 0.0 && b == 0.0) return 0.0;
    const double h = std::atan2(b, a_prime) * 180.0 / std::numbers::pi;
    return h < 0.0 ? h + 360.0 : h;
}

double pow7_ratio(double c) {
    const double c7 = std::pow(c, 7.0);
    return std::sqrt(c7 / (c7 + std::pow(25.0, 7.0)));
}

}  // namespace

double delta_e_2000(const Vec3& lab1, const Vec3& lab2) {
    const double c1 = std::hypot(lab1[1], lab1[2]), c2 = std::hypot(lab2[1], lab2[2]);
    const double g = 0.5 * (1.0 - pow7_ratio(0.5 * (c1 + c2)));
    const double a1 = (1.0 + g) * lab1[1], a2 = (1.0 + g) * lab2[1];
    const double c1p = std::hypot(a1, lab1[2]), c2p = std::hypot(a2, lab2[2]);
    const double h1 = hue_degrees(lab1[2], a1), h2 = hue_degrees(lab2[2], a2);
    const bool neutral = c1p * c2p == 0.0;

    const double delta_l = lab2[0] - lab1[0], delta_c = c2p - c1p;
    double delta_h_angle = neutral ? 0.0 : h2 - h1;
    if (delta_h_angle > 180.0) delta_h_angle -= 360.0;
    else if (delta_h_angle < -180.0) delta_h_angle += 360.0;
    const double delta_h = 2.0 * std::sqrt(c1p * c2p) * std::sin(radians(delta_h_angle / 2.0));

    const double l_mean = 0.5 * (lab1[0] + lab2[0]), c_mean = 0.5 * (c1p + c2p);
    double h_mean = h1 + h2;
    if (!neutral) {
        if (std::abs(h1 - h2) <= 180.0) h_mean *= 0.5;
        else h_mean = h_mean < 360.0 ? 0.5 * (h_mean + 360.0) : 0.5 * (h_mean - 360.0);
    }
    const double t = 1.0 - 0.17 * std::cos(radians(h_mean - 30.0)) + 0.24 * std::cos(radians(2.0 * h_mean)) +
                     0.32 * std::cos(radians(3.0 * h_mean + 6.0)) - 0.20 * std::cos(radians(4.0 * h_mean - 63.0));
    const double delta_theta = 30.0 * std::exp(-std::pow((h_mean - 275.0) / 25.0, 2.0));
    const double rc = 2.0 * pow7_ratio(c_mean);
    const double l50 = (l_mean - 50.0) * (l_mean - 50.0);
    const double sl = 1.0 + 0.015 * l50 / std::sqrt(20.0 + l50), sc = 1.0 + 0.045 * c_mean, sh = 1.0 + 0.015 * c_mean * t;
    const double rt = -std::sin(radians(2.0 * delta_theta)) * rc;
    const double l = delta_l / sl, c = delta_c / sc, h = delta_h / sh;
    return std::sqrt(l * l + c * c + h * h + rt * c * h);
}

}  // namespace fxview::spectral

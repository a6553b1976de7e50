#include "scene/light_intensity.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>

#include "core/error.hpp"
#include "scene/scene.hpp"

namespace fxview::scene {
namespace {

constexpr double kPi = std::numbers::pi;

}  // namespace

std::optional<LightIntensity> parse_light_intensity(std::string_view text) {
    const std::string s(text);
    // A plain decimal number (no hexadecimal, no inf or nan), then the unit.
    const size_t used = s.find_first_not_of("0123456789.eE+-");
    if (used == 0 || used == std::string::npos) return std::nullopt;
    double value = 0;
    try {
        size_t parsed = 0;
        value = std::stod(s.substr(0, used), &parsed);
        if (parsed != used) return std::nullopt;
    } catch (const std::exception&) {
        return std::nullopt;
    }
    std::string unit = s.substr(used);
    while (!unit.empty() && unit.front() == ' ') unit.erase(unit.begin());
    if (!std::isfinite(value) || value < 0 || value > kMaxLightIntensity) return std::nullopt;
    LightIntensity intensity;
    intensity.value = value;
    if (unit == "lx" || unit == "lux") intensity.unit = LightIntensity::Unit::Lux;
    else if (unit == "lm") intensity.unit = LightIntensity::Unit::Lumen;
    else if (unit == "cd") intensity.unit = LightIntensity::Unit::Candela;
    else if (unit == "nit" || unit == "nits" || unit == "cd/m2") intensity.unit = LightIntensity::Unit::Nit;
    else return std::nullopt;
    return intensity;
}

const char* unit_name(LightIntensity::Unit unit) {
    switch (unit) {
        case LightIntensity::Unit::Lumen: return "lm";
        case LightIntensity::Unit::Candela: return "cd";
        case LightIntensity::Unit::Nit: return "nit";
        default: return "lx";
    }
}

std::string to_string(const LightIntensity& intensity) {
    std::string number = std::to_string(intensity.value);
    while (number.find('.') != std::string::npos && (number.back() == '0' || number.back() == '.')) number.pop_back();
    return number + " " + unit_name(intensity.unit);
}

double illuminance_at_origin(const Light& light, const LightIntensity& intensity) {
    const LightGeometry g = light_geometry(light);
    const double distance = glm::length(g.centre), value = intensity.value;
    // The effects take E in float: what passes 1e30 lx would overflow their sums.
    const auto checked = [](double lux) {
        if (!(lux <= kMaxLightIntensity)) {
            char text[64];
            std::snprintf(text, sizeof text, "%.3g", lux);
            throw UsageError(std::string("--light-intensity: ") + text + " lx at the origin is beyond 1e30");
        }
        return lux;
    };
    if (intensity.unit == LightIntensity::Unit::Lux) return value;
    if (g.is_flat()) {
        // A one-sided Lambertian emitter of luminance L: flux π L A, axial intensity L A; E at the origin
        // is L times the irradiance of unit radiance there (scene/light_geometry.hpp's closed forms).
        const double area = g.area();
        const double luminance = intensity.unit == LightIntensity::Unit::Nit       ? value
                                 : intensity.unit == LightIntensity::Unit::Candela ? value / area
                                                                                   : value / (kPi * area);
        return checked(luminance * flat_light_irradiance_at_origin(g.shape, g.half_size, distance));
    }
    if (intensity.unit == LightIntensity::Unit::Nit) {
        // A sphere of luminance L seen under sin α = R / D: E = π L sin²α (its radiance over the disc it shows).
        if (g.radius <= 0) throw UsageError("--light-intensity: a point light has no surface, so no luminance; give lx, lm or cd");
        if (g.radius >= distance) throw UsageError("--light-intensity: the origin lies inside the sphere light; give lx");
        return checked(kPi * value * (g.radius / distance) * (g.radius / distance));
    }
    if (distance <= 0) throw UsageError("--light-intensity: the light sits at the origin; give lx");
    // An isotropic point or sphere: I = Φ / 4π, E = I / D².
    const double candela = intensity.unit == LightIntensity::Unit::Candela ? value : value / (4.0 * kPi);
    return checked(candela / (distance * distance));
}

}  // namespace fxview::scene

// The scene light's intensity in photometric units (--light-intensity, a preset's "light_intensity",
// the Scene tab): the illuminance it gives at the origin (lx), its luminous flux (lm), its luminous
// intensity (cd: a point's in every direction, a flat light's along its axis) or the luminance of its
// surface (nit = cd/m²). Each comes down to the illuminance E at the origin on a surface facing the
// light, which effects take through parameters annotated SceneLight = "irradiance" (E itself) or
// "spectral-brightness" (E / (π Y) for the light spectrum's luminance Y): with scene radiance read as
// luminance in cd/m², a white Lambertian surface facing the light then shows E / π.
#pragma once
#include <optional>
#include <string>
#include <string_view>

namespace fxview::scene {

struct Light;

struct LightIntensity {
    enum class Unit { Lux, Lumen, Candela, Nit };
    double value = 0;
    Unit unit = Unit::Lux;
};

// The largest value and illuminance accepted: the effects sum E in float.
inline constexpr double kMaxLightIntensity = 1e30;

// "500lx", "800 lm", "120cd", "3000nit" (also "lux", "cd/m2"); empty for anything else (a number
// without a unit, a negative value or one above kMaxLightIntensity, hexadecimal, inf, nan).
std::optional<LightIntensity> parse_light_intensity(std::string_view text);
std::string to_string(const LightIntensity& intensity);  // "500 lx"
const char* unit_name(LightIntensity::Unit unit);

// E at the origin in lux. UsageError where the unit does not fit the light: a point has no luminance,
// and lumens or candela need the light away from the origin.
double illuminance_at_origin(const Light& light, const LightIntensity& intensity);

}  // namespace fxview::scene

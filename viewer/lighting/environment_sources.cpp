#include "lighting/environment_sources.hpp"

#include <functional>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <sstream>

#include "core/error.hpp"
#include "image/color_encoding.hpp"
#include "lighting/bright_sources.hpp"
#include "lighting/image_spectral_form.hpp"
#include "spectral/colorimetry.hpp"
#include "spectral/generators.hpp"
#include "texture/texture_file.hpp"

namespace fxview::lighting {
namespace {

constexpr double kPi = std::numbers::pi;

double smooth_box(double x, double half_width, double softness) {
    return std::clamp((half_width - std::abs(x)) / softness + 0.5, 0.0, 1.0);
}

// A soft rectangular light facing the origin, centred in direction (azimuth, elevation) in degrees,
// `width` x `height` degrees across.
double soft_box(const glm::dvec3& d, double azimuth, double elevation, double width, double height) {
    const double az = azimuth * kPi / 180.0, el = elevation * kPi / 180.0;
    const glm::dvec3 centre(std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az));
    const glm::dvec3 right = glm::normalize(glm::cross(glm::dvec3(0, 1, 0), centre));
    const glm::dvec3 up = glm::cross(centre, right);
    const double forward = glm::dot(d, centre);
    if (forward <= 0.0) return 0.0;
    const double x = std::atan2(glm::dot(d, right), forward) * 180.0 / kPi, y = std::atan2(glm::dot(d, up), forward) * 180.0 / kPi;
    return smooth_box(x, width / 2, 4.0) * smooth_box(y, height / 2, 4.0);
}

// CIE daylight at `kelvin` as linear sRGB with luminance 1.
glm::dvec3 daylight_rgb(double kelvin) {
    const spectral::Observer observer = spectral::load_observer("1931");
    const spectral::Vec3 xyz = spectral::spectrum_to_xyz(spectral::cie_daylight(kelvin), observer);
    const spectral::Vec3 rgb = spectral::xyz_to_linear_srgb_unclipped({xyz[0] / xyz[1], 1.0, xyz[2] / xyz[1]});
    return glm::max(glm::dvec3(rgb[0], rgb[1], rgb[2]), glm::dvec3(0.0));
}

// CIE daylight at `kelvin` over 360-830 nm at 1 nm with luminance 1 as SpectralForm defines it.
std::vector<double> daylight_spectrum(double kelvin) {
    const spectral::Observer observer = spectral::load_observer("1931");
    const spectral::Spectrum daylight = spectral::cie_daylight(kelvin);
    double ybar = 0, luminance = 0;
    for (int nm = SpectralForm::kFirstNm; nm <= SpectralForm::kLastNm; ++nm) {
        ybar += observer.y.at(nm);
        luminance += observer.y.at(nm) * daylight.at(nm);
    }
    std::vector<double> out;
    for (int nm = SpectralForm::kFirstNm; nm <= SpectralForm::kLastNm; ++nm) out.push_back(daylight.at(nm) * ybar / luminance);
    return out;
}

// CIE S 011 / ISO 15469 standard clear sky, type 12: relative luminance at zenith angle z, angle to the sun chi.
double clear_sky(double z, double chi) {
    const double a = -1.0, b = -0.32, c = 10.0, d = -3.0, e = 0.45;
    const double gradation = 1.0 + a * std::exp(b / std::max(std::cos(z), 1e-3));
    const double indicatrix = 1.0 + c * (std::exp(d * chi) - std::exp(d * kPi / 2)) + e * std::cos(chi) * std::cos(chi);
    return gradation * indicatrix;
}

Environment make_sky(const Sky& sky, int size) {
    const double el = sky.sun_elevation_degrees * kPi / 180.0;
    // The sun on the default camera's side (+Z), 40 degrees to its left: objects are front-lit.
    const double azimuth = -40.0 * kPi / 180.0;
    const glm::dvec3 sun(std::cos(el) * std::sin(azimuth), std::sin(el), std::cos(el) * std::cos(azimuth));
    const double sun_radius = 1.5 * kPi / 180.0;             // widened from 0.27 deg so that the cube resolves it; its irradiance is kept
    const double sun_solid_angle = 2.0 * kPi * (1.0 - std::cos(sun_radius));
    const glm::dvec3 sun_colour = daylight_rgb(sky.sun_cct), sky_colour = daylight_rgb(12000.0);
    // Sky luminance scaled so that the sky gives a horizontal surface 0.25 of the sun's irradiance on it
    // (a clear day: diffuse about a fifth of global), and sun + sky light a white horizontal Lambertian surface to 1.
    double sky_horizontal = 0.0;
    const int n = 256;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < 2 * n; ++j) {
            const double z = (i + 0.5) / n * kPi / 2, phi = (j + 0.5) / (2 * n) * 2 * kPi;
            const glm::dvec3 d(std::sin(z) * std::sin(phi), std::cos(z), std::sin(z) * std::cos(phi));
            sky_horizontal += clear_sky(z, std::acos(std::clamp(glm::dot(d, sun), -1.0, 1.0))) * std::cos(z) * std::sin(z) * (kPi / 2 / n) * (kPi / n);
        }
    // At the default elevation (35 deg) sun and sky light a white horizontal Lambertian surface to 1, the
    // sky giving a fifth of it (a clear day); the sun keeps that normal irradiance at other elevations,
    // so a lower sun lights horizontal surfaces less, as outdoors; the sky's horizontal share stays.
    const double default_sin = std::sin(35.0 * kPi / 180.0);
    const double sun_scale = 0.8 * kPi / default_sin, sky_scale = 0.2 * kPi / sky_horizontal;
    // A grey Lambertian ground of albedo 0.2 lit by this sky: radiance 0.2/π times the horizontal
    // irradiance of sun (sun_scale sin(elevation), in the sun's colour) and sky (0.2π, in the sky's):
    // 0.2 at the default elevation, 0.064 with the sun at 5°, dark once it has set.
    // The sky by its two spectra: the dome's weight (12000 K daylight) and the sun's (CCT), the ground
    // lit by both; its RGB is w_dome sky_colour + w_sun sun_colour.
    const auto weights = [=](const glm::dvec3& d) {  // by value: the exact form keeps it
        if (d.y < 0.0) return glm::dvec2(0.2 / kPi * sky_scale * sky_horizontal, 0.2 / kPi * sun_scale * std::max(std::sin(el), 0.0));
        const double chi = std::acos(std::clamp(glm::dot(d, sun), -1.0, 1.0));
        return glm::dvec2(sky_scale * clear_sky(std::acos(std::clamp(d.y, 0.0, 1.0)), chi), 0.0);
    };
    Environment environment;
    environment.radiance = tabulate(size, 2, [&](const glm::dvec3& d) {
        const glm::dvec2 w = weights(d);
        return glm::vec3(w.x * sky_colour + w.y * sun_colour);
    });
    environment.discs.push_back({sun, sun_radius, sun_scale / sun_solid_angle * sun_colour});
    const Environment weight_cube{tabulate(size, 2, [&](const glm::dvec3& d) { return glm::vec3(weights(d), 0.0); }),
                                  {{sun, sun_radius, glm::dvec3(0.0, sun_scale / sun_solid_angle, 0.0)}}, std::nullopt};
    environment.spectral = SpectralForm{weight_cube.radiance_with_discs(), {daylight_spectrum(12000.0), daylight_spectrum(sky.sun_cct), {}}, {},
                                        weight_cube.radiance, weight_cube.discs};
    environment.spectral->spectra[2].assign(environment.spectral->spectra[0].size(), 0.0);
    const double sun_cos = std::cos(sun_radius), sun_radiance = sun_scale / sun_solid_angle;
    environment.spectral->exact = [weights, sun, sun_cos, sun_radiance](const glm::dvec3& d) {
        const glm::dvec2 w = weights(glm::normalize(d));
        return glm::dvec3(w.x, w.y + (glm::dot(glm::normalize(d), sun) >= sun_cos ? sun_radiance : 0.0), 0.0);
    };
    return environment;
}

// A neutral environment of grey radiance: all in D65 (CIE daylight at 6504 K, the white of sRGB),
// so its spectral form is one spectrum weighted by the grey level. The studio (walls, floor and soft
// boxes are neutral) and the furnace are such.
Environment neutral_environment(int size, int supersampling, const std::function<glm::vec3(const glm::dvec3&)>& grey) {
    Environment environment{tabulate(size, supersampling, grey), {}, std::nullopt};
    environment.spectral = SpectralForm{tabulate(size, supersampling, [&](const glm::dvec3& d) { return glm::vec3(grey(d).g, 0.0f, 0.0f); }),
                                        {daylight_spectrum(6504.0), {}, {}},
                                        [grey](const glm::dvec3& d) { return glm::dvec3(grey(glm::normalize(d)).g, 0.0, 0.0); },
                                        FloatCube(0), {}};
    for (size_t k = 1; k < 3; ++k) environment.spectral->spectra[k].assign(environment.spectral->spectra[0].size(), 0.0);
    environment.spectral->map_weights = environment.spectral->weights;
    return environment;
}

// Finite is not enough: prefiltering and SH sum thousands of texels times weights in float, so a
// texel near float's maximum (an EXR value of 3e38, an RGBE exponent of 255) overflows to NaN
// pixels. The brightest real sources are far below the bound (the sun's disc: about 1.6e9 cd/m²).
constexpr float kMaxRadiance = 1e20f;

// Whether every RGB of `count` RGBA texels is a radiance the maps can hold (make_environment says
// which is not, after resampling).
bool finite_and_bounded(const float* rgba, size_t count) {
    for (size_t i = 0; i < count * 4; ++i)
        if (i % 4 != 3 && !(std::isfinite(rgba[i]) && rgba[i] >= 0.0f && rgba[i] <= kMaxRadiance)) return false;
    return true;
}

// An equirectangular image (-Z at its centre, +Y at the top) resampled onto the cube.
// Its bright small sources (a sun) are taken out into `discs` first, at the image's own resolution.
FloatCube from_equirectangular(const texture::TextureData& image, int size, std::vector<DiscLight>& discs) {
    texture::TextureData rgba = texture::convert(image, texture::PixelFormat::RGBA32F);
    const int width = rgba.width(), height = rgba.height();
    auto* texels = reinterpret_cast<float*>(rgba.faces[0][0].bytes.data());
    if (finite_and_bounded(texels, static_cast<size_t>(width) * height)) extract_bright_sources_equirectangular(texels, width, height, discs);
    const auto at = [&](int x, int y) {
        x = ((x % width) + width) % width;
        y = std::clamp(y, 0, height - 1);
        const float* p = texels + (static_cast<size_t>(y) * width + x) * 4;
        return glm::vec3(p[0], p[1], p[2]);
    };
    // Enough taps per cube texel to average the image's pixels under it.
    const int supersample = std::clamp(width / (4 * size), 1, 8) + 1;
    return tabulate(size, supersample, [&](const glm::dvec3& d) {
        const double u = 0.5 + std::atan2(d.x, -d.z) / (2 * kPi), v = std::acos(std::clamp(d.y, -1.0, 1.0)) / kPi;
        const double x = u * width - 0.5, y = v * height - 0.5;
        const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
        const float ax = static_cast<float>(x - x0), ay = static_cast<float>(y - y0);
        return glm::mix(glm::mix(at(x0, y0), at(x0 + 1, y0), ax), glm::mix(at(x0, y0 + 1), at(x0 + 1, y0 + 1), ax), ay);
    });
}

// A cube's faces (any size, 8-bit sRGB or float) resampled to `size`.
FloatCube from_cube(const texture::TextureData& data, int size) {
    const bool srgb = data.format == texture::PixelFormat::RGBA8;
    FloatCube source(data.width());
    for (int face = 0; face < 6; ++face)
        for (int y = 0; y < source.size; ++y)
            for (int x = 0; x < source.size; ++x) {
                float rgba[4];
                texture::read_texel(data, face, 0, x, y, rgba);
                glm::vec3 c(rgba[0], rgba[1], rgba[2]);
                if (srgb)  // 8-bit images hold display values: decode to linear
                    for (int k = 0; k < 3; ++k) c[k] = image::srgb_decode(c[k]);
                source.at(face, x, y) = c;
            }
    while (source.size >= 2 * size) source = downsample(source);
    return source.size == size ? source : tabulate(size, 2, [&](const glm::dvec3& d) { return sample_bilinear(source, d); });
}

std::vector<std::string> split(const std::string& text, char separator) {
    std::vector<std::string> parts;
    std::stringstream stream(text);
    for (std::string part; std::getline(stream, part, separator);) parts.push_back(part);
    return parts;
}

// The float radiance `data` becomes, added to what earlier files of the environment hold, checked
// against texture-bytes before it is converted (six 8-bit faces that each fit grow fourfold).
void check_float_budget(const texture::TextureData& data, std::int64_t& used, const ResourceLimits& limits, const std::string& file) {
    std::int64_t texels = 0;
    for (const auto& face : data.faces)
        if (!face.empty()) texels += static_cast<std::int64_t>(face[0].width) * face[0].height;
    used += texels * 16;
    check_limit(limits, "texture-bytes", used, file, "the environment's float radiance");
}

FloatCube from_files(const std::string& source, int size, const ResourceLimits& limits, std::vector<DiscLight>& discs) {
    const std::vector<std::string> files = split(source, ',');
    std::int64_t used = 0;
    if (files.size() == 6) {
        texture::TextureData cube;
        cube.type = texture::TextureType::Cube;
        for (const auto& file : files) {
            const texture::TextureData loaded = texture::load_texture_file(file, limits);
            check_float_budget(loaded, used, limits, file);
            texture::TextureData face = texture::convert(loaded, texture::PixelFormat::RGBA32F);
            if (face.width() != face.height() || (!cube.faces.empty() && face.width() != cube.width()))
                throw Error(file + ": the six faces of an environment must be equal squares");
            cube.faces.push_back(std::move(face.faces[0]));
        }
        cube.format = texture::PixelFormat::RGBA32F;
        return from_cube(cube, size);
    }
    if (files.size() != 1) throw Error("environment '" + source + "': one file, or six face files separated by commas");
    texture::TextureData data = texture::load_texture_file(source, limits);
    check_float_budget(data, used, limits, source);
    if (data.type == texture::TextureType::Cube) return from_cube(texture::convert(data, texture::PixelFormat::RGBA32F), size);
    if (data.width() == 2 * data.height()) return from_equirectangular(data, size, discs);
    if (data.width() * 3 == data.height() * 4 || data.width() * 4 == data.height() * 3)
        return from_cube(texture::convert(texture::split_cube_cross(data), texture::PixelFormat::RGBA32F), size);
    throw Error(source + ": an environment image must be equirectangular (width twice the height) or a cube cross (4x3 or 3x4 faces); this one is " +
                std::to_string(data.width()) + "x" + std::to_string(data.height()));
}

}  // namespace

double DiscLight::solid_angle() const { return 2.0 * kPi * (1.0 - std::cos(angular_radius)); }

namespace {

// A tangent frame about `centre` for points on a disc around it.
void disc_frame(const glm::dvec3& centre, glm::dvec3& dt, glm::dvec3& db) {
    const glm::dvec3 up = std::abs(centre.y) < 0.999 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
    dt = glm::normalize(glm::cross(up, centre));
    db = glm::cross(centre, dt);
}

}  // namespace

std::vector<glm::dvec3> DiscLight::quadrature(const glm::dvec3& centre, int count) const {
    glm::dvec3 dt, db;
    disc_frame(centre, dt, db);
    const double golden = kPi * (3.0 - std::sqrt(5.0));
    std::vector<glm::dvec3> points;
    points.reserve(static_cast<size_t>(count));
    for (int k = 0; k < count; ++k) {
        const double r = std::sqrt((k + 0.5) / count) * angular_radius, angle = golden * k;
        points.push_back(glm::normalize(centre + std::tan(r) * (std::cos(angle) * dt + std::sin(angle) * db)));
    }
    return points;
}

glm::dvec3 DiscLight::nearest(const glm::dvec3& centre, const glm::dvec3& towards, double radius) {
    const double c = std::clamp(glm::dot(centre, towards), -1.0, 1.0);
    if (c >= std::cos(radius)) return towards;
    const glm::dvec3 side = towards - c * centre;
    const double length = glm::length(side);
    if (length < 1e-8) return centre;  // the opposite way: every edge point is as near
    return std::cos(radius) * centre + std::sin(radius) * side / length;
}

double disc_widened_alpha(double alpha, double angular_radius) { return std::sqrt(alpha * alpha + 0.25 * angular_radius * angular_radius); }

FloatCube Environment::radiance_with_discs() const {
    if (discs.empty()) return radiance;
    FloatCube out = radiance;
    const int n = 4;  // n x n taps per texel near a disc's edge
    for (int face = 0; face < 6; ++face)
        for (int y = 0; y < out.size; ++y)
            for (int x = 0; x < out.size; ++x) {
                const glm::dvec3 centre = texel_direction(face, x, y, out.size);
                for (const DiscLight& disc : discs) {
                    // Texels farther than the disc plus a texel's diagonal cannot touch it.
                    if (std::acos(std::clamp(glm::dot(centre, disc.direction), -1.0, 1.0)) > disc.angular_radius + 3.0 / out.size) continue;
                    int inside = 0;
                    for (int b = 0; b < n; ++b)
                        for (int a = 0; a < n; ++a) {
                            const glm::dvec3 d = glm::normalize(cube_direction(face, (x + (a + 0.5) / n) / out.size, (y + (b + 0.5) / n) / out.size));
                            inside += glm::dot(d, disc.direction) > std::cos(disc.angular_radius);
                        }
                    out.at(face, x, y) += glm::vec3(disc.radiance * (static_cast<double>(inside) / (n * n)));
                }
            }
    return out;
}

glm::vec3 studio_radiance(const glm::dvec3& d) {
    // Walls and ceiling a dim neutral grey, brighter overhead; the floor darker towards the nadir.
    double base = d.y >= 0.0 ? 0.25 + 0.15 * d.y : 0.2 * (1.0 + d.y) + 0.04;
    base += 7.0 * soft_box(d, -40.0, 35.0, 50.0, 30.0);   // key light, front left
    base += 2.5 * soft_box(d, 70.0, 15.0, 30.0, 60.0);    // fill strip, right
    base += 4.0 * soft_box(d, 170.0, 50.0, 80.0, 15.0);   // rim strip, behind and above
    return glm::vec3(static_cast<float>(base));
}

Sky parse_sky(const std::string& source) {
    Sky sky;
    if (source == "sky") return sky;
    const std::vector<std::string> values = split(source.substr(4), ',');
    try {
        if (values.size() > 2 || values.empty() || source.back() == ',') throw std::invalid_argument("count");
        sky.sun_elevation_degrees = std::stod(values[0]);
        if (values.size() == 2) sky.sun_cct = std::stod(values[1]);
    } catch (const std::exception&) {
        throw UsageError("environment '" + source + "': sky, sky:ELEVATION or sky:ELEVATION,CCT (degrees, kelvin)");
    }
    if (!(sky.sun_elevation_degrees >= 0.0 && sky.sun_elevation_degrees <= 90.0))
        throw UsageError("environment '" + source + "': the sun's elevation must be 0-90 degrees");
    if (!(sky.sun_cct >= 4000.0 && sky.sun_cct <= 25000.0))
        throw UsageError("environment '" + source + "': CIE daylight is defined for 4000-25000 K");
    return sky;
}

Environment make_environment(const std::string& source, int size, const ResourceLimits& limits) {
    if (source.size() > kMaxEnvironmentSourceChars)
        throw UsageError("environment: " + std::to_string(source.size()) + " characters, longer than any list of six file names");
    if (source == "studio") return neutral_environment(size, 2, studio_radiance);
    if (source == "furnace") return neutral_environment(size, 1, [](const glm::dvec3&) { return glm::vec3(1.0f); });
    if (source == "sky" || source.rfind("sky:", 0) == 0) return make_sky(parse_sky(source), size);
    // A bare word that is no file is most likely a misspelt built-in name.
    std::error_code error;
    if (source.find_first_of("/.,") == std::string::npos && !std::filesystem::exists(source, error))
        throw UsageError("unknown environment '" + source + "' (studio, sky, sky:ELEVATION[,CCT], furnace, none, or an image file)");
    Environment environment;
    environment.radiance = from_files(source, size, limits, environment.discs);
    for (const auto& face : environment.radiance.faces)
        for (const glm::vec3& texel : face) {
            if (!std::isfinite(texel.r) || !std::isfinite(texel.g) || !std::isfinite(texel.b) || texel.r < 0 || texel.g < 0 || texel.b < 0)
                throw Error(source + ": the environment holds NaN, infinite or negative radiance");
            if (std::max({texel.r, texel.g, texel.b}) > kMaxRadiance)
                throw Error(source + ": the environment holds radiance above 1e20, beyond what float sums of its texels can hold");
        }
    extract_bright_sources(environment);  // a sun in cube faces (an equirectangular image's went before resampling)
    add_image_spectral_form(environment);
    return environment;
}

}  // namespace fxview::lighting

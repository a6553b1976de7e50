// Environment lighting: the CPU tables against integrals computed here by other means, the display
// transforms, and the rendered results the issue asks for (white furnace, metal presets).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <vector>
#include <numbers>

#include <nlohmann/json.hpp>

#include "image/display_transform.hpp"
#include "image/image_file.hpp"
#include "lighting/bright_sources.hpp"
#include "lighting/cube_map.hpp"
#include "lighting/environment_sources.hpp"
#include "lighting/image_based_lighting.hpp"
#include "spectral/colorimetry.hpp"
#include "texture/texture_file.hpp"
#include "test_support.hpp"

using namespace fxview;
using fxview::test::Result;
using fxview::test::run;
using fxview::test::temp_path;

namespace {
constexpr double kPi = std::numbers::pi;

// ∫ f_ss cos over the hemisphere for F0 = 1 (GGX, height-correlated Smith), by a midpoint rule in (θ, φ):
// no importance sampling, nothing shared with make_dfg_table but the BRDF's definition.
double albedo_by_quadrature(double nv, double roughness) {
    const double alpha = roughness * roughness;
    const glm::dvec3 v(std::sqrt(1 - nv * nv), 0, nv);
    const int n_theta = 600, n_phi = 300;
    double sum = 0;
    for (int i = 0; i < n_theta; ++i) {
        const double theta = (i + 0.5) / n_theta * kPi / 2;
        for (int j = 0; j < n_phi; ++j) {
            const double phi = (j + 0.5) / n_phi * kPi;  // symmetric about the plane of incidence: half, doubled
            const glm::dvec3 l(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
            const glm::dvec3 h = glm::normalize(l + v);
            // Height-correlated Smith, written out here: 1 / (1 + Λ(v) + Λ(l)).
            const auto lambda = [alpha](double c) { return 0.5 * (std::sqrt(1.0 + alpha * alpha * (1.0 - c * c) / (c * c)) - 1.0); };
            const double f = lighting::ggx_d(h.z, alpha) / (1.0 + lambda(nv) + lambda(l.z)) / (4 * nv * l.z);
            sum += 2 * f * l.z * std::sin(theta) * (kPi / 2 / n_theta) * (kPi / n_phi);
        }
    }
    return sum;
}

// Mean display value (R, G, B) and the spread of luma inside the sphere's silhouette.
struct Stats {
    glm::dvec3 mean{0.0};
    double luma_mean = 0, luma_sd = 0;
};
Stats sphere_stats(const std::string& png, double radius) {
    const texture::TextureData t = texture::load_stb_image(png);
    const int w = t.width(), h = t.height();
    Stats s;
    std::vector<double> lumas;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            if (std::hypot(x + 0.5 - w / 2.0, y + 0.5 - h / 2.0) > radius) continue;
            const std::uint8_t* p = &t.faces[0][0].bytes[(static_cast<size_t>(y) * w + x) * 4];
            const glm::dvec3 c(p[0] / 255.0, p[1] / 255.0, p[2] / 255.0);
            s.mean += c;
            lumas.push_back(0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b);
        }
    s.mean /= static_cast<double>(lumas.size());
    for (double l : lumas) s.luma_mean += l / lumas.size();
    for (double l : lumas) s.luma_sd += (l - s.luma_mean) * (l - s.luma_mean) / lumas.size();
    s.luma_sd = std::sqrt(s.luma_sd);
    return s;
}
}  // namespace

TEST_CASE("a uniform environment prefilters to itself and its SH irradiance is exact") {
    const lighting::Environment furnace = lighting::make_environment("furnace", 16);
    const lighting::PrefilteredEnvironment p = lighting::prefilter(furnace, 4, 32);
    for (const auto& level : p.specular)
        for (const auto& face : level.faces)
            for (const auto& texel : face) CHECK(texel.g == doctest::Approx(1.0).epsilon(1e-5));  // weights normalised: float rounding only
    // The texel solid angles sum to 4π (exact formula), so L00 and with it E/π = 1 (float rounding of 1536 texels).
    for (const glm::dvec3 n : {glm::dvec3(0, 1, 0), glm::dvec3(1, 0, 0), glm::normalize(glm::dvec3(1, -2, 3))})
        CHECK(lighting::evaluate_irradiance(p.irradiance, n).g == doctest::Approx(1.0).epsilon(1e-5));
}

TEST_CASE("the sky's ground is a grey ground of albedo 0.2 lit by that sky: darker under a low sun") {
    // Issue 28: the ground was 0.208 at every elevation. Here its radiance is checked against 0.2/π
    // times the horizontal irradiance the test integrates itself from the environment: the cube's
    // texels above the horizon (solid angle per texel from the cube's geometry) plus the sun disc.
    const auto luminance = [](const glm::dvec3& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; };
    double ground_at[2] = {0, 0};
    int index = 0;
    for (const char* source : {"sky:5", "sky:60"}) {
        CAPTURE(source);
        const lighting::Environment sky = lighting::make_environment(source, 64);
        double irradiance = 0;
        const int n = sky.radiance.size;
        for (int face = 0; face < 6; ++face)
            for (int y = 0; y < n; ++y)
                for (int x = 0; x < n; ++x) {
                    const glm::dvec3 d = lighting::cube_direction(face, (x + 0.5) / n, (y + 0.5) / n);
                    const double r = glm::length(d);
                    const glm::dvec3 u = d / r;
                    if (u.y <= 0) continue;
                    // dω of a texel at distance r from the cube's centre, face at distance 1, texel side 2/n.
                    const double solid_angle = (2.0 / n) * (2.0 / n) / (r * r * r);
                    irradiance += luminance(glm::dvec3(sky.radiance.at(face, x, y))) * u.y * solid_angle;
                }
        for (const auto& disc : sky.discs) irradiance += luminance(disc.radiance) * disc.solid_angle() * std::max(disc.direction.y, 0.0);
        const glm::dvec3 below = lighting::cube_direction(3, 0.5, 0.5);  // -Y face's centre: straight down
        const auto& face = lighting::select_cube_face(glm::normalize(below));
        const int tx = std::min(n - 1, static_cast<int>(face.s * n)), ty = std::min(n - 1, static_cast<int>(face.t * n));
        const double ground = luminance(glm::dvec3(sky.radiance.at(face.face, tx, ty)));
        // The cube's sky texels are a midpoint rule over smooth radiance: 2 % covers it at 64² a face.
        CHECK(ground == doctest::Approx(0.2 / kPi * irradiance).epsilon(0.02));
        ground_at[index++] = ground;
    }
    // 0.2/π (0.8π sin 5°/sin 35° + 0.2π) = 0.064 against 0.281 at 60°.
    CHECK(ground_at[0] == doctest::Approx(0.0643).epsilon(0.03));
    CHECK(ground_at[0] < 0.3 * ground_at[1]);
}

TEST_CASE("SH irradiance of a sky brightening towards the zenith matches the analytic integral") {
    // L = max(y, 0): E(up)/π = ∫ cos² dω / π = 2/3, E(down) = 0.
    const lighting::Environment sky{lighting::tabulate(32, 2, [](const glm::dvec3& d) { return glm::vec3(static_cast<float>(std::max(d.y, 0.0))); }), {}, std::nullopt};
    const lighting::PrefilteredEnvironment p = lighting::prefilter(sky, 1);
    // Order-2 SH irradiance is not exact for a clamped lighting; Ramamoorthi & Hanrahan (2001) bound its
    // error at a few percent of the mean: allow 0.03 absolute against radiance of order 1.
    CHECK(lighting::evaluate_irradiance(p.irradiance, {0, 1, 0}).g == doctest::Approx(2.0 / 3.0).epsilon(0.045));
    CHECK(std::abs(lighting::evaluate_irradiance(p.irradiance, {0, -1, 0}).g) < 0.03);
    // Horizontal n = x: ∫ max(y, 0) max(x, 0) dω by a midpoint rule over the sphere (10 %: order-2 SH
    // rings most where the lighting's edge, the horizon, faces the normal).
    double e = 0;
    const int n = 400;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < 2 * n; ++j) {
            const double theta = (i + 0.5) / n * kPi, phi = (j + 0.5) / (2 * n) * 2 * kPi;
            const glm::dvec3 d(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
            e += std::max(d.y, 0.0) * std::max(d.x, 0.0) * std::sin(theta) * (kPi / n) * (kPi / n);
        }
    CHECK(lighting::evaluate_irradiance(p.irradiance, {1, 0, 0}).g == doctest::Approx(e / kPi).epsilon(0.1));
}

TEST_CASE("the DFG table's directional albedo matches a quadrature of the BRDF; it never exceeds 1") {
    const lighting::DfgTable table = lighting::make_dfg_table(32, 1024);
    for (const glm::vec3 a : table.data) CHECK(a.x + a.y <= 1.0f + 1e-6f);
    for (const double nv : {0.2, 0.5, 0.9, 1.0})  // the ends are tabulated, not clamped
        for (const double r : {0.3, 0.6, 1.0}) {
            CAPTURE(nv);
            CAPTURE(r);
            const glm::dvec3 ab = table.lookup(nv, r);
            // 1024 Hammersley samples and bilinear lookup between texels 1/32 apart: 1 % of the albedo.
            CHECK(ab.x + ab.y == doctest::Approx(albedo_by_quadrature(nv, r)).epsilon(0.01));
        }
}

TEST_CASE("display transforms: none clamps, PBR Neutral keeps dark colours' hue, exposure doubles per stop") {
    using image::ToneMap;
    CHECK(image::display_transform({0.25f, 0.5f, 2.0f}, {}).z == 1.0f);
    CHECK(image::display_transform({0.25f, 0.5f, 0.1f}, {1.0f, ToneMap::None}).y == doctest::Approx(1.0f));
    // Khronos PBR Neutral: below the compression start (0.76) only the 0.04 toe offset applies.
    const glm::vec3 neutral = image::display_transform({0.5f, 0.3f, 0.2f}, {0.0f, ToneMap::PbrNeutral});
    CHECK(neutral.x == doctest::Approx(0.46f));
    CHECK(neutral.y == doctest::Approx(0.26f));
    for (const ToneMap t : {ToneMap::Aces, ToneMap::PbrNeutral}) {
        float previous = 0.0f;
        for (float v = 0.0f; v < 100.0f; v = v * 1.5f + 0.01f) {  // monotonic, below 1
            const float shown = image::display_transform(glm::vec3(v), {0.0f, t}).g;
            CHECK(shown >= previous);
            CHECK(shown <= 1.0f);
            previous = shown;
        }
    }
    CHECK_THROWS(image::parse_tone_map("filmic"));
}

TEST_CASE("white furnace: a white metal under uniform light reflects 1 within 2 % at every roughness, never more") {
    for (const double roughness : {0.1, 0.3, 0.5, 0.7, 1.0}) {
        const std::string out = temp_path("furnace.exr");
        const Result r = run("render " + std::string(FXVIEW_SOURCE_EFFECTS_DIR) +
                             "/brdf/analytic.fx -t PBR --set BaseColor=1,1,1 --set Metallic=1 --set LightIrradiance=0 --set Roughness=" +
                             std::to_string(roughness) + " --environment furnace --size 64x64 --out " + out);
        REQUIRE(r.exit_code == 0);
        const image::FloatImage image = image::read_float_image(out);
        double sum = 0, most = 0;
        int count = 0;
        for (int y = 0; y < 64; ++y)
            for (int x = 0; x < 64; ++x)
                if (std::hypot(x + 0.5 - 32, y + 0.5 - 32) < 24) {  // inside the silhouette (radius ~27 px)
                    sum += image.pixel(x, y)[1];
                    most = std::max<double>(most, image.pixel(x, y)[1]);
                    ++count;
                }
        CAPTURE(roughness);
        CHECK(sum / count == doctest::Approx(1.0).epsilon(0.02));
        CHECK(most <= 1.0 + 1e-4);  // float rounding of the compensation
    }
}

TEST_CASE("metal presets look like their metal: hue order, mid-grey luminance, reflected structure") {
    struct Metal {
        const char* name;
        bool warm;  // R > G > B with a clear gap (gold, copper); else near neutral
    };
    for (const Metal m : {Metal{"gold", true}, Metal{"copper", true}, Metal{"silver", false}, Metal{"aluminium", false}, Metal{"titanium", false}}) {
        const std::string out = temp_path(std::string(m.name) + ".png");
        const Result r = run("render " + std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/brdf/analytic.fx --preset " + FXVIEW_SOURCE_EFFECTS_DIR +
                             "/brdf/presets/" + m.name + ".json --mesh sphere --size 128x128 --out " + out);
        REQUIRE(r.exit_code == 0);
        const Stats s = sphere_stats(out, 48.0);  // the sphere's silhouette has a radius of ~55 px
        CAPTURE(m.name);
        CAPTURE(s.mean.r);
        CAPTURE(s.mean.g);
        CAPTURE(s.mean.b);
        CAPTURE(s.luma_sd);
        CHECK(s.luma_mean > 0.2);
        CHECK(s.luma_mean < 0.8);
        CHECK(s.luma_sd > 0.05);  // a flat shade would be ~0; soft boxes and the floor reflect
        if (m.warm) {
            // Copper's F0 has G − B = 0.10; its rim turns white by Fresnel at grazing angles (with the
            // height-correlated masking of image-based light), so the sphere's mean keeps about half of
            // it: 0.048 measured. 0.03 still separates warm from neutral (silver: 0.016).
            CHECK(s.mean.r > s.mean.g + 0.05);
            CHECK(s.mean.g > s.mean.b + 0.03);
        } else {
            CHECK(std::abs(s.mean.r - s.mean.b) < 0.08);
        }
    }
}

TEST_CASE("bad environments: unknown names and files exit non-zero naming them") {
    const std::string analytic = std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/brdf/analytic.fx";
    const Result missing = run("render " + analytic + " --environment /no/such/sky.hdr --size 16x16 --out " + temp_path("x.png"));
    CHECK(missing.exit_code != 0);
    CHECK(missing.err.find("/no/such/sky.hdr") != std::string::npos);
    const Result sky = run("render " + analytic + " --environment sky:95 --size 16x16 --out " + temp_path("x.png"));
    CHECK(sky.exit_code != 0);
    CHECK(sky.err.find("0-90") != std::string::npos);
    const Result tone = run("render " + analytic + " --tone-map filmic --size 16x16 --out " + temp_path("x.png"));
    CHECK(tone.exit_code != 0);
    CHECK(tone.err.find("pbr-neutral") != std::string::npos);
}

TEST_CASE("an environment that an effect's shaders do not read is said, never silently ignored") {
    const std::string effects = std::string(FXVIEW_SOURCE_EFFECTS_DIR);
    const std::string out = " --environment sky --size 16x16 --out " + temp_path("unused-environment.png");
    // Said per technique: cd.fx's Orders diffracts the environment, its Thesis and Grating do not.
    for (const std::string spectral : {"/spectral/cd.fx -t Thesis", "/spectral/cd.fx -t Grating", "/spectral/wavelength.fx -t Constant"}) {
        const Result r = run("render " + effects + spectral + out);
        CHECK(r.exit_code == 0);
        CHECK(r.err.find("is lit by the point light only; the environment 'sky'") != std::string::npos);
    }
    // The thin films, the CD's orders and wavelength.fx take the spectral form of the sky, studio and
    // furnace, and of an image (its colours uplifted); an image of more varied colours than its three
    // spectra hold is said.
    for (const std::string environment : {"sky", "studio", "furnace"})
        for (const std::string spectral : {"/spectral/thinfilm.fx", "/spectral/cd.fx -t Orders", "/spectral/wavelength.fx"}) {
            CAPTURE(environment);
            CAPTURE(spectral);
            CHECK(run("render " + effects + spectral + " --environment " + environment + " --size 16x16 --out " + temp_path("spectral-env.png"))
                      .err.find("warning") == std::string::npos);
        }
    image::FloatImage grey(16, 8, 4);
    for (float& v : grey.data) v = 0.5f;
    const std::string rgb_file = temp_path("grey-env.exr");
    image::write_exr(rgb_file, grey);
    const Result rgb = run("render " + effects + "/spectral/thinfilm.fx --environment " + rgb_file + " --size 16x16 --out " + temp_path("rgb-film.png"));
    CHECK(rgb.exit_code == 0);
    CHECK(rgb.err.find("warning") == std::string::npos);
    image::FloatImage hues(24, 12, 4);  // six saturated hues side by side
    const float colours[6][3] = {{1, 0.05f, 0.05f}, {1, 1, 0.05f}, {0.05f, 1, 0.05f}, {0.05f, 1, 1}, {0.05f, 0.05f, 1}, {1, 0.05f, 1}};
    for (int y = 0; y < 12; ++y)
        for (int x = 0; x < 24; ++x)
            for (int c = 0; c < 4; ++c) hues.data[static_cast<size_t>((y * 24 + x) * 4 + c)] = c < 3 ? colours[x / 4][c] : 1.0f;
    const std::string hues_file = temp_path("hues-env.exr");
    image::write_exr(hues_file, hues);
    const Result varied = run("render " + effects + "/spectral/thinfilm.fx --environment " + hues_file + " --size 16x16 --out " + temp_path("hue-film.png"));
    CHECK(varied.exit_code == 0);
    CHECK(varied.err.find("more varied colours than its three spectra hold") != std::string::npos);
    // An effect that is lit by it says nothing of the kind; without --environment neither does a spectral one.
    CHECK(run("render " + effects + "/brdf/analytic.fx" + out).err.find("point light only") == std::string::npos);
    CHECK(run("render " + effects + "/spectral/cd.fx --size 16x16 --out " + temp_path("no-environment.png")).err.find("point light only") == std::string::npos);
}

TEST_CASE("compare --ground-truth: the split sum is exact in uniform light and its error elsewhere is reported") {
    const std::string analytic = std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/brdf/analytic.fx";
    const auto truth_of = [&](const std::string& options) {
        const Result r = run("compare " + analytic + " -t PBR --set LightIrradiance=0 --size 48x48 --ground-truth --json --heatmap " +
                             temp_path("truth.png") + " " + options);
        CAPTURE(r.err);
        REQUIRE(r.exit_code == 0);  // the GPU matches the reference whatever the approximation costs
        return nlohmann::json::parse(r.out)["ground_truth"];
    };
    // A grey dielectric in the furnace: the split sum's diffuse weight (1 - F0)(1 - G) and specular F0 A + B
    // are exactly what the BRDF reflects of uniform light; what is left is the Monte Carlo's own error
    // and the tables' resolution (0.1 CIEDE2000 is far below visibility).
    const auto furnace = truth_of("--set Metallic=0 --set BaseColor=0.5,0.5,0.5 --environment furnace");
    CHECK(furnace["mean_delta_e2000"].get<double>() < 0.1);
    // Under the studio the approximation shows (n = v = r, separated integrals): reported, not hidden.
    const auto studio = truth_of("--environment studio");
    CHECK(studio["mean_delta_e2000"].get<double>() > 0.2);
    CHECK(studio["pixels"].get<long>() > 500);
    CHECK(std::filesystem::exists(temp_path("truth-PBR-truth.png")));
    // The integral's own noise is measured (two independent estimates) and stated beside the error:
    // under the studio it is a small fraction of the approximation's error (measured 0.016 against
    // 4.1 for gold at roughness 0.4), so nearly every pixel's error is beyond it; in the furnace, where
    // the split sum is exact, errors are within reach of the noise and the tables' resolution.
    CHECK(studio["noise_mean_delta_e2000"].get<double>() < 0.2 * studio["mean_delta_e2000"].get<double>());
    CHECK(studio["pixels_beyond_noise"].get<long>() > studio["pixels"].get<long>() / 2);
    CHECK(furnace["noise_mean_delta_e2000"].get<double>() >= 0.0);
    CHECK(furnace["pixels_beyond_noise"].get<long>() <= furnace["pixels"].get<long>());
}

TEST_CASE("environment files: equirectangular EXR, six faces and a cube cross light the scene; a wrong shape is named") {
    const std::string analytic = std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/brdf/analytic.fx";
    const std::string white_metal = analytic + " -t PBR --set BaseColor=1,1,1 --set Metallic=1 --set LightIrradiance=0 --set Roughness=0.6 --size 32x32";
    const auto centre_of = [&](const std::string& environment) {
        const std::string out = temp_path("file-env.exr");
        const Result r = run("render " + white_metal + " --environment " + environment + " --out " + out);
        CAPTURE(r.err);
        REQUIRE(r.exit_code == 0);
        return image::read_float_image(out).pixel(16, 16)[1];
    };
    const auto uniform_image = [](const std::string& path, int width, int height, float value) {
        image::FloatImage image(width, height, 4);
        for (float& v : image.data) v = value;
        image::write_exr(path, image);
    };
    // Uniform radiance 1 from a file is the furnace: a white metal reflects 1 (2 %, as the furnace test).
    const std::string equirect = temp_path("uniform-equirect.exr");
    uniform_image(equirect, 64, 32, 1.0f);
    CHECK(centre_of(equirect) == doctest::Approx(1.0).epsilon(0.02));
    std::string faces;
    for (int face = 0; face < 6; ++face) {
        const std::string path = temp_path("face" + std::to_string(face) + ".exr");
        uniform_image(path, 8, 8, 0.5f);
        faces += (face ? "," : "") + path;
    }
    CHECK(centre_of(faces) == doctest::Approx(0.5).epsilon(0.02));
    // The shipped cube cross (8-bit sRGB, decoded to linear) lights and fills the background.
    const std::string cross = std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/../textures/sky_cross.png";
    CHECK(centre_of(cross) > 0.05);
    const std::string wrong = temp_path("wrong-shape.exr");
    uniform_image(wrong, 30, 20, 1.0f);
    const Result r = run("render " + white_metal + " --environment " + wrong + " --out " + temp_path("x.png"));
    CHECK(r.exit_code == 1);
    CHECK(r.err.find("wrong-shape.exr") != std::string::npos);
    CHECK(r.err.find("equirectangular") != std::string::npos);
    // Finite but near float's maximum: prefiltering would overflow to NaN pixels (issue 28). Refused.
    const std::string huge = temp_path("huge.exr");
    image::FloatImage bright(64, 32, 4);
    for (float& v : bright.data) v = 1.0f;
    bright.pixel(10, 10)[0] = 3e38f;
    image::write_exr(huge, bright);
    const Result overflow = run("render " + white_metal + " --environment " + huge + " --out " + temp_path("x.png"));
    CHECK(overflow.exit_code == 1);
    CHECK(overflow.err.find("huge.exr") != std::string::npos);
    CHECK(overflow.err.find("above 1e20") != std::string::npos);
}

TEST_CASE("Radiance .hdr files: read exactly; truncated or malformed ones are errors naming the file, never a hang") {
    const auto write = [](const std::string& path, const std::string& header, const std::vector<std::uint8_t>& pixels) {
        std::ofstream file(path, std::ios::binary);
        file << header;
        file.write(reinterpret_cast<const char*>(pixels.data()), static_cast<std::streamsize>(pixels.size()));
    };
    const std::string header = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 16\n";
    // Run-length scanlines: each channel a run of 16 equal bytes; RGBE (128, 64, 32, 129) is, as
    // Radiance's colr_color() decodes it, (m + 0.5) 2^(129 - 136): (128.5, 64.5, 32.5) / 128.
    std::vector<std::uint8_t> rle;
    for (int row = 0; row < 2; ++row) {
        rle.insert(rle.end(), {2, 2, 0, 16});
        for (const std::uint8_t value : {128, 64, 32, 129}) rle.insert(rle.end(), {static_cast<std::uint8_t>(128 + 16), value});
    }
    const std::string good = temp_path("good.hdr");
    write(good, header, rle);
    const texture::TextureData t = texture::load_texture_file(good);
    float rgba[4];
    texture::read_texel(t, 0, 0, 15, 1, rgba);
    CHECK(rgba[0] == 128.5f / 128);  // exact in float
    CHECK(rgba[1] == 64.5f / 128);
    CHECK(rgba[2] == 32.5f / 128);
    // An exponent of 255 (2^119 per step) reads as finite floats near float's maximum: refused as an
    // environment, naming the file.
    std::vector<std::uint8_t> blinding;
    for (int row = 0; row < 8; ++row) {  // 16 x 8: an equirectangular shape
        blinding.insert(blinding.end(), {2, 2, 0, 16});
        for (const std::uint8_t value : {200, 200, 200, 255}) blinding.insert(blinding.end(), {static_cast<std::uint8_t>(128 + 16), value});
    }
    const std::string sun = temp_path("blinding.hdr");
    write(sun, "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 8 +X 16\n", blinding);
    const Result blinded = run("render --environment " + sun + " " + std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/brdf/analytic.fx --size 8x8 --out " +
                               temp_path("x.png"));
    CHECK(blinded.exit_code == 1);
    CHECK(blinded.err.find("blinding.hdr") != std::string::npos);
    // Cut inside the second scanline's runs (Debian's stb loops forever here: CVE-2021-42715).
    const std::string cut = temp_path("cut.hdr");
    write(cut, header, std::vector<std::uint8_t>(rle.begin(), rle.begin() + 16));
    CHECK_THROWS_WITH(texture::load_texture_file(cut), doctest::Contains("truncated"));
    // Flat pixels, fewer than the size says.
    const std::string flat = temp_path("flat.hdr");
    write(flat, "#?RADIANCE\n\n-Y 4 +X 4\n", std::vector<std::uint8_t>(40, 128));
    CHECK_THROWS_WITH(texture::load_texture_file(flat), doctest::Contains("flat.hdr"));
    // The same as an environment on the command line: exit 1 naming it.
    const Result r = run("render --environment " + cut + " " + std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/brdf/analytic.fx --size 8x8 --out " +
                         temp_path("x.png"));
    CHECK(r.exit_code == 1);
    CHECK(r.err.find("cut.hdr") != std::string::npos);
}

TEST_CASE("a photographed 1-degree sun becomes a disc: its shading matches a sum over the image's own pixels") {
    // Issue 28: a user's HDR with a small bright sun gave faceted blotches at roughness 0.2 and
    // streaks at 0.3-0.5. An equirectangular sky of radiance 0.5 with a sun 1° across (radiance 2e4:
    // 43 % of the map's power) at 30° elevation. The sun leaves the map and is shaded in closed form;
    // the truth: for a normal n seen head-on (n = v = r), the sun's ∫ (L - 0.5) D(h)/4 dl (a GGX lobe's
    // f (n·l) with F = G = 1) summed over every pixel of the image with its exact solid angle, nothing
    // shared with the shading but the GGX formula.
    const int width = 720, height = 360;
    image::FloatImage sky(width, height, 4);
    const glm::dvec3 sun = glm::normalize(glm::dvec3(0.0, std::sin(30 * kPi / 180), -std::cos(30 * kPi / 180)));  // -Z: the image's centre
    const auto pixel_direction = [&](double px, double py) {
        const double phi = (px / width - 0.5) * 2 * kPi, theta = py / height * kPi;  // as from_equirectangular reads it
        return glm::dvec3(std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi));
    };
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            float* p = sky.pixel(x, y);
            const bool in_sun = glm::dot(pixel_direction(x + 0.5, y + 0.5), sun) > std::cos(0.5 * kPi / 180);
            for (int c = 0; c < 3; ++c) p[c] = in_sun ? 2e4f : 0.5f;
            p[3] = 1.0f;
        }
    const std::string path = temp_path("sun-sky.exr");
    image::write_exr(path, sky);
    const lighting::Environment environment = lighting::make_environment(path, 128);
    REQUIRE(environment.discs.size() == 1);
    CHECK(glm::dot(environment.discs[0].direction, sun) > std::cos(0.3 * kPi / 180));
    double sun_power = 0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            if (sky.pixel(x, y)[1] > 1.0f)
                sun_power += (sky.pixel(x, y)[1] - 0.5) * (std::cos(y * kPi / height) - std::cos((y + 1) * kPi / height)) * 2 * kPi / width;
    // Taken out of the image before resampling: the disc carries the image's sun power to float
    // rounding, and its solid angle is that of the pixels above half the peak (0.5° radius, 1.7e-4
    // of a pixel row's rounding).
    CHECK(environment.discs[0].radiance.g * environment.discs[0].solid_angle() == doctest::Approx(sun_power).epsilon(1e-5));
    CHECK(environment.discs[0].angular_radius * 180 / kPi == doctest::Approx(0.5).epsilon(0.1));
    // The sun left no trace in the map: every prefiltered level about it holds the sky's 0.5.
    const lighting::PrefilteredEnvironment maps = lighting::prefilter(environment, 6);
    for (const int level : {0, 1, 3}) {
        const lighting::FloatCube& cube = maps.specular[static_cast<size_t>(level)];
        CHECK(lighting::sample_bilinear(cube, sun).g == doctest::Approx(0.5).epsilon(0.01));  // the ring it was filled from is 0.5
    }
    const lighting::DiscLight& disc = environment.discs[0];
    const auto truth = [&](const glm::dvec3& n, double alpha) {
        double sum = 0;
        for (int y = 0; y < height; ++y) {
            const double omega = (std::cos(y * kPi / height) - std::cos((y + 1.0) * kPi / height)) * 2 * kPi / width;
            for (int x = 0; x < width; ++x) {
                const double excess = sky.pixel(x, y)[1] - 0.5;
                if (excess <= 0) continue;
                const glm::dvec3 l = pixel_direction(x + 0.5, y + 0.5);
                if (glm::dot(n, l) > 0) sum += excess * lighting::ggx_d(glm::dot(n, glm::normalize(n + l)), alpha) / 4 * omega;
            }
        }
        return sum;
    };
    const double power = disc.radiance.g * disc.solid_angle();
    for (const double roughness : {0.1, 0.2, 0.4}) {  // narrower lobes are finer than the image's 0.5° pixels
        const double alpha = roughness * roughness, widened = lighting::disc_widened_alpha(alpha, disc.angular_radius);
        double worst_centre = 0, worst_nearest = 0, peak = 0;
        // Normals whose mirror direction sweeps across the sun and its lobe, in steps of a tenth of the lobe.
        const double reach = 2.0 * std::max(alpha, disc.angular_radius);
        const glm::dvec3 side = glm::normalize(glm::cross(sun, glm::dvec3(0, 1, 0)));
        for (double t = -reach; t <= reach; t += reach / 10) {
            const glm::dvec3 r = glm::normalize(sun + std::tan(t) * side), n = r;  // v = n: the mirror direction is n
            const double expected = truth(n, alpha);
            peak = std::max(peak, expected);
            // PBR (metallic_roughness_discs): the BRDF at the centre with the lobe widened.
            const double centre = power * lighting::ggx_d(glm::dot(n, glm::normalize(n + disc.direction)), widened) / 4;
            // Other BRDFs (environment_light): at the point nearest r of the disc shrunk by b²/widened²
            // (b = radius/2: the disc itself for a mirror, its centre for a wide lobe), scaled by alpha² / widened².
            const double b = disc.angular_radius / 2;
            const glm::dvec3 l = lighting::DiscLight::nearest(disc.direction, r, disc.angular_radius * b * b / (widened * widened));
            const double nearest = power * lighting::ggx_d(glm::dot(n, glm::normalize(n + l)), alpha) / 4 * alpha * alpha / (widened * widened);
            worst_centre = std::max(worst_centre, std::abs(centre - expected));
            worst_nearest = std::max(worst_nearest, std::abs(nearest - expected));
        }
        CAPTURE(roughness);
        // Errors relative to the lobe's peak, measured (centre / nearest point): 3.7 % / 3.0 % at
        // roughness 0.1, where the lobe is two of the image's pixels wide (the sum itself is coarse),
        // 0.29 % / 0.43 % at 0.2, 0.02 % / 0.03 % at 0.4. Without the widening the centre method is
        // 10 % off at 0.1; the nearest point of the whole disc (Karis' choice) 11 % at 0.2.
        CHECK(worst_centre / peak < (roughness >= 0.2 ? 0.01 : 0.05));
        CHECK(worst_nearest / peak < (roughness >= 0.2 ? 0.01 : 0.05));
    }
}

TEST_CASE("an image with two small suns: both become discs, and the GPU shades them as the CPU reference does") {
    // The GPU tables held one disc and refused a second with an error; they hold four now. Two suns
    // 1° across, 90° apart in azimuth, over a sky of 0.5.
    const int width = 360, height = 180;
    image::FloatImage sky(width, height, 4);
    const auto direction = [&](double px, double py) {
        const double phi = (px / width - 0.5) * 2 * kPi, theta = py / height * kPi;
        return glm::dvec3(std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi));
    };
    const glm::dvec3 suns[2] = {glm::normalize(glm::dvec3(0.5, 0.5, -0.7)), glm::normalize(glm::dvec3(-0.5, 0.5, 0.3))};
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const glm::dvec3 d = direction(x + 0.5, y + 0.5);
            const bool in_sun = glm::dot(d, suns[0]) > std::cos(kPi / 180) || glm::dot(d, suns[1]) > std::cos(kPi / 180);
            float* p = sky.pixel(x, y);
            p[0] = p[1] = p[2] = in_sun ? 5e3f : 0.5f;
            p[3] = 1.0f;
        }
    const std::string path = temp_path("two-suns.exr");
    image::write_exr(path, sky);
    CHECK(lighting::make_environment(path, 64).discs.size() == 2);
    const std::string effect = std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/brdf/analytic.fx";
    for (const char* technique : {"PBR", "CookTorranceGGX"}) {
        CAPTURE(technique);
        const Result r = run("compare " + effect + " --technique " + technique + " --environment " + path +
                             " --size 32x32 --set Metallic=1 --set Roughness=0.3 --set GGXAlpha=0.09");
        CHECK(r.exit_code == 0);
        CHECK(r.out.find("pass") != std::string::npos);
    }
}

TEST_CASE("the built-in environments' spectral forms are their RGB radiance: Σ w_k S_k through the CIE 1931 CMFs gives the cube's colour") {
    // Independent of the sky's construction: colord's CMFs integrate the spectra at 1 nm, and the
    // result must be the RGB the background and the RGB techniques see. 1e-3 relative: the cube's
    // float texels and the clipping of daylight's RGB at 0 (12000 K and 5500 K lie inside sRGB; the
    // studio's and furnace's D65 is sRGB's white to 1e-4).
    const spectral::Observer observer = spectral::load_observer("1931");
    for (const char* source : {"sky", "sky:5,4500", "studio", "furnace"}) {
        const lighting::Environment sky = lighting::make_environment(source, 32);
        REQUIRE(sky.spectral.has_value());
        double ybar = 0;
        for (int nm = 360; nm <= 830; ++nm) ybar += observer.y.at(nm);
        const lighting::FloatCube with_discs = sky.radiance_with_discs();  // the weights hold the sun drawn in
        for (int face = 0; face < 6; ++face)
            for (int y = 1; y < 32; y += 5)
                for (int x = 2; x < 32; x += 7) {
                    const glm::vec3 w = sky.spectral->weights.at(face, x, y), rgb = with_discs.at(face, x, y);
                    spectral::Vec3 xyz{};
                    for (int nm = 360; nm <= 830; ++nm) {
                        const size_t i = static_cast<size_t>(nm - 360);
                        const double l = w.x * sky.spectral->spectra[0][i] + w.y * sky.spectral->spectra[1][i] + w.z * sky.spectral->spectra[2][i];
                        xyz[0] += l * observer.x.at(nm) / ybar;
                        xyz[1] += l * observer.y.at(nm) / ybar;
                        xyz[2] += l * observer.z.at(nm) / ybar;
                    }
                    const spectral::Vec3 expected = spectral::xyz_to_linear_srgb_unclipped(xyz);
                    CAPTURE(source); CAPTURE(face); CAPTURE(x); CAPTURE(y);
                    for (int c = 0; c < 3; ++c) CHECK(rgb[c] == doctest::Approx(expected[static_cast<size_t>(c)]).epsilon(1e-3).scale(1e-4));
                }
    }
}

TEST_CASE("Fourier films under the sky: the series of the sky's three spectra matches the exact sum and the CPU reference") {
    const std::string thinfilm = std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/spectral/thinfilm.fx";
    const std::string scene = " --environment sky:35 --size 32x32 --set Thickness=300 --set Variation=700 --set Brightness=0.5";
    for (const auto& [fourier, exact] : {std::pair{"FresnelFourier", "FresnelExact"}, std::pair{"BubbleFourier", "Bubble"}}) {
        CAPTURE(fourier);
        const Result compare = run("compare " + thinfilm + " -t " + fourier + scene);
        CHECK(compare.exit_code == 0);
        // Against Airy's sum over every nm under the same sky, a method without the series: the rule
        // stops once what is left is below 1e-3 of the light (kSeriesTailLimit), so 2e-3 of the
        // brightest pixel bounds the difference with float rounding to spare.
        const std::string a = temp_path(std::string(fourier) + "-sky.pfm"), b = temp_path(std::string(exact) + "-sky.pfm");
        REQUIRE(run("render " + thinfilm + " -t " + fourier + scene + " --out " + a).exit_code == 0);
        REQUIRE(run("render " + thinfilm + " -t " + exact + scene + " --set Steps=1 --set Lower=360 --set Upper=830 --out " + b).exit_code == 0);
        const image::FloatImage series = image::read_float_image(a), sum = image::read_float_image(b);
        double brightest = 0, worst = 0, lit = 0;
        for (int y = 0; y < 32; ++y)
            for (int x = 0; x < 32; ++x)
                for (int c = 0; c < 3; ++c) {
                    brightest = std::max<double>(brightest, sum.pixel(x, y)[c]);
                    worst = std::max<double>(worst, std::abs(series.pixel(x, y)[c] - sum.pixel(x, y)[c]));
                    lit += sum.pixel(x, y)[c] > 0.01;
                }
        CHECK(lit > 500);  // the film is seen, not the background alone
        CHECK(brightest < 0.99);  // nothing clipped
        CHECK(worst < 2e-3 * brightest);
    }
}

TEST_CASE("a CD in the white furnace reflects its coating's reflectance in neutral grey, whatever its tracks") {
    // Uniform radiance 1 of D65 from every direction: whatever directions the grating equation picks,
    // every order sees 1, so the disc shows Σ η_m = Reflectance in the furnace's colour, for any track
    // spacing, number of tracks, pit width and view (an analytic result the shader's formulas do not
    // contain). 2e-3: D65 against sRGB's white (1e-4), float sums over 471 wavelengths, and orders
    // turning evanescent inside a band of EnvironmentBand nm (their share then goes to the others).
    const std::string cd = std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/spectral/cd.fx -t Orders --mesh disc --environment furnace --size 32x32"
                           " --set Lamp=0 --set SubstrateWeight=0 --set Reflectance=0.8";
    for (const std::string settings : {" --set Tracks=10", " --set Tracks=200 --set TrackSpacing=740", " --set PitFraction=0.6 --camera-rotate 40,0,0",
                                       " --set TrackSpacing=5000 --set EnvironmentBand=1 --camera-rotate 0,60,0"}) {
        CAPTURE(settings);
        const std::string out = temp_path("cd-furnace.exr");
        REQUIRE(run("render " + cd + settings + " --out " + out).exit_code == 0);
        const image::FloatImage image = image::read_float_image(out);
        int disc = 0;
        double worst = 0;
        for (int y = 0; y < 32; ++y)
            for (int x = 0; x < 32; ++x) {
                const auto p = image.pixel(x, y);
                if (std::abs(p[1] - 1.0f) < 1e-3f) continue;  // the furnace behind the disc
                ++disc;
                for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(p[c] - 0.8));
            }
        CHECK(disc > 100);
        CHECK(worst < 2e-3);
    }
}

TEST_CASE("compare --ground-truth for films under the sky: the exact film mirroring the sky's model, independent of the weight cube") {
    const std::string thinfilm = std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/spectral/thinfilm.fx";
    const auto truth_of = [&](const std::string& arguments) {
        const Result r = run("compare " + thinfilm + " " + arguments + " --environment sky:35 --size 32x32 --ground-truth --json");
        CAPTURE(arguments);
        CAPTURE(r.err);
        REQUIRE(r.exit_code == 0);
        const auto json = nlohmann::json::parse(r.out.substr(r.out.find('{')));
        REQUIRE(json.contains("ground_truth"));
        return json["ground_truth"];
    };
    // A soap bubble and oil on water: the techniques' pictures lie within CIEDE2000 1 of the truth
    // on average (the acceptance of issue 25; measured 6e-4 and 3e-3 at 64x64, the cube's bilinear
    // reads of the sun's edge the largest part).
    CHECK(truth_of("-t BubbleFourier --set Thickness=300 --set Variation=700")["mean_delta_e2000"].get<double>() < 1.0);
    CHECK(truth_of("-t FresnelFourier --set FilmIndex=1.5 --set SubstrateIndex=1.33 --set Thickness=150 --set Variation=900")["mean_delta_e2000"].get<double>() < 1.0);
    // The truth is the physical film, not the technique's formula: the thesis' Fresnel model (Code 15,
    // which keeps only the cosine of the phase) lies far from it (measured mean 21.6 at 64x64).
    CHECK(truth_of("-t Fresnel")["mean_delta_e2000"].get<double>() > 5.0);
}

TEST_CASE("compare --ground-truth for the CD's orders in the studio: bands and weight cube against every nm of the model") {
    const Result r = run("compare " + std::string(FXVIEW_SOURCE_EFFECTS_DIR) +
                         "/spectral/cd.fx -t Orders --mesh disc --camera-rotate -25,15,0 --environment studio --set Lamp=0 --size 32x32 --ground-truth --json");
    CAPTURE(r.err);
    REQUIRE(r.exit_code == 0);
    const auto truth = nlohmann::json::parse(r.out.substr(r.out.find('{')))["ground_truth"];
    // Measured 0.097 at 64x64 with 10 nm bands; a colour error users would see starts near 1.
    CHECK(truth["mean_delta_e2000"].get<double>() < 0.5);
    CHECK(truth["method"].get<std::string>().find("every nm") != std::string::npos);
}

#include "app/gpu_cpu_compare.hpp"

#include <algorithm>
#include <tuple>
#include <atomic>
#include <cmath>
#include <exception>
#include <filesystem>
#include <iostream>
#include <limits>
#include <mutex>
#include <thread>
#include <vector>

#include "context/context.hpp"
#include "effect/preset.hpp"
#include "gl/render_target.hpp"
#include "image/color_encoding.hpp"
#include "reference/reference.hpp"
#include "spectral/color_difference.hpp"
#include "spectral/level_of_detail.hpp"
#include "render/effect_session.hpp"

namespace fxview::app {

std::vector<std::string> technique_names(const EffectOptions& options) {
    const effect::Effect effect = effect::load_effect(options.path, effect_load_options(options.access));
    std::vector<std::string> names;
    for (const auto& t : effect.techniques) names.push_back(t.name);
    return names;
}

namespace {

// Whether the 8-bit PNG codes of the GPU's and the CPU's colour differ by more than one step.
bool codes_differ(const float* gpu, const std::array<double, 4>& cpu) {
    for (int c = 0; c < 4; ++c) {
        const auto encoding = c < 3 ? image::Encoding::Srgb : image::Encoding::Linear;
        if (std::abs(image::to_8bit(gpu[c], encoding) - image::to_8bit(static_cast<float>(cpu[static_cast<size_t>(c)]), encoding)) > 1) return true;
    }
    return false;
}

// Blue (no error) through yellow (at the tolerance) to red (twice the tolerance and beyond).
std::array<float, 3> heat(double ratio) {
    const float t = static_cast<float>(std::clamp(ratio, 0.0, 2.0));
    if (t <= 1.0f) return {t, t, 1.0f - t};
    return {1.0f, 2.0f - t, 0.0f};
}

// Linear sRGB radiance as CIELAB, white at radiance 1 (D65).
spectral::Vec3 radiance_to_lab(const std::array<double, 4>& rgb) {
    const double r = rgb[0], g = rgb[1], b = rgb[2];
    const spectral::Vec3 xyz{0.4124 * r + 0.3576 * g + 0.1805 * b, 0.2126 * r + 0.7152 * g + 0.0722 * b, 0.0193 * r + 0.1192 * g + 0.9505 * b};
    return spectral::xyz_to_lab(xyz, {0.95047, 1.0, 1.08883});
}

// Judges the approximation against two independent Monte Carlo estimates of its integral: the
// error against their mean, and the estimate's own noise, half their difference (the mean of two
// equal estimates is off by about half of what separates them); an error counts as beyond the noise
// where it exceeds twice it.
template <typename PixelTriple>
CompareResult::GroundTruth judge_ground_truth(int width, int height, const PixelTriple& at) {
    CompareResult::GroundTruth truth;
    truth.heat_map = image::FloatImage(width, height, 4);
    std::vector<double> errors, noises;
    double beyond_sum = 0;
    long beyond = 0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            float* heat_pixel = truth.heat_map.pixel(x, y);
            heat_pixel[3] = 1.0f;
            const auto pixel = at(x, y);
            if (!pixel) continue;
            const auto& [reference, first, second] = *pixel;
            std::array<double, 4> mean{};
            for (size_t c = 0; c < 4; ++c) mean[c] = 0.5 * (first[c] + second[c]);
            const double delta_e = spectral::delta_e_2000(radiance_to_lab(reference), radiance_to_lab(mean));
            const double noise = 0.5 * spectral::delta_e_2000(radiance_to_lab(first), radiance_to_lab(second));
            errors.push_back(delta_e);
            noises.push_back(noise);
            if (delta_e > 2.0 * noise) {
                ++beyond;
                beyond_sum += delta_e;
            }
            if (delta_e > truth.max_delta_e || truth.worst_x < 0) {
                truth.max_delta_e = delta_e;
                truth.worst_x = x;
                truth.worst_y = y;
                truth.worst_reference = {reference[0], reference[1], reference[2]};
                truth.worst_truth = {mean[0], mean[1], mean[2]};
            }
            const auto colour = heat(delta_e / 2.0);
            std::copy(colour.begin(), colour.end(), heat_pixel);
        }
    truth.pixels = static_cast<long>(errors.size());
    if (errors.empty()) return truth;
    const auto mean_and_p95 = [](std::vector<double> values, double& mean, double& p95) {
        for (const double e : values) mean += e / static_cast<double>(values.size());
        const auto at95 = values.begin() + static_cast<std::ptrdiff_t>(values.size() * 95 / 100);
        std::nth_element(values.begin(), at95, values.end());
        p95 = *at95;
    };
    mean_and_p95(errors, truth.mean_delta_e, truth.p95_delta_e);
    mean_and_p95(noises, truth.mean_noise_delta_e, truth.p95_noise_delta_e);
    truth.pixels_beyond_noise = beyond;
    truth.mean_delta_e_beyond_noise = beyond > 0 ? beyond_sum / static_cast<double>(beyond) : 0.0;
    return truth;
}

}  // namespace

CompareResult compare_technique(const RenderRequest& request, const std::string& technique,
                                const std::vector<std::string>& reference_sets, bool ground_truth) {
    context::ContextOptions context_options;
    context_options.backend = request.backend;
    context_options.window_width = request.width;
    context_options.window_height = request.height;
    context_options.window_visible = false;
    context_options.debug_output = request.gl_debug;
    const auto gl_context = context::create_context(context_options);

    EffectOptions effect_options = request.effect;
    if (!technique.empty()) effect_options.technique = technique;
    const auto opened = open_effect_session(effect_options);
    render::EffectSession& session = *opened;
    const std::vector<std::string> warned = session.scene_warnings(request.scene);
    for (const std::string& warning : warned) std::cerr << warning << "\n";

    CompareResult result;
    result.technique = session.technique();
    const std::string stem = std::filesystem::path(request.effect.path).stem().string();
    // A legacy file's technique may have a reference of its own (its code differs from the port's).
    const reference::Reference* ref = session.effect().legacy ? reference::find_reference(stem, "legacy:" + result.technique) : nullptr;
    if (!ref) ref = reference::find_reference(stem, result.technique);
    result.has_reference = ref != nullptr;
    if (!ref) return result;
    result.tolerance_reason = ref->why;

    // No MSAA: every pixel's colour and captured inputs must come from one fragment.
    gl::RenderTarget target({request.width, request.height, 6, 0});
    session.render(request.scene, target);
    for (const std::string& warning : session.scene_warnings(request.scene))  // those that need the loaded environment
        if (std::find(warned.begin(), warned.end(), warning) == warned.end()) std::cerr << warning << "\n";
    const image::FloatImage gpu = target.read_color(0), positions = target.read_color(1), normals = target.read_color(2),
                            uvs = target.read_color(3), tangents = target.read_color(4),
                            footprints = target.read_color(5);

    effect::ParameterValues cpu_values = session.values_for(request.scene);
    for (const auto& assignment : reference_sets) effect::set_value_from_text(session.effect(), cpu_values, assignment);
    const reference::ReferenceContext reference_context{cpu_values, session.resources(), &request.scene.environment};
    const double tolerance = ref->tolerance_for ? ref->tolerance_for(reference_context) : ref->tolerance;
    result.tolerance = tolerance;
    const glm::dvec3 camera(math::camera_world_position(request.scene.camera.pose));
    const glm::dvec3 light(request.scene.light.world_position());
    const scene::LightGeometry lamp = scene::light_geometry(request.scene.light);

    // The references are pure functions of the pixel's inputs: shade rows on every core, then judge
    // the pixels in order.
    struct Shaded {
        std::array<double, 4> cpu{};
        double slack = 0;
        std::array<double, 4> truth{}, second_truth{};  // two independent estimates of the integral
    };
    const bool with_truth = ground_truth && ref->truth &&
                            (!request.scene.environment.source.empty() || (ref->truth_with_sized_light && request.scene.light.has_size()) ||
                             (ref->truth_wanted && ref->truth_wanted(reference_context)));
    std::vector<Shaded> shaded(static_cast<size_t>(request.width) * static_cast<size_t>(request.height));
    const auto input_at = [&](int x, int y) {
        reference::ShadingInput input;
        input.position = glm::dvec3(positions.pixel(x, y)[0], positions.pixel(x, y)[1], positions.pixel(x, y)[2]);
        input.normal = glm::dvec3(normals.pixel(x, y)[0], normals.pixel(x, y)[1], normals.pixel(x, y)[2]);
        input.uv = glm::dvec2(uvs.pixel(x, y)[0], uvs.pixel(x, y)[1]);
        input.tangent = glm::dvec3(tangents.pixel(x, y)[0], tangents.pixel(x, y)[1], tangents.pixel(x, y)[2]);
        input.footprint =
            glm::dvec4(footprints.pixel(x, y)[0], footprints.pixel(x, y)[1], footprints.pixel(x, y)[2], footprints.pixel(x, y)[3]);
        input.camera = camera;
        input.light = light;
        input.lamp = lamp;
        input.light_radius = lamp.is_flat() ? 0.0 : lamp.equivalent_radius();  // what LIGHTRADIUS gives the GPU beside a flat light
        return input;
    };
    std::atomic<int> next_row{0};
    std::exception_ptr failure;
    std::mutex failure_mutex;
    const auto shade_rows = [&] {
        try {
            for (int y = next_row++; y < request.height; y = next_row++)
                for (int x = 0; x < request.width; ++x) {
                    if (positions.pixel(x, y)[3] <= 0.0f) continue;  // not covered
                    const reference::ShadingInput input = input_at(x, y);
                    Shaded& out = shaded[static_cast<size_t>(y) * static_cast<size_t>(request.width) + static_cast<size_t>(x)];
                    out.cpu = ref->shade(input, reference_context);
                    // The slack only matters where the tolerance alone fails or the 8-bit codes differ,
                    // and costs several shadings: computed there only.
                    double error = 0;
                    for (int c = 0; c < 4; ++c) {
                        const double difference = std::abs(gpu.pixel(x, y)[c] - out.cpu[static_cast<size_t>(c)]);
                        error = std::isnan(difference) ? std::numeric_limits<double>::infinity() : std::max(error, difference);
                    }
                    const bool needed = error > tolerance || codes_differ(gpu.pixel(x, y), out.cpu);
                    out.slack = ref->slack && needed ? ref->slack(input, reference_context) : 0.0;
                    if (with_truth) {
                        const unsigned seed = static_cast<unsigned>(y * request.width + x + 1);
                        out.truth = ref->truth(input, reference_context, seed);
                        out.second_truth = ref->truth_deterministic_without_environment && request.scene.environment.source.empty()
                                               ? out.truth
                                               : ref->truth(input, reference_context, seed + 0x9E3779B9u);  // another sequence
                    }
                }
        } catch (...) {
            const std::lock_guard lock(failure_mutex);
            if (!failure) failure = std::current_exception();
            next_row = request.height;
        }
    };
    {
        std::vector<std::jthread> workers;
        const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
        for (unsigned i = 1; i < cores; ++i) workers.emplace_back(shade_rows);
        shade_rows();
    }
    if (failure) std::rethrow_exception(failure);

    result.heat_map = image::FloatImage(request.width, request.height, 4);
    double error_sum = 0;
    for (int y = 0; y < request.height; ++y)
        for (int x = 0; x < request.width; ++x) {
            float* heat_pixel = result.heat_map.pixel(x, y);
            heat_pixel[3] = 1.0f;
            if (positions.pixel(x, y)[3] <= 0.0f) continue;  // not covered
            const Shaded& pixel = shaded[static_cast<size_t>(y) * static_cast<size_t>(request.width) + static_cast<size_t>(x)];
            const std::array<double, 4>& cpu = pixel.cpu;
            const double slack = pixel.slack;
            double pixel_error = 0;
            const bool mismatch = codes_differ(gpu.pixel(x, y), cpu);
            for (int c = 0; c < 4; ++c) {
                const double difference = std::abs(gpu.pixel(x, y)[c] - cpu[c]);
                // A NaN on either side is the largest error there is, never hidden by max().
                pixel_error = std::isnan(difference) ? std::numeric_limits<double>::infinity() : std::max(pixel_error, difference);
            }
            ++result.pixels;
            error_sum += pixel_error;
            // A pixel that needed its slack (a jump, or a highlight as sensitive as the slack says) is
            // judged by the float bound alone: the 8-bit check would only repeat it. So is one whose
            // 8-bit codes differ (near black, where sRGB's slope is 12.9) by less than its slack.
            const bool used_slack = (pixel_error > tolerance || (mismatch && pixel_error <= slack)) && pixel_error <= tolerance + slack;
            if (used_slack) ++result.pixels_within_slack;
            if (mismatch && !used_slack) ++result.mismatched_8bit;
            if (pixel_error > tolerance + slack) ++result.exceeding;
            if (pixel_error > result.max_abs_error || result.worst_pixel.x < 0) {
                result.max_abs_error = std::max(result.max_abs_error, pixel_error);
                result.worst_pixel.x = x;
                result.worst_pixel.y = y;
                for (int c = 0; c < 4; ++c) result.worst_pixel.gpu[c] = gpu.pixel(x, y)[c];
                result.worst_pixel.cpu = cpu;
            }
            const auto colour = heat(pixel_error / (tolerance + slack));
            std::copy(colour.begin(), colour.end(), heat_pixel);
        }
    result.mean_abs_error = result.pixels > 0 ? error_sum / static_cast<double>(result.pixels) : 0.0;
    if (with_truth)
        result.ground_truth = judge_ground_truth(request.width, request.height, [&](int x, int y)
                                                     -> std::optional<std::tuple<std::array<double, 4>, std::array<double, 4>, std::array<double, 4>>> {
            if (positions.pixel(x, y)[3] <= 0.0f) return std::nullopt;
            const Shaded& pixel = shaded[static_cast<size_t>(y) * static_cast<size_t>(request.width) + static_cast<size_t>(x)];
            return std::tuple{pixel.cpu, pixel.truth, pixel.second_truth};
        });
    if (result.ground_truth) result.ground_truth->method = ref->truth_method;
    result.pass = result.pixels > 0 && result.mismatched_8bit == 0 && result.exceeding == 0;
    return result;
}

}  // namespace fxview::app

// `fxview brdf-plot FILE... --view polar|albedo|lobe|slice|sphere --out P.png [--csv F.csv]`: BRDF Explorer's
// views, headless. Values come from the GPU (app/brdf_evaluation.hpp), so any .brdf file works.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>

#include "app/brdf_check.hpp"
#include "app/brdf_evaluation.hpp"
#include "app/brdf_plot.hpp"
#include "app/commands.hpp"
#include "app/offscreen_render.hpp"
#include "app/scene_options.hpp"
#include "app/value_parsing.hpp"
#include "core/error.hpp"
#include "fit/merl.hpp"
#include "image/image_file.hpp"

namespace fxview::app {
namespace {

constexpr int kPlaneSamples = 721;  // 180°/721 apart across the plane of incidence

double mean_rgb(const float* p) { return (static_cast<double>(p[0]) + p[1] + p[2]) / 3.0; }

// An image's values as CSV rows `header` + r,g,b, with the two coordinates of pixel (x, y) (y from the
// top) that `coordinates` gives.
void write_image_csv(const std::string& path, const image::FloatImage& image, const std::string& header,
                     const std::function<std::pair<double, double>(int, int)>& coordinates) {
    std::ofstream csv(path);
    if (!csv) throw Error("cannot write " + path);
    csv << header << ",r,g,b\n";
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const auto [a, b] = coordinates(x, y);
            const float* p = image.pixel(x, y);
            csv << a << "," << b << "," << p[0] << "," << p[1] << "," << p[2] << "\n";
        }
    std::printf("wrote %s\n", path.c_str());
}

}  // namespace

CommandRunner add_brdf_plot_command(CLI::App& app) {
    struct Options {
        std::vector<std::string> files, measured;
        std::vector<std::string> sets;
        std::string view = "polar", out, csv, size = "800x600", backend = "egl", technique;
        double incidence = 30, phi_d = 90, phi_i = 0;
        bool logarithmic = false;
    };
    auto o = std::make_shared<Options>();
    CLI::App* command = app.add_subcommand("brdf-plot", "Plot BRDFs (.brdf files): polar plot of the plane of incidence, albedo, lit sphere");
    command->add_option("files", o->files, "One or more .brdf files (overlaid in the polar and albedo views)");
    command->add_option("--measured", o->measured, "A MERL .binary file to overlay (repeatable; polar and albedo views)");
    command->add_option("--view", o->view, "polar (default), albedo, lobe, slice or sphere")
        ->check(CLI::IsMember({"polar", "albedo", "lobe", "slice", "sphere"}));
    command->add_option("--phi-d", o->phi_d, "Difference azimuth of the slice view, degrees")->check(finite_range(0.0, 180.0));
    command->add_option("--out", o->out, "PNG (or EXR/PFM for the sphere) to write")->required();
    command->add_option("--csv", o->csv, "Also write the plotted values as CSV");
    command->add_option("--incidence", o->incidence, "Angle of incidence for the polar view, degrees")->check(finite_range(0.0, 89.0));
    command->add_option("--phi-i", o->phi_i, "Azimuth of incidence (polar, lobe and albedo views), degrees: the polar view plots the plane of incidence at it")
        ->check(finite_range(0.0, 360.0));
    command->add_flag("--log", o->logarithmic, "Logarithmic radius in the polar view (four decades)");
    command->add_option("--size", o->size, "Image size WxH");
    command->add_option("--set", o->sets, "NAME=VALUE for every file's parameters (repeatable)");
    command->add_option("-t,--technique", o->technique, "The model of an effect with several (analytic.fx's BrdfModel); the sphere's technique");
    command->add_option("--backend", o->backend, "egl (default), egl-device or osmesa");
    return [o] {
        const glm::ivec2 size = parse_size("--size", o->size);
        if (o->files.empty() && o->measured.empty()) throw UsageError("brdf-plot needs a .brdf file or --measured FILE.binary");
        if (o->view == "sphere") {
            if (o->files.size() != 1 || !o->measured.empty()) throw UsageError("brdf-plot --view sphere draws one .brdf file");
            SceneOptions scene;
            scene.size = o->size;
            scene.backend = o->backend;
            scene.effect.path = o->files[0];
            scene.effect.technique = o->technique;  // empty: the default (Lit for .brdf files)
            scene.effect.sets = o->sets;
            const image::FloatImage sphere = render_offscreen(to_render_request(scene));
            image::write_image(o->out, sphere);
            std::printf("wrote %s (%dx%d)\n", o->out.c_str(), size.x, size.y);
            if (!o->csv.empty())  // the lit sphere's linear radiance per pixel
                write_image_csv(o->csv, sphere, "x,y", [](int x, int y) { return std::pair<double, double>(x, y); });
            return 0;
        }
        if (o->view == "lobe" || o->view == "slice") {
            if (o->files.size() != 1 || !o->measured.empty()) throw UsageError("brdf-plot --view " + o->view + " draws one .brdf file");
            EffectOptions effect;
            effect.path = o->files[0];
            effect.sets = o->sets;
            effect.technique = o->technique;
            BrdfEvaluation evaluation(effect, o->backend);
            if (o->view == "lobe") {
                const image::FloatImage hemisphere = evaluate_brdf_hemisphere(evaluation.session(), o->incidence, 144, 60, o->phi_i);
                image::write_image(o->out, lobe_chart(hemisphere, std::filesystem::path(o->files[0]).stem().string(), o->incidence, {size.x, size.y}));
                if (!o->csv.empty())  // θo up from the bottom row, φo across (evaluate_brdf_hemisphere)
                    write_image_csv(o->csv, hemisphere, "theta_o_deg,phi_o_deg", [&hemisphere](int x, int y) {
                        return std::pair<double, double>(90.0 * (hemisphere.height - y - 0.5) / hemisphere.height, 360.0 * (x + 0.5) / hemisphere.width);
                    });
            } else {
                // The values themselves in EXR/PFM; in PNG scaled so that the 99th percentile is white.
                // A PNG is a chart (axes, colour bar) around the slice; EXR/PFM hold f itself at --size.
                const bool png = std::filesystem::path(o->out).extension() == ".png";
                const int width = png ? std::max(16, size.x - kSliceMargins.left - kSliceMargins.right) : size.x;
                const int height = png ? std::max(16, size.y - kSliceMargins.top - kSliceMargins.bottom) : size.y;
                image::FloatImage slice = evaluate_brdf_slice(evaluation.session(), o->phi_d, width, height);
                if (!o->csv.empty())  // the values themselves, before any display scaling; θh across, θd up
                    write_image_csv(o->csv, slice, "theta_h_deg,theta_d_deg", [&slice](int x, int y) {
                        return std::pair<double, double>(90.0 * (x + 0.5) / slice.width, 90.0 * (slice.height - y - 0.5) / slice.height);
                    });
                const float white = png ? scale_slice_for_display(slice) : 0.0f;
                image::write_image(o->out, png ? slice_chart(slice, white, o->phi_d, {width + kSliceMargins.left + kSliceMargins.right,
                                                                                       height + kSliceMargins.top + kSliceMargins.bottom})
                                               : slice);
                if (png) std::printf("slice at phi_d = %g deg: theta_h 0-90 deg across, theta_d 90 (top) to 0 deg; white = f of %g\n", o->phi_d, white);
            }
            std::printf("wrote %s (%dx%d)\n", o->out.c_str(), size.x, size.y);
            return 0;
        }
        std::vector<BrdfSeries> series;
        std::vector<std::vector<std::array<double, 3>>> rgb;  // per file, per sample, for the CSV
        std::vector<double> incidences;
        BrdfCheckOptions albedo_only;
        albedo_only.phi_i_degrees = {o->phi_i};
        albedo_only.reciprocity = false;
        const auto add_albedo = [&](const BrdfCheck& check, BrdfSeries& s, std::vector<std::array<double, 3>>& values) {
            incidences.clear();
            for (const AlbedoEstimate& e : check.albedo) {
                incidences.push_back(e.incidence_degrees);
                s.values.push_back((e.rgb[0] + e.rgb[1] + e.rgb[2]) / 3.0);
                values.push_back(e.rgb);
            }
            if (check.energy == BrdfCheck::Energy::Unresolved) std::fprintf(stderr, "brdf-plot: %s: %s\n", s.name.c_str(), check.unresolved_reason.c_str());
        };
        for (const auto& file : o->files) {
            EffectOptions effect;
            effect.path = file;
            effect.sets = o->sets;
            effect.technique = o->technique;
            BrdfEvaluation evaluation(effect, o->backend);
            BrdfSeries s{std::filesystem::path(file).stem().string(), {}};
            std::vector<std::array<double, 3>> values;
            if (o->view == "polar") {
                const image::FloatImage plane = evaluate_brdf_plane(evaluation.session(), o->incidence, kPlaneSamples, false, o->phi_i);
                for (int k = 0; k < kPlaneSamples; ++k) {
                    const float* p = plane.pixel(k, 0);
                    s.values.push_back(mean_rgb(p));
                    values.push_back({p[0], p[1], p[2]});
                }
            } else {
                add_albedo(check_brdf(gpu_sample_renderer(evaluation.session()), albedo_only), s, values);
            }
            series.push_back(std::move(s));
            rgb.push_back(std::move(values));
        }
        // Measured data: the same directions, looked up in the table on the CPU.
        for (const auto& file : o->measured) {
            const fit::MerlBrdf merl = fit::read_merl(file);
            BrdfSeries s{std::filesystem::path(file).stem().string() + " (measured)", {}};
            std::vector<std::array<double, 3>> values;
            if (o->view == "polar") {
                values = measured_plane(merl, o->incidence, kPlaneSamples, o->phi_i);
                for (const auto& f : values) s.values.push_back((f[0] + f[1] + f[2]) / 3.0);
            } else {
                add_albedo(check_brdf(measured_sample_renderer(merl), albedo_only), s, values);
            }
            series.push_back(std::move(s));
            rgb.push_back(std::move(values));
        }
        for (const BrdfSeries& s : series)
            if (const size_t bad = not_finite(s); bad > 0)
                std::fprintf(stderr, "brdf-plot: %s: %zu of %zu values are NaN or infinite: not drawn (the legend says so)\n", s.name.c_str(), bad,
                             s.values.size());
        const ChartSize chart{size.x, size.y};
        image::write_image(o->out, o->view == "polar" ? polar_chart(series, o->incidence, o->logarithmic, chart)
                                                      : albedo_chart(series, incidences, chart));
        std::printf("wrote %s (%dx%d)\n", o->out.c_str(), size.x, size.y);
        if (!o->csv.empty()) {
            std::ofstream csv(o->csv);
            if (!csv) throw Error("cannot write " + o->csv);
            csv << (o->view == "polar" ? "theta_o_deg" : "theta_i_deg") << ",file,r,g,b\n";
            for (size_t f = 0; f < series.size(); ++f)
                for (size_t k = 0; k < rgb[f].size(); ++k) {
                    const double angle = o->view == "polar" ? -90.0 + 180.0 * (k + 0.5) / kPlaneSamples : incidences[k];
                    csv << angle << "," << series[f].name << "," << rgb[f][k][0] << "," << rgb[f][k][1] << "," << rgb[f][k][2] << "\n";
                }
            std::printf("wrote %s\n", o->csv.c_str());
        }
        return 0;
    };
}

}  // namespace fxview::app

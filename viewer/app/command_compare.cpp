#include <nlohmann/json.hpp>

#include <filesystem>
#include <iostream>

#include "app/commands.hpp"
#include "app/compare_sweep.hpp"
#include "app/gpu_cpu_compare.hpp"
#include "effect/parser.hpp"
#include "core/error.hpp"
#include "image/image_file.hpp"

namespace fxview::app {

namespace {

int run_sweep(const RenderRequest& base, const std::vector<std::string>& techniques, int random_cases, unsigned seed, bool json) {
    const effect::Effect effect = effect::load_effect(base.effect.path, effect_load_options(base.effect.access));
    const std::vector<SweepCase> cases = sweep_cases(effect, random_cases, seed);
    int failures = 0, runs = 0;
    for (const auto& technique : techniques)
        for (const auto& c : cases) {
            RenderRequest request = base;
            request.effect.sets.insert(request.effect.sets.end(), c.sets.begin(), c.sets.end());
            CompareResult r;
            std::string error;
            try {
                r = compare_technique(request, technique, {});
            } catch (const std::exception& e) {
                error = e.what();
            }
            ++runs;
            const bool failed = !error.empty() || !r.pass;
            failures += failed ? 1 : 0;
            std::string sets;
            for (const auto& s : c.sets) sets += (sets.empty() ? "" : " ") + s;
            if (json) {
                nlohmann::json out = {{"technique", technique}, {"case", c.label}, {"sets", c.sets}, {"pass", !failed}};
                if (!error.empty()) out["error"] = error;
                else out.update({{"max_abs_error", r.max_abs_error}, {"tolerance", r.tolerance}, {"exceeding", r.exceeding},
                                 {"mismatched_8bit", r.mismatched_8bit}, {"pixels", r.pixels}});
                std::cout << out.dump() << std::endl;
            } else if (failed) {
                if (!error.empty()) std::printf("FAIL  %-18s %-22s error: %s   [%s]\n", technique.c_str(), c.label.c_str(), error.c_str(), sets.c_str());
                else std::printf("FAIL  %-18s %-22s max %.3g > tolerance %.3g (%ld pixels, %ld 8-bit)   [%s]\n", technique.c_str(),
                                 c.label.c_str(), r.max_abs_error, r.tolerance, r.exceeding, r.mismatched_8bit, sets.c_str());
                std::fflush(stdout);
            }
        }
    if (!json) std::printf("sweep: %d frames compared (%zu techniques x %zu cases), %d failed\n", runs, techniques.size(), cases.size(), failures);
    return failures == 0 ? 0 : 1;
}

}  // namespace

CommandRunner add_compare_command(CLI::App& app) {
    struct Options {
        SceneOptions scene;
        std::vector<std::string> reference_sets;
        std::string heatmap = "out/compare.png";
        bool json = false;
        bool sweep = false;
        bool ground_truth = false;
        int sweep_random = 4;
        unsigned seed = 1;
    };
    auto options = std::make_shared<Options>();
    options->scene.size = "128x128";
    CLI::App* command = app.add_subcommand(
        "compare", "Render a technique on the GPU and check every covered pixel against its CPU reference");
    add_scene_options(*command, options->scene);
    command->add_option("--reference-set", options->reference_sets,
                        "NAME=VALUE for the CPU side only (proves that the comparison can fail)");
    command->add_option("--heatmap", options->heatmap, "Error heat map (PNG); -T is appended to the name per technique")
        ->capture_default_str();
    command->add_flag("--json", options->json, "Print one JSON object per technique");
    command->add_flag("--ground-truth", options->ground_truth,
                      "Also measure the technique's own approximation (image-based lighting's split sum) against the integral it "
                      "stands for, by Monte Carlo: CIEDE2000 per pixel and a heat map (NAME-truth.png)");
    command->add_flag("--sweep", options->sweep,
                      "Every parameter at its UI minimum, maximum and middle (alone), plus random combinations: a table of failures");
    command->add_option("--sweep-random", options->sweep_random, "Random combinations per technique in --sweep")
        ->check(CLI::Range(0, 10000))
        ->capture_default_str();
    command->add_option("--seed", options->seed, "Seed of the random combinations (reproducible)")->capture_default_str();
    return [options] {
        RenderRequest request = to_render_request(options->scene);
        if (request.effect.path.empty()) throw UsageError("compare needs an effect file");
        if (options->scene.samples_given.value_or(0) > 1) throw UsageError("compare renders without MSAA: every pixel must come from one fragment");
        request.samples = 0;  // a preset's MSAA is for pictures, not for comparisons
        std::vector<std::string> techniques;
        if (request.effect.technique.empty()) techniques = technique_names(request.effect);
        else techniques = {request.effect.technique};
        if (options->sweep) return run_sweep(request, techniques, options->sweep_random, options->seed, options->json);
        bool all_pass = true;
        for (const auto& technique : techniques) {
            const CompareResult r = compare_technique(request, technique, options->reference_sets, options->ground_truth);
            all_pass = all_pass && r.pass;
            if (!options->heatmap.empty() && r.has_reference) {
                const std::filesystem::path p(options->heatmap);
                if (!p.parent_path().empty()) std::filesystem::create_directories(p.parent_path());
                image::write_image((p.parent_path() / (p.stem().string() + "-" + technique + p.extension().string())).string(),
                                   r.heat_map);
                if (r.ground_truth)
                    image::write_image((p.parent_path() / (p.stem().string() + "-" + technique + "-truth" + p.extension().string())).string(),
                                       r.ground_truth->heat_map);
            }
            if (options->json) {
                nlohmann::json out = {{"technique", r.technique}, {"reference", r.has_reference}, {"pass", r.pass}};
                if (r.has_reference) {
                    out.update({{"pixels", r.pixels},
                                {"max_abs_error", r.max_abs_error},
                                {"mean_abs_error", r.mean_abs_error},
                                {"worst_pixel", {{"x", r.worst_pixel.x}, {"y", r.worst_pixel.y}, {"gpu", r.worst_pixel.gpu}, {"cpu", r.worst_pixel.cpu}}},
                                {"mismatched_8bit", r.mismatched_8bit},
                                {"exceeding", r.exceeding},
                                {"pixels_within_slack", r.pixels_within_slack},
                                {"tolerance", r.tolerance},
                                {"tolerance_reason", r.tolerance_reason}});
                    if (r.pixels == 0) out["error"] = "the mesh covers no pixel: nothing was compared";
                    if (r.ground_truth)
                        out["ground_truth"] = {{"method", r.ground_truth->method}, {"pixels", r.ground_truth->pixels},
                                               {"mean_delta_e2000", r.ground_truth->mean_delta_e},
                                               {"p95_delta_e2000", r.ground_truth->p95_delta_e},
                                               {"max_delta_e2000", r.ground_truth->max_delta_e},
                                               {"noise_mean_delta_e2000", r.ground_truth->mean_noise_delta_e},
                                               {"noise_p95_delta_e2000", r.ground_truth->p95_noise_delta_e},
                                               {"pixels_beyond_noise", r.ground_truth->pixels_beyond_noise},
                                               {"mean_delta_e2000_beyond_noise", r.ground_truth->mean_delta_e_beyond_noise},
                                               {"worst_pixel", {{"x", r.ground_truth->worst_x}, {"y", r.ground_truth->worst_y},
                                                                {"reference", r.ground_truth->worst_reference}, {"truth", r.ground_truth->worst_truth}}}};
                } else {
                    out["error"] = "no CPU reference for this technique";
                }
                std::cout << out.dump() << "\n";
            } else if (!r.has_reference) {
                std::cout << r.technique << ": no CPU reference - FAIL\n";
            } else {
                std::printf("%-20s %s  pixels %ld  max %.3g  mean %.3g  8-bit mismatches %ld  tolerance %.3g", r.technique.c_str(),
                            r.pass ? "pass" : "FAIL", r.pixels, r.max_abs_error, r.mean_abs_error, r.mismatched_8bit, r.tolerance);
                if (r.exceeding > 0) std::printf("  %ld beyond tolerance and slack", r.exceeding);
                if (r.pixels_within_slack > 0) std::printf("  (%ld pixels within their slack)", r.pixels_within_slack);
                if (r.pixels == 0) std::printf("  - the mesh covers no pixel: nothing was compared (check the camera and mesh)");
                std::printf("\n");
                if (r.ground_truth)
                    std::printf("%-20s approximation against %s: CIEDE2000 mean %.3g, 95th percentile %.3g, max %.3g at (%d, %d)\n",
                                "", r.ground_truth->method.c_str(), r.ground_truth->mean_delta_e, r.ground_truth->p95_delta_e, r.ground_truth->max_delta_e,
                                r.ground_truth->worst_x, r.ground_truth->worst_y);
                if (r.ground_truth && r.ground_truth->mean_noise_delta_e == 0 && r.ground_truth->p95_noise_delta_e == 0)
                    std::printf("%-20s (deterministic: no noise of its own)\n", "");
                else if (r.ground_truth)
                    std::printf("%-20s the integral's own noise (two estimates): CIEDE2000 mean %.3g, 95th percentile %.3g; errors beyond twice "
                                "it at %ld of %ld pixels, mean %.3g there\n",
                                "", r.ground_truth->mean_noise_delta_e, r.ground_truth->p95_noise_delta_e, r.ground_truth->pixels_beyond_noise,
                                r.ground_truth->pixels, r.ground_truth->mean_delta_e_beyond_noise);
                else if (options->ground_truth)
                    std::printf("%-20s exact up to float rounding: no approximation to measure (or no environment)\n", "");
            }
        }
        return all_pass ? 0 : 1;
    };
}

}  // namespace fxview::app

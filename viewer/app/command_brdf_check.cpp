// `fxview brdf-check FILE`: evaluates the BRDF at brdf-check's sample directions (f(L, V), and
// f(V, L) for reciprocity) and prints what app/brdf_check.hpp measures.
#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>

#include "app/brdf_check.hpp"
#include "app/brdf_evaluation.hpp"
#include "app/commands.hpp"
#include "app/value_parsing.hpp"

namespace fxview::app {
namespace {

nlohmann::json to_json(const BrdfCheck& c, const std::string& path) {
    nlohmann::json albedo = nlohmann::json::array();
    for (const AlbedoEstimate& e : c.albedo)
        albedo.push_back({{"incidence_deg", e.incidence_degrees}, {"phi_i_deg", e.phi_i_degrees}, {"rgb", e.rgb}, {"error", e.error},
                          {"converged", e.converged}});
    return {{"effect", path},
            {"albedo", albedo},
            {"max_albedo", c.max_albedo},
            {"max_albedo_incidence_deg", c.max_albedo_degrees},
            {"max_albedo_phi_i_deg", c.max_albedo_phi_degrees},
            {"energy", energy_verdict(c.energy)},
            {"unresolved_reason", c.unresolved_reason},
            {"conserves_energy", c.conserves_energy},
            {"energy_tolerance", BrdfCheck::kEnergyTolerance},
            {"convergence_tolerance", BrdfCheck::kConvergence},
            {"reciprocity_max_relative", c.reciprocity},
            {"reciprocal", c.reciprocal},
            {"reciprocity_tolerance", BrdfCheck::kReciprocityTolerance},
            {"reciprocity_where_deg", {c.reciprocity_incidence, c.reciprocity_exitance, c.reciprocity_azimuth, c.reciprocity_phi_i}},
            {"negative_samples", c.negative},
            {"non_finite_samples", c.non_finite},
            {"non_finite_where_deg", c.non_finite_where},
            {"samples", c.samples},
            {"file_sampling", c.file_sampling},
            {"file_sampling_note", c.file_sampling_note}};
}

void print_text(const BrdfCheck& c, const std::string& path, const BrdfCheckOptions& options) {
    std::printf("%s: %d incidence angles (1..89 deg) at %zu azimuth(s) of incidence, %d sampling strategies%s on two grids of at "
                "least %d directions each, up to 16 times that where needed\n",
                path.c_str(), kGridIncidences, options.phi_i_degrees.size(), brdf::kSamplingStrategies + (c.file_sampling ? 1 : 0),
                c.file_sampling ? " (the file's own isFunc among them)" : "", kSampleSide * kSampleSide);
    if (!c.file_sampling_note.empty()) std::printf("%s: warning: %s\n", path.c_str(), c.file_sampling_note.c_str());
    std::printf("directional albedo (R G B +- estimated error) at phi_i %g deg:\n", options.phi_i_degrees.front());
    for (size_t i = 0; i < static_cast<size_t>(kGridIncidences); ++i) {
        const AlbedoEstimate& e = c.albedo[i];
        if (i % 5 != 0 && i + 1 != static_cast<size_t>(kGridIncidences) && e.converged) continue;
        std::printf("  theta_i %4.0f deg  %.4f %.4f %.4f  +- %.1e%s\n", e.incidence_degrees, e.rgb[0], e.rgb[1], e.rgb[2],
                    std::max({e.error[0], e.error[1], e.error[2]}), e.converged ? "" : "  (not converged)");
    }
    std::printf("largest albedo %.4f at theta_i %.0f deg, phi_i %g deg: ", c.max_albedo, c.max_albedo_degrees, c.max_albedo_phi_degrees);
    switch (c.energy) {
        case BrdfCheck::Energy::Conserves: std::printf("energy conserving\n"); break;
        case BrdfCheck::Energy::Violates: std::printf("REFLECTS MORE THAN IT RECEIVES\n"); break;
        case BrdfCheck::Energy::Unresolved: std::printf("UNRESOLVED: %s\n", c.unresolved_reason.c_str()); break;
    }
    std::printf("reciprocity: largest relative |f(L,V) - f(V,L)| = %.3g", c.reciprocity);
    if (c.reciprocity > 0)
        std::printf(" (theta_i %.0f, phi_i %g, theta_o %.1f, phi_o %.1f deg)", c.reciprocity_incidence, c.reciprocity_phi_i, c.reciprocity_exitance,
                    c.reciprocity_azimuth);
    std::printf(": %s", c.reciprocal ? "reciprocal" : "NOT RECIPROCAL");
    std::printf("\nnegative values at %ld of %ld samples, NaN or infinite at %ld", c.negative, c.samples, c.non_finite);
    if (c.non_finite > 0)
        std::printf(" (the first at theta_i %.0f, phi_i %g, theta_o %.4f, phi_o %.4f deg)", c.non_finite_where[0], c.non_finite_where[1],
                    c.non_finite_where[2], c.non_finite_where[3]);
    std::printf("\n");
}

}  // namespace

CommandRunner add_brdf_check_command(CLI::App& app) {
    struct Options {
        EffectOptions effect;
        std::string backend = "egl";
        std::vector<double> phi_i;
        bool json = false;
    };
    auto o = std::make_shared<Options>();
    CLI::App* command = app.add_subcommand("brdf-check", "Check a BRDF (.brdf file) for energy conservation, reciprocity, negative and NaN values");
    command->add_option("effect", o->effect.path, "A .brdf file (or an effect with the BrdfGrid technique)")->required();
    add_effect_options(*command, o->effect);
    command->add_option("--backend", o->backend, "egl (default), egl-device or osmesa");
    command->add_option("--phi-i", o->phi_i, "Azimuths of incidence to check, degrees (default 0 45 90 135)")
        ->check(finite_range(0.0, 360.0))
        ->expected(1, 16);
    command->add_flag("--json", o->json, "Print one JSON object");
    return [o] {
        BrdfEvaluation evaluation(o->effect, o->backend);
        BrdfCheckOptions options;
        if (!o->phi_i.empty()) options.phi_i_degrees = o->phi_i;
        options.file_sampler = has_file_sampler(evaluation.session());
        const BrdfCheck c = check_brdf(gpu_sample_renderer(evaluation.session()), options);
        if (o->json) std::cout << to_json(c, o->effect.path).dump() << "\n";
        else print_text(c, o->effect.path, options);
        return 0;
    };
}

}  // namespace fxview::app

// `fxview brdf-check FILE`: evaluates the BRDF over the grid twice (f(L, V), then f(V, L)) and prints
// what app/brdf_check.hpp measures.
#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>

#include "app/brdf_check.hpp"
#include "app/brdf_evaluation.hpp"
#include "app/commands.hpp"

namespace fxview::app {

CommandRunner add_brdf_check_command(CLI::App& app) {
    struct Options {
        EffectOptions effect;
        std::string backend = "egl";
        bool json = false;
    };
    auto o = std::make_shared<Options>();
    CLI::App* command = app.add_subcommand("brdf-check", "Check a BRDF (.brdf file) for energy conservation, reciprocity, negative and NaN values");
    command->add_option("effect", o->effect.path, "A .brdf file (or an effect with the BrdfGrid technique)")->required();
    add_effect_options(*command, o->effect);
    command->add_option("--backend", o->backend, "egl (default), egl-device or osmesa");
    command->add_flag("--json", o->json, "Print one JSON object");
    return [o] {
        BrdfEvaluation evaluation(o->effect, o->backend);
        const image::FloatImage forward = evaluate_brdf_grid(evaluation.session(), false), swapped = evaluate_brdf_grid(evaluation.session(), true);
        const BrdfCheck c = analyse_brdf_grid(forward, swapped);
        if (o->json) {
            nlohmann::json albedo = nlohmann::json::array();
            for (size_t i = 0; i < c.albedo.size(); ++i) albedo.push_back({{"incidence_deg", c.incidence_degrees[i]}, {"rgb", c.albedo[i]}});
            std::cout << nlohmann::json{{"effect", o->effect.path},
                                        {"albedo", albedo},
                                        {"max_albedo", c.max_albedo},
                                        {"max_albedo_incidence_deg", c.max_albedo_degrees},
                                        {"conserves_energy", c.conserves_energy},
                                        {"energy_tolerance", BrdfCheck::kEnergyTolerance},
                                        {"reciprocity_max_relative", c.reciprocity},
                                        {"reciprocal", c.reciprocal},
                                        {"reciprocity_tolerance", BrdfCheck::kReciprocityTolerance},
                                        {"reciprocity_where_deg", {c.reciprocity_incidence, c.reciprocity_exitance, c.reciprocity_azimuth}},
                                        {"negative_samples", c.negative},
                                        {"non_finite_samples", c.non_finite},
                                        {"samples", c.samples}}
                             .dump()
                      << "\n";
            return 0;
        }
        std::printf("%s: %d incidence angles in the tangent plane (1..89 deg), %d outgoing directions each\n", o->effect.path.c_str(),
                    kGridIncidences, kGridTile * kGridTile);
        std::printf("directional albedo (R G B):\n");
        for (size_t i = 0; i < c.albedo.size(); i += 5)
            std::printf("  theta_i %4.0f deg  %.4f %.4f %.4f\n", c.incidence_degrees[i], c.albedo[i][0], c.albedo[i][1], c.albedo[i][2]);
        std::printf("largest albedo %.4f at theta_i %.0f deg: %s\n", c.max_albedo, c.max_albedo_degrees,
                    c.conserves_energy ? "energy conserving" : "REFLECTS MORE THAN IT RECEIVES");
        std::printf("reciprocity: largest relative |f(L,V) - f(V,L)| = %.3g", c.reciprocity);
        if (c.reciprocity > 0)
            std::printf(" (theta_i %.0f, theta_o %.1f, phi_o %.1f deg)", c.reciprocity_incidence, c.reciprocity_exitance, c.reciprocity_azimuth);
        std::printf(": %s", c.reciprocal ? "reciprocal" : "NOT RECIPROCAL");
        std::printf("\nnegative values at %ld of %ld samples, NaN or infinite at %ld\n", c.negative, c.samples, c.non_finite);
        return 0;
    };
}

}  // namespace fxview::app

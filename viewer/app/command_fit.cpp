// `fxview fit` (seed 000's fitter, grown to several models: an analytic BRDF to a measured one) and `fxview brdf-grid`
// (synthetic "measurements" of an analytic model on the thesis' grid, the thesis' way of checking
// its Levenberg-Marquardt).
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <random>

#include "app/commands.hpp"
#include "fit/fit_preview.hpp"
#include "app/value_parsing.hpp"
#include "brdf/models.hpp"
#include "core/error.hpp"
#include "fit/brdf_fit.hpp"
#include "fit/measurement.hpp"
#include "fit/merl.hpp"
#include "image/image_file.hpp"

namespace fxview::app {
namespace {

void create_parent(const std::string& path) {
    const std::filesystem::path p(path);
    if (!p.parent_path().empty()) std::filesystem::create_directories(p.parent_path());
}

std::string join(const std::vector<double>& values, const char* separator = ",", int digits = 10) {
    std::string out;
    char text[64];
    for (size_t i = 0; i < values.size(); ++i) {
        std::snprintf(text, sizeof text, "%.*g", digits, values[i]);
        out += (i ? separator : "") + std::string(text);
    }
    return out;
}

// The parameters as the model's technique reads them, one line each: name,r,g,b or name,value.
void write_result_csv(const fit::FitResult& r, const std::string& path) {
    create_parent(path);
    std::ofstream out(path);
    if (!out) throw Error(path + ": cannot write");
    out << "# " << r.title << " (model " << r.model << ", technique " << r.technique << " of effects/brdf/analytic.fx)\n";
    out << "parameter,values\n";
    for (const fit::FittedParameter& p : r.parameters) out << p.name << ',' << join(p.values) << '\n';
    if (r.model == fit::kDefaultModel) {
        out << "# renderer form (eq. 4.23/4.24): f = (1 - Rs) Rd/pi + Rs cs' lobe\n";
        out << "Rs," << join({r.rs}) << '\n';
        out << "Rd," << join({r.rd_renderer.begin(), r.rd_renderer.end()}) << '\n';
        out << "cs_renderer," << join({r.cs_renderer.begin(), r.cs_renderer.end()}) << '\n';
    }
    out << "error_rgb," << join({r.error_rgb}) << '\n';
    out << "weighted_rms," << join({r.weighted_rms}) << '\n';
    if (!out) throw Error(path + ": write failed");
}

// The ranking of `--model all` as CSV: one line per model, best first.
void write_ranking_csv(const std::vector<fit::FitResult>& results, const std::string& path) {
    create_parent(path);
    std::ofstream out(path);
    if (!out) throw Error(path + ": cannot write");
    out << "rank,model,weighted_cost,robust_objective,weighted_rms,error_rgb,converged,parameters\n";
    for (size_t i = 0; i < results.size(); ++i) {
        const fit::FitResult& r = results[i];
        std::string parameters;
        for (const fit::FittedParameter& p : r.parameters) parameters += (parameters.empty() ? "" : " ") + p.name + "=" + join(p.values);
        out << i + 1 << ',' << r.model << ',' << join({r.cost}) << ',' << join({r.objective}) << ',' << join({r.weighted_rms}) << ',' << join({r.error_rgb}) << ','
            << (r.converged ? "yes" : "no") << ",\"" << parameters << "\"\n";
    }
    if (!out) throw Error(path + ": write failed");
}

// A preset for effects/brdf/analytic.fx: the fitted BRDF in the viewer with the model's technique.
void write_preset(const fit::FitResult& r, const std::string& path) {
    create_parent(path);
    std::ofstream out(path);
    if (!out) throw Error(path + ": cannot write");
    nlohmann::json parameters = nlohmann::json::object();
    for (const fit::FittedParameter& p : r.parameters) parameters[p.uniform] = p.values.size() == 1 ? nlohmann::json(p.values[0]) : nlohmann::json(p.values);
    out << nlohmann::json{{"effect", "effects/brdf/analytic.fx"}, {"technique", r.technique}, {"parameters", parameters}}.dump(2) << "\n";
}

nlohmann::json result_json(const fit::FitResult& r) {
    nlohmann::json parameters = nlohmann::json::object();
    for (const fit::FittedParameter& p : r.parameters) parameters[p.name] = p.values.size() == 1 ? nlohmann::json(p.values[0]) : nlohmann::json(p.values);
    nlohmann::json out{{"model", r.model}, {"title", r.title}, {"technique", r.technique}, {"parameters", parameters},
                       {"samples_used", r.samples_used}, {"samples_masked", r.samples_masked},
                       {"error_rgb", r.error_rgb}, {"weighted_rms", r.weighted_rms},
                       {"solver", r.solver}, {"stop_reason", r.stop_reason}, {"converged", r.converged},
                       {"weighted_cost", r.cost}, {"warnings", r.warnings},
                       {"residual", r.residual}, {"loss", r.loss}, {"loss_scale", r.loss_scale_used}, {"objective", r.objective}, {"reweightings", r.reweightings}};
    // The thesis' model keeps its own names and renderer form (eq. 4.23/4.24); the thesis solver its stage 1.
    if (r.model == fit::kDefaultModel)
        out.update({{"ns", r.ns}, {"cd", r.cd}, {"cs", r.cs}, {"mono_cd", r.mono_cd}, {"mono_cs", r.mono_cs}, {"error_mono", r.error_mono},
                    {"rs", r.rs}, {"rd_renderer", r.rd_renderer}, {"cs_renderer", r.cs_renderer}});
    if (r.solver == "thesis") out.update({{"accepted_steps", r.stage1.accepted}, {"optimum_cost", r.optimum_cost}});
    return out;
}

std::string parameters_text(const fit::FitResult& r) {
    std::string out;
    for (const fit::FittedParameter& p : r.parameters) out += (out.empty() ? "" : "  ") + p.name + " " + join(p.values, " ", 6);
    return out;
}

std::array<double, 3> rgb(const glm::dvec3& v) { return {v.r, v.g, v.b}; }


// Analytic models by name with KEY=VALUE parameters (colours as r,g,b or one value).
const std::string kGridModels = "ashikhmin-fit, ashikhmin-shirley, pbr, phong, cook-torrance, ggx, beckmann, blinn-phong, ward";

std::function<std::array<double, 3>(const glm::dvec3&, const glm::dvec3&)> analytic_model(const std::string& name,
                                                                                        const std::vector<std::string>& params) {
    std::map<std::string, std::vector<double>> values;
    for (const auto& p : params) {
        const auto eq = p.find('=');
        if (eq == std::string::npos) throw UsageError("--param: expected KEY=VALUE, got '" + p + "'");
        const std::string text = p.substr(eq + 1);
        const auto count = static_cast<size_t>(std::count(text.begin(), text.end(), ',') + 1);
        values[p.substr(0, eq)] = parse_doubles("--param " + p.substr(0, eq), text, count);
    }
    std::vector<std::string> used;
    // Each value must lie in the model's domain: outside it the model is not a BRDF (a negative
    // exponent, a GGX of roughness 0 is a delta) and the grid would hold NaN or infinities.
    const auto check = [](const std::string& key, double v, double low, double high, bool open_low) {
        if (v < low || v > high || (open_low && v == low)) {
            char message[160];
            std::snprintf(message, sizeof message, ": %g is outside the model's range %s%g, %g]", v, open_low ? "(" : "[", low, high);
            throw UsageError("--param " + key + message);
        }
    };
    const auto number = [&](const std::string& key, double fallback, double low, double high, bool open_low = false) {
        used.push_back(key);
        const auto found = values.find(key);
        if (found == values.end()) return fallback;
        if (found->second.size() != 1) throw UsageError("--param " + key + ": expected one value");
        check(key, found->second[0], low, high, open_low);
        return found->second[0];
    };
    const auto colour = [&](const std::string& key, glm::dvec3 fallback, double high = 1e6) {
        used.push_back(key);
        const auto found = values.find(key);
        if (found == values.end()) return fallback;
        const auto& v = found->second;
        if (v.size() != 1 && v.size() != 3) throw UsageError("--param " + key + ": expected one value or r,g,b");
        for (double x : v) check(key, x, 0.0, high, false);
        return v.size() == 1 ? glm::dvec3(v[0]) : glm::dvec3(v[0], v[1], v[2]);
    };
    const brdf::Directions frame{{0, 0, 1}, {}, {}, {1, 0, 0}};
    std::function<std::array<double, 3>(const glm::dvec3&, const glm::dvec3&)> f;
    if (name == "ashikhmin-fit") {
        brdf::AshikhminShirleyFit m{colour("cd", glm::dvec3(0.2)), colour("cs", glm::dvec3(0.2)), number("ns", 50, 0, 1e6, true)};
        f = [=](const glm::dvec3& l, const glm::dvec3& v) { return rgb(brdf::evaluate(m, {frame.n, l, v, frame.t})); };
    } else if (name == "ashikhmin-shirley") {
        brdf::AshikhminShirley m{colour("rd", glm::dvec3(0.5)), colour("rs", glm::dvec3(0.05), 1.0), number("nu", 100, 0, 1e6, true), number("nv", 100, 0, 1e6, true)};
        f = [=](const glm::dvec3& l, const glm::dvec3& v) { return rgb(brdf::evaluate(m, {frame.n, l, v, frame.t})); };
    } else if (name == "pbr") {
        brdf::MetallicRoughness m{colour("base", {1.0, 0.71, 0.29}, 1.0), number("metallic", 1, 0, 1), number("roughness", 0.4, 0, 1, true)};
        f = [=](const glm::dvec3& l, const glm::dvec3& v) { return rgb(brdf::evaluate(m, {frame.n, l, v, frame.t})); };
    } else if (name == "phong") {
        brdf::ModifiedPhong m{colour("kd", glm::dvec3(0.5)), number("ks", 0.4, 0, 1e6), number("n", 40, 0, 1e6)};
        f = [=](const glm::dvec3& l, const glm::dvec3& v) { return rgb(brdf::evaluate(m, {frame.n, l, v, frame.t})); };
    } else if (name == "cook-torrance") {
        brdf::CookTorranceBeckmann m{colour("kd", glm::dvec3(0.4)), number("ks", 1, 0, 1e6), number("m", 0.3, 0, 10, true), number("eta", 1.5, 0, 100, true), false};
        f = [=](const glm::dvec3& l, const glm::dvec3& v) { return rgb(brdf::evaluate(m, {frame.n, l, v, frame.t})); };
    } else if (name == "ggx") {
        brdf::CookTorranceGGX m{colour("kd", glm::dvec3(0.1)), colour("f0", glm::dvec3(0.04), 1.0), number("alpha", 0.2, 0, 10, true)};
        f = [=](const glm::dvec3& l, const glm::dvec3& v) { return rgb(brdf::evaluate(m, {frame.n, l, v, frame.t})); };
    } else if (name == "beckmann") {
        brdf::CookTorranceBeckmannSchlick m{colour("kd", glm::dvec3(0.1)), colour("f0", glm::dvec3(0.04), 1.0), number("m", 0.2, 0, 10, true)};
        f = [=](const glm::dvec3& l, const glm::dvec3& v) { return rgb(brdf::evaluate(m, {frame.n, l, v, frame.t})); };
    } else if (name == "blinn-phong") {
        brdf::BlinnPhong m{colour("kd", glm::dvec3(0.5)), colour("ks", glm::dvec3(0.2)), number("n", 50, 0, 1e6)};
        f = [=](const glm::dvec3& l, const glm::dvec3& v) { return rgb(brdf::evaluate(m, {frame.n, l, v, frame.t})); };
    } else if (name == "ward") {
        brdf::Ward m{colour("kd", glm::dvec3(0.5)), colour("ks", glm::dvec3(0.1)), number("alpha", 0.15, 0, 10, true)};
        f = [=](const glm::dvec3& l, const glm::dvec3& v) { return rgb(brdf::evaluate(m, {frame.n, l, v, frame.t})); };
    } else {
        throw UsageError("--model: unknown model '" + name + "' (" + kGridModels + ")");
    }
    for (const auto& [key, value] : values)
        if (std::find(used.begin(), used.end(), key) == used.end()) throw UsageError("--param: model " + name + " has no parameter '" + key + "'");
    return f;
}

}  // namespace

CommandRunner add_fit_command(CLI::App& app) {
    struct Options {
        std::string data, out, preset, preview, progress, solver = "global", residual = "linear", loss = "squared", model = fit::kDefaultModel;
        fit::FitOptions fit;
        fit::PreviewOptions preview_options;
        bool json = false;
    };
    auto o = std::make_shared<Options>();
    CLI::App* command = app.add_subcommand("fit", "Fit an analytic BRDF model to a measured BRDF (grid CSV or MERL file)");
    command->add_option("data", o->data, "BRDF grid (CSV: theta_in_deg,theta_out_deg,phi_out_deg,r,g,b) or MERL .binary")->required();
    std::string models;
    for (const auto& name : fit::model_names()) models += (models.empty() ? "" : ", ") + name;
    command->add_option("--model", o->model,
                        "The model: " + models + "; or all (each fitted and ranked by weighted cost). ashikhmin-fit is the simplified "
                        "Ashikhmin-Shirley of the original fitter")
        ->capture_default_str();
    command->add_option("--clear-coat", o->fit.clear_coat_index,
                        "The data are a base under a clear coat of this refractive index with its Fresnel reflection removed (as in "
                        "lacquer measurements): fit base / (1 - Fresnel) (0: no coat)")
        ->capture_default_str();
    command->add_option("--limit", o->fit.limit_deg, "Leave out light and camera angles beyond this (degrees)")
        ->capture_default_str()->check(finite_range(5.0, 90.0));
    command->add_option("--iterations", o->fit.iterations, "Levenberg-Marquardt iterations of stage 1")
        ->capture_default_str()->check(CLI::Range(1, 100000));
    command->add_option("--solver", o->solver,
                        "global: the optimum of the weighted least squares (bounded: ns > 0, cd >= 0, 0 <= cs <= 1); "
                        "thesis: the original fitter's two-stage Levenberg-Marquardt from --start-* (ashikhmin-fit only; may stall: reported)")
        ->capture_default_str()->check(CLI::IsMember({"global", "thesis"}));
    command->add_option("--residual", o->residual,
                        "linear, cbrt or log: compress the residual so that the highlight's peak does not outweigh the rest "
                        "(global solver)")
        ->capture_default_str()->check(CLI::IsMember({"linear", "cbrt", "log"}));
    command->add_option("--loss", o->loss, "squared (least squares), huber or cauchy: robust against outliers (global solver)")
        ->capture_default_str()->check(CLI::IsMember({"squared", "huber", "cauchy"}));
    command->add_option("--loss-scale", o->fit.loss_scale, "Robust losses: the residual where they turn (0: 1.345 x the residuals' robust sigma)")
        ->capture_default_str();
    command->add_option("--start-ns", o->fit.start_ns, "Thesis solver: starting exponent (start low: 25-50)")->capture_default_str();
    command->add_option("--start-cd", o->fit.start_cd, "Thesis solver: starting diffuse weight")->capture_default_str();
    command->add_option("--start-cs", o->fit.start_cs, "Thesis solver: starting specular weight")->capture_default_str();
    command->add_option("--out,-o", o->out, "Write the parameters as CSV (with --model all: the ranking)");
    command->add_option("--preset", o->preset, "Write a preset of effects/brdf/analytic.fx with the model's technique (--model all: the best)");
    command->add_option("--preview", o->preview, "Write measured | model | difference as an image (PNG, EXR, PFM)");
    command->add_option("--brighten", o->preview_options.brighten, "Preview: multiply values by this")->capture_default_str()->check(finite_range(1e-9, 1e9));
    command->add_option("--gamma", o->preview_options.gamma, "Preview: raise values to 1/gamma")->capture_default_str()->check(finite_range(0.1, 10.0));
    command->add_option("--progress", o->progress, "Thesis solver: write the error number e per iteration of its first stage as CSV");
    command->add_flag("--json", o->json, "Print the result as JSON");
    return [o] {
        o->fit.solver = o->solver == "thesis" ? fit::Solver::Thesis : fit::Solver::Global;
        o->fit.residual = o->residual == "cbrt" ? fit::Residual::CubeRoot : o->residual == "log" ? fit::Residual::Log : fit::Residual::Linear;
        o->fit.loss = o->loss == "huber" ? fit::Loss::Huber : o->loss == "cauchy" ? fit::Loss::Cauchy : fit::Loss::Squared;
        const bool all = o->model == "all";
        if (all && o->fit.solver == fit::Solver::Thesis)
            throw UsageError("fit: --model all fits every model with the global solver; the thesis solver fits ashikhmin-fit only");
        o->fit.model = all ? fit::kDefaultModel : o->model;
        fit::validate(o->fit);  // before reading the data: a bad start is a usage error (exit 2)
        const fit::Measurement measurement = fit::read_measurement_for_fit(o->data);
        const fit::BrdfGrid& measured = measurement.grid;
        const bool isotropic = measurement.merl.has_value();  // MERL tables fold the half vector's azimuth away
        if (!all && isotropic && fit::find_model(o->model)->anisotropic())
            throw UsageError("fit: " + o->data + " is a MERL file, isotropic by construction: " + o->model +
                             " needs data that can show anisotropy (a grid); use ashikhmin-fresnel");
        const auto start = std::chrono::steady_clock::now();
        const fit::Observations observed = fit::observations(measurement, o->fit.limit_deg);
        std::vector<fit::FitResult> results;
        if (all) results = fit::fit_all_models(observed, o->fit, isotropic);
        else results.push_back(fit::fit_brdf(observed, o->fit));
        const fit::FitResult& r = results.front();
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (!o->out.empty()) {
            if (all) write_ranking_csv(results, o->out);
            else write_result_csv(r, o->out);
        }
        if (!o->preset.empty()) write_preset(r, o->preset);
        double preview_scale = 0;
        if (!o->preview.empty()) {
            create_parent(o->preview);
            o->preview_options.limit_deg = o->fit.limit_deg;
            const fit::FitPreview preview = fit::fit_preview(measured, fit::evaluate_fit(measured, r), o->preview_options);
            image::write_image(o->preview, preview.image);
            preview_scale = preview.difference_scale;
        }
        if (!o->progress.empty()) {
            create_parent(o->progress);
            std::ofstream out(o->progress);
            out << "iteration,e\n";
            for (size_t i = 0; i < r.error_per_iteration.size(); ++i) out << i + 1 << ',' << r.error_per_iteration[i] << '\n';
            if (!out) throw Error(o->progress + ": cannot write");
        }
        if (o->json) {
            nlohmann::json out = result_json(r);
            out["data"] = o->data;
            out["limit_deg"] = o->fit.limit_deg;
            if (r.solver == "thesis") out["iterations"] = o->fit.iterations;
            out["seconds"] = seconds;
            if (o->fit.clear_coat_index > 0) out["clear_coat_index"] = o->fit.clear_coat_index;
            if (all) {
                out["ranking"] = nlohmann::json::array();
                for (const fit::FitResult& each : results) out["ranking"].push_back(result_json(each));
            }
            if (!o->preview.empty()) out["preview_difference_scale"] = preview_scale;
            std::cout << out.dump() << "\n";
        } else if (all) {
            std::printf("%s: %d directions inside %.0f deg, %zu models, %.2f s; ranked by weighted cost (%s residual, %s loss)\n",
                        o->data.c_str(), r.samples_used, o->fit.limit_deg, results.size(), seconds, r.residual.c_str(), r.loss.c_str());
            std::printf("%-4s %-18s %-13s %-13s %-11s %s\n", "rank", "model", "weighted cost", "weighted RMS", "e (4.1)", "parameters");
            for (size_t i = 0; i < results.size(); ++i)
                std::printf("%-4zu %-18s %-13.6g %-13.6g %-11.6g %s%s\n", i + 1, results[i].model.c_str(), results[i].cost, results[i].weighted_rms,
                            results[i].error_rgb, parameters_text(results[i]).c_str(), results[i].converged ? "" : "  NOT CONVERGED");
            if (isotropic) std::printf("(ashikhmin-aniso left out: a MERL file is isotropic by construction)\n");
        } else {
            std::printf("%s: %d directions inside %.0f deg, model %s (%s), solver %s (%s), %.2f s\n", o->data.c_str(), r.samples_used,
                        o->fit.limit_deg, r.model.c_str(), r.title.c_str(), r.solver.c_str(), r.stop_reason.c_str(), seconds);
            if (r.solver == "thesis")
                std::printf("stage 1 (mean of RGB): ns %.4f  cd %.6f  cs %.6f  e %.6g\n", r.ns, r.mono_cd, r.mono_cs, r.error_mono);
            std::printf("%s: %s  e %.6g\n", r.solver == "thesis" ? "stage 2 (per channel)" : "fit", parameters_text(r).c_str(), r.error_rgb);
            if (r.residual == "linear" && r.loss == "squared" && r.solver == "thesis")
                std::printf("weighted cost %.6g (the global optimum: %.6g), weighted RMS %.6g 1/sr%s\n", r.cost, r.optimum_cost,
                            r.weighted_rms, r.converged ? "" : "  NOT CONVERGED");
            else if (r.residual == "linear" && r.loss == "squared")
                std::printf("weighted cost %.6g, weighted RMS %.6g 1/sr%s\n", r.cost, r.weighted_rms, r.converged ? "" : "  NOT CONVERGED");
            else
                std::printf("weighted cost %.6g (%s residual, %s loss, scale %.3g)%s\n", r.cost, r.residual.c_str(), r.loss.c_str(),
                            r.loss_scale_used, r.converged ? "" : "  NOT CONVERGED");
            if (r.model == fit::kDefaultModel)
                std::printf("renderer form: Rs %.6f  Rd %.6f %.6f %.6f  cs' %.6f %.6f %.6f\n", r.rs, r.rd_renderer[0], r.rd_renderer[1],
                            r.rd_renderer[2], r.cs_renderer[0], r.cs_renderer[1], r.cs_renderer[2]);
        }
        if (!o->json && !o->preview.empty())
            std::printf("preview %s (%s): measured | model | difference (red: measured above the model, blue: below, full colour at "
                        "%.3g 1/sr, mean of RGB); phi_out = 0 (mirror side) in each panel's centre; rows beyond %.0f deg greyed\n",
                        o->preview.c_str(), r.model.c_str(), preview_scale, o->fit.limit_deg);
        std::vector<std::string> said;  // warnings every model shares (masked samples, the coat) once
        for (const fit::FitResult& each : results)
            for (const std::string& warning : each.warnings) {
                const bool shared = std::all_of(results.begin(), results.end(), [&](const fit::FitResult& r) {
                    return std::find(r.warnings.begin(), r.warnings.end(), warning) != r.warnings.end();
                });
                if (shared && std::find(said.begin(), said.end(), warning) != said.end()) continue;
                if (shared) said.push_back(warning);
                std::fprintf(stderr, "fxview fit: warning: %s%s\n", all && !shared ? (each.model + ": ").c_str() : "", warning.c_str());
            }
        if (!r.converged) {  // written and printed, but not an optimum: a script must not take it for one
            std::fprintf(stderr, "fxview fit: %s did not converge (%s): the parameters are not an optimum (exit 1)\n", r.model.c_str(),
                         r.stop_reason.c_str());
            return 1;
        }
        return 0;
    };
}

CommandRunner add_brdf_grid_command(CLI::App& app) {
    struct Options {
        std::string model = "ashikhmin-fit", out, merl;
        std::vector<std::string> params;
        double noise = 0;
        unsigned seed = 1;
        std::vector<int> samples{19, 37, 36};
        int digits = 17;
        bool merl_out = false;
    };
    auto o = std::make_shared<Options>();
    CLI::App* command = app.add_subcommand("brdf-grid", "Tabulate an analytic BRDF on a goniometer grid (synthetic data for fit)");
    command->add_option("--model", o->model, kGridModels)->capture_default_str();
    command->add_option("--param", o->params, "KEY=VALUE, colours as r,g,b (e.g. --param cs=0.5,0.4,0.3 --param ns=80)");
    command->add_option("--noise", o->noise, "Relative Gaussian noise on every value (e.g. 0.02)")->check(finite_range(0.0, 1.0));
    command->add_option("--seed", o->seed, "Noise seed (the same seed gives the same file)")->capture_default_str();
    command->add_option("--merl", o->merl, "Sample a MERL .binary file instead of a model");
    command->add_option("--samples", o->samples, "Samples of theta_in, theta_out (0..90) and phi_out (0..180); default: the original fitter's measurement grid")
        ->expected(3)->capture_default_str();
    command->add_option("--digits", o->digits, "Significant digits written (17 keeps doubles exact)")->capture_default_str()->check(CLI::Range(3, 17));
    command->add_option("--out,-o", o->out, "CSV file, or with --merl-out nothing")->required();
    command->add_flag("--merl-out", o->merl_out,
                      "Write the model as a full-density MERL .binary file (90 x 90 x 180 bins, each at its centre) instead of a grid");
    return [o] {
        if (o->merl_out) {
            if (!o->merl.empty()) throw UsageError("brdf-grid: --merl-out tabulates a --model, not a --merl file");
            fit::MerlBrdf merl = fit::tabulate_merl(analytic_model(o->model, o->params));
            std::mt19937 random(o->seed);
            std::normal_distribution<double> gauss(0.0, 1.0);
            if (o->noise > 0)
                for (double& v : merl.data)
                    if (v > 0) v *= 1.0 + o->noise * gauss(random);
            create_parent(o->out);
            fit::write_merl(merl, o->out);
            std::cout << "wrote " << o->out << " (MERL, 90 x 90 x 180 bins, model " << o->model << ")\n";
            return 0;
        }
        std::mt19937 random(o->seed);
        std::normal_distribution<double> gauss(0.0, 1.0);
        const fit::BrdfGrid shape = fit::uniform_grid(o->samples[0], o->samples[1], o->samples[2]);
        fit::BrdfGrid grid = o->merl.empty() ? fit::tabulate(shape, analytic_model(o->model, o->params))
                                             : fit::merl_to_grid(fit::read_merl(o->merl), shape);
        if (o->noise > 0)
            for (auto& v : grid.values)
                for (double& c : v) c *= 1.0 + o->noise * gauss(random);
        create_parent(o->out);
        fit::write_brdf_grid(grid, o->out, o->digits);
        std::cout << "wrote " << o->out << " (" << grid.size() << " directions, " << (o->merl.empty() ? "model " + o->model : o->merl) << ")\n";
        return 0;
    };
}

}  // namespace fxview::app

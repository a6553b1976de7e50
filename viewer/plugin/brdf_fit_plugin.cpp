#include "plugin/brdf_fit_plugin.hpp"

#include <algorithm>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <sstream>

#include "effect/parser.hpp"
#include "fit/brdf_fit.hpp"
#include "fit/fit_preview.hpp"
#include "fit/measurement.hpp"
#include "render/effect_resources.hpp"

namespace fxview::plugin {
namespace {

std::vector<std::string> split(const std::string& text) {
    std::vector<std::string> parts;
    std::stringstream in(text);
    for (std::string part; std::getline(in, part, ',');) {
        const size_t first = part.find_first_not_of(" \t"), last = part.find_last_not_of(" \t");
        parts.push_back(first == std::string::npos ? "" : part.substr(first, last - first + 1));
    }
    return parts;
}

class BrdfFit final : public Plugin {
public:
    BrdfFit(const effect::Effect& effect, const effect::PluginDeclaration& d, const std::vector<std::string>& texture_dirs)
        : name_(d.name), effect_path_(effect.path), access_(effect.access), limits_(effect.limits), texture_dirs_(texture_dirs) {
        const auto fail = [&](const std::string& message) { throw fxview::effect::EffectError(d.where, "plugin " + d.name + " (brdf-fit): " + message); };
        options_.model = d.text("Model").empty() ? fit::kDefaultModel : d.text("Model");
        try {
            model_ = fit::find_model(options_.model);
        } catch (const UsageError& e) {
            fail(std::string("Model: ") + e.what());
        }
        // The data: the file behind one of the effect's samplers (Data), or a file of its own (DataFile),
        // which the input `NAME.Data` overrides (the viewer's data-file field, `--set`-like).
        data_ = d.text("Data");
        if (!data_.empty()) {
            const effect::Parameter* data = effect.find_parameter(data_);
            if (!data || !fxview::effect::is_sampler_type(data->type))
                fail("Data must name a sampler of the effect holding the measured BRDF (string Data = \"Measured\")");
            const effect::TextureResource* texture = effect.find_texture(data->texture);
            if (!texture || texture->files.size() != 1) fail("the sampler " + data_ + " has no data file");
            texture_ = texture->name;
            file_ = texture->files[0];
        } else {
            file_ = d.text("DataFile");
            if (file_.empty()) fail("name the measured BRDF: string Data = \"SAMPLER\" or string DataFile = \"FILE\"");
            data_ = d.name + ".Data";
            texture_ = data_;
        }
        // Targets: one effect parameter per model parameter, in the model's order; by default the
        // model's own uniforms (those of effects/brdf/analytic.fx).
        const std::vector<fit::ModelParameter> wanted = model_->parameters();
        std::string expected;
        for (const auto& w : wanted) expected += (expected.empty() ? "" : ", ") + w.name + " (" + (w.colour ? "vec3" : "float") + ")";
        std::vector<std::string> targets = split(d.text("Targets"));
        if (d.text("Targets").empty())
            for (const auto& w : wanted) targets.push_back(w.uniform);
        if (targets.size() != wanted.size()) fail("Targets must name " + std::to_string(wanted.size()) + " parameters: " + expected);
        for (size_t i = 0; i < targets.size(); ++i)
            if (std::find(targets.begin(), targets.begin() + static_cast<std::ptrdiff_t>(i), targets[i]) != targets.begin() + static_cast<std::ptrdiff_t>(i))
                fail("Targets names " + targets[i] + " twice: each model parameter needs a parameter of its own");
        for (size_t i = 0; i < wanted.size(); ++i) {
            const char* type = wanted[i].colour ? "vec3" : "float";
            const effect::Parameter* p = effect.find_parameter(targets[i]);
            if (!p) fail("Targets: the effect has no parameter '" + targets[i] + "' (expected " + expected + ")");
            if (p->type != type || p->array_size != 0 || !p->semantic.empty())
                fail("Targets: " + targets[i] + " must be a " + type + " without semantic (it receives " + wanted[i].name + ")");
        }
        targets_ = targets;
        technique_ = d.text("Technique").empty() && effect.find_technique(model_->technique()) ? model_->technique() : d.text("Technique");
        if (!technique_.empty() && !effect.find_technique(technique_)) fail("Technique: the effect has no technique '" + technique_ + "'");
        if (const effect::Annotation* limit = d.find("Limit")) {
            if (limit->value.is_string || limit->value.numbers.size() != 1 || !(limit->value.numbers[0] >= 5 && limit->value.numbers[0] <= 90))
                fail("Limit must be an angle in degrees from 5 to 90");
            options_.limit_deg = limit->value.numbers[0];
        }
        const std::string residual = d.text("Residual"), loss = d.text("Loss");
        if (residual == "cbrt") options_.residual = fit::Residual::CubeRoot;
        else if (residual == "log") options_.residual = fit::Residual::Log;
        else if (!residual.empty() && residual != "linear") fail("Residual must be \"linear\", \"cbrt\" or \"log\"");
        if (loss == "huber") options_.loss = fit::Loss::Huber;
        else if (loss == "cauchy") options_.loss = fit::Loss::Cauchy;
        else if (!loss.empty() && loss != "squared") fail("Loss must be \"squared\", \"huber\" or \"cauchy\"");
        const std::string solver = d.text("Solver");
        if (solver == "thesis") options_.solver = fit::Solver::Thesis;
        else if (!solver.empty() && solver != "global") fail("Solver must be \"global\" or \"thesis\"");
        try {
            fit::validate(options_);
        } catch (const UsageError& e) {
            fail(e.what());
        }
    }

    std::string name() const override { return name_; }
    std::string type() const override { return "brdf-fit"; }
    std::string technique() const override { return technique_; }
    std::string description() const override {
        char text[200];
        std::snprintf(text, sizeof text, "fit %s to the measured BRDF of %s (limit %.0f deg, %s solver)", model_->title().c_str(), data_.c_str(),
                      options_.limit_deg, options_.solver == fit::Solver::Thesis ? "thesis" : "global");
        return text;
    }
    std::vector<std::string> inputs() const override { return {data_}; }
    std::vector<std::string> outputs() const override { return targets_; }

    Result run(const effect::ParameterValues& values, const Reporter& reporter, const std::string& user_file) const override {
        const std::string path = user_file.empty() ? data_path(values) : user_file;
        std::error_code error;
        if (!std::filesystem::is_regular_file(path, error)) throw Error(path + ": no such file");
        reporter.update({0.0, "reading " + path, {}, 0.0});
        const fit::Measurement measurement = fit::read_measurement_for_fit(path, limits_);
        fit::FitOptions options = options_;
        options.on_progress = [&](const fit::FitProgress& p) {
            reporter.update({p.fraction, p.stage, named(model_->values(p.cd, p.cs, p.shape.empty() ? std::vector<double>{p.ns} : p.shape)), p.cost});
        };
        if (measurement.merl && model_->anisotropic())
            throw Error(path + ": a MERL file is isotropic by construction; model " + model_->name() + " needs a grid");
        const fit::FitResult r = fit::fit_brdf(fit::observations(measurement, options.limit_deg), options);

        Result result;
        std::vector<std::vector<double>> fitted_values;
        for (const fit::FittedParameter& p : r.parameters) fitted_values.push_back(p.values);
        result.parameters = named(fitted_values);
        result.technique = technique_;
        result.converged = r.converged;
        result.warnings = r.warnings;
        for (const double e : r.error_per_iteration) result.cost_per_iteration.push_back(e * e);
        char line[256];
        std::snprintf(line, sizeof line, "%d directions inside %.0f deg of %s, %s solver: %s", r.samples_used, options.limit_deg,
                      path.c_str(), r.solver.c_str(), r.stop_reason.c_str());
        result.summary.push_back(line);
        std::string fitted = r.model + ":";
        for (const fit::FittedParameter& p : r.parameters) {
            fitted += "  " + p.name;
            for (const double v : p.values) {
                std::snprintf(line, sizeof line, " %.6g", v);
                fitted += line;
            }
        }
        result.summary.push_back(fitted);
        if (r.solver == "thesis")
            std::snprintf(line, sizeof line, "weighted cost %.6g (the global optimum: %.6g)%s", r.cost, r.optimum_cost, r.converged ? "" : "  NOT CONVERGED");
        else
            std::snprintf(line, sizeof line, "weighted cost %.6g, weighted RMS %.3g 1/sr%s", r.cost, r.weighted_rms, r.converged ? "" : "  NOT CONVERGED");
        result.summary.push_back(line);
        result.numbers = {{"weighted_cost", r.cost}, {"weighted_rms", r.weighted_rms}, {"optimum_cost", r.optimum_cost}, {"samples_used", r.samples_used},
                          {"samples_masked", static_cast<double>(r.samples_masked)}, {"error_rgb", r.error_rgb}, {"limit_deg", options.limit_deg}};
        fit::PreviewOptions preview_options;
        preview_options.limit_deg = options.limit_deg;
        const fit::FitPreview preview = fit::fit_preview(measurement.grid, fit::evaluate_fit(measurement.grid, r), preview_options);
        result.preview = preview.image;
        std::snprintf(line, sizeof line,
                      "measured | model (x3) | difference (red: measured above the model, blue: below, full colour at %.3g 1/sr); "
                      "mirror side in each panel's centre; rows outside the fit greyed",
                      preview.difference_scale);
        result.preview_caption = line;
        return result;
    }

private:
    // The model's parameter values under the effect's names (Targets).
    std::map<std::string, std::vector<double>> named(const std::vector<std::vector<double>>& values) const {
        std::map<std::string, std::vector<double>> out;
        for (size_t i = 0; i < targets_.size() && i < values.size(); ++i) out[targets_[i]] = values[i];
        return out;
    }

    // The data file as the renderer would load it: the sampler's override (--set, preset, viewer),
    // else its ResourceName resolved like any texture; under the effect's file-access policy.
    std::string data_path(const effect::ParameterValues& values) const {
        std::string path;
        if (const auto o = values.textures.find(data_); o != values.textures.end()) path = o->second;
        else if (const auto t = values.textures.find(texture_); t != values.textures.end()) path = t->second;
        else path = render::resolve_texture_path(file_, effect_path_, texture_dirs_);
        access_.require(path, "measured BRDF");
        return path;
    }

    std::string name_, effect_path_, data_, texture_, file_, technique_;
    std::vector<std::string> targets_;
    std::shared_ptr<const fit::FitModel> model_;
    FileAccessPolicy access_;
    ResourceLimits limits_;
    std::vector<std::string> texture_dirs_;
    fit::FitOptions options_;
};

}  // namespace

std::unique_ptr<Plugin> create_brdf_fit(const effect::Effect& effect, const effect::PluginDeclaration& declaration,
                                        const std::vector<std::string>& texture_dirs) {
    return std::make_unique<BrdfFit>(effect, declaration, texture_dirs);
}

}  // namespace fxview::plugin

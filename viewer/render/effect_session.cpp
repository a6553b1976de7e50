#include "render/effect_session.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "core/error.hpp"
#include "core/text.hpp"
#include "lighting/environment_sources.hpp"
#include "spectral/packing.hpp"

namespace fxview::render {

namespace fs = std::filesystem;

EffectSession::EffectSession(std::string path, effect::LoadOptions options, std::vector<std::string> texture_dirs)
    : path_(std::move(path)), options_(std::move(options)), texture_dirs_(std::move(texture_dirs)) {
    auto parsed = std::make_unique<effect::Effect>(effect::load_effect(path_, options_));
    values_ = effect::default_values(*parsed);
    loaded_ = prepare(std::move(parsed), values_);
    technique_ = opening_technique();
    watch();
}

std::string EffectSession::opening_technique() const {
    const std::string preferred = loaded_->effect->default_technique().name;
    if (loaded_->techniques.count(preferred)) return preferred;
    for (const auto& t : loaded_->effect->techniques)
        if (loaded_->techniques.count(t.name)) return t.name;
    return preferred;
}

std::vector<std::string> EffectSession::warnings() const {
    std::vector<std::string> all = loaded_->effect->warnings;
    for (const auto& w : loaded_->resources->warnings()) all.push_back(w);
    if (!loaded_->failed_techniques.empty()) {
        std::string text = loaded_->failed_techniques;
        while (!text.empty() && text.back() == '\n') text.pop_back();
        all.push_back(text);
    }
    return all;
}

std::unique_ptr<EffectSession::Loaded> EffectSession::prepare(std::unique_ptr<effect::Effect> parsed,
                                                             const effect::ParameterValues& values) const {
    auto loaded = std::make_unique<Loaded>();
    loaded->effect = std::move(parsed);
    // Every technique is compiled and every failure reported together (each message keeps its own
    // file:line), as `fxview check` does: the viewer lists them all, not the first technique's.
    std::string failures;
    std::optional<effect::SourceLocation> first;
    for (const auto& technique : loaded->effect->techniques) {
        try {
            loaded->techniques.emplace(technique.name, effect::compile_technique(*loaded->effect, technique));
        } catch (const effect::EffectError& error) {
            failures += (failures.empty() ? "" : "\n") + std::string(error.what());
            if (!first) first = error.location;
        }
    }
    // A legacy effect opens with the techniques that translate; the others are reported.
    if (first && loaded->effect->legacy && !loaded->techniques.empty()) {
        loaded->failed_techniques = effect::fold_repeated_messages(failures);
        first.reset();
    }
    if (first) throw effect::EffectError(*first, effect::fold_repeated_messages(failures), effect::EffectError::Lines{});
    for (const auto& [name, compiled] : loaded->techniques) {
        TechniqueTraits& t = loaded->traits[name];
        for (const auto& pass : compiled.passes) {
            t.renders_to_textures = t.renders_to_textures || !pass.pass->states.render_targets.empty();
            for (const auto& uniform : pass.uniforms) {
                t.reads.insert(uniform.parameter->name);
                const std::string semantic = to_lower(uniform.parameter->semantic);
                t.animated = t.animated || semantic == "time" || semantic == "frame";
                t.sized_light = t.sized_light || semantic == "lightradius";
                t.shaped_light = t.shaped_light || semantic == "lightshape";
                if (!effect::is_sampler_type(uniform.parameter->type)) continue;
                const std::string& texture_name = uniform.parameter->texture.empty() ? uniform.parameter->name : uniform.parameter->texture;
                const effect::TextureResource* texture = loaded->effect->find_texture(texture_name);
                if (texture && texture->files.size() == 1 && EnvironmentMaps::is_resource_name(texture->files[0])) {
                    t.reads_environment = true;
                    t.reads_rgb_environment = t.reads_rgb_environment || !EnvironmentMaps::is_spectral_resource_name(texture->files[0]);
                }
            }
        }
    }
    loaded->resources = std::make_unique<EffectResources>(*loaded->effect, values, texture_dirs_);
    return loaded;
}

std::optional<std::string> EffectSession::reload() {
    // Values carry over where the parameter still exists with the same type and size.
    std::unique_ptr<Loaded> fresh;
    effect::ParameterValues carried;
    try {
        auto candidate = std::make_unique<effect::Effect>(effect::load_effect(path_, options_));
        carried = effect::default_values(*candidate);
        for (const auto& [name, numbers] : values_.numbers) {
            const effect::Parameter* before = loaded_->effect->find_parameter(name);
            const effect::Parameter* after = candidate->find_parameter(name);
            if (before && after && before->type == after->type && before->array_size == after->array_size &&
                after->semantic.empty())
                carried.numbers[name] = numbers;
        }
        for (const auto& [name, file] : values_.textures)
            if (const auto* after = candidate->find_parameter(name); after && effect::is_sampler_type(after->type))
                carried.textures[name] = file;
        fresh = prepare(std::move(candidate), carried);
    } catch (const std::exception& error) {
        watch();  // do not retry the same broken files every frame
        return std::string(error.what());
    }
    loaded_ = std::move(fresh);
    values_ = std::move(carried);
    renderer_.reset();
    if (!loaded_->techniques.count(technique_)) technique_ = opening_technique();
    watch();
    return std::nullopt;
}

void EffectSession::select_technique(const std::string& name) {
    if (!loaded_->techniques.count(name) && loaded_->effect->find_technique(name))
        throw UsageError(path_ + ": technique '" + excerpt(name) + "' did not translate or compile (its messages are above)");
    if (!loaded_->techniques.count(name)) {
        std::string names;
        for (const auto& t : loaded_->effect->techniques) names += (names.empty() ? "" : ", ") + t.name;
        throw UsageError(path_ + " has no technique '" + excerpt(name) + "' (it has " + excerpt(names, 2000) + ")");
    }
    technique_ = name;
}

const EffectSession::TechniqueTraits& EffectSession::traits(const std::string& technique) const {
    static const TechniqueTraits none;
    const auto found = loaded_->traits.find(technique);
    return found == loaded_->traits.end() ? none : found->second;
}

void EffectSession::reload_textures() {
    loaded_->resources = std::make_unique<EffectResources>(*loaded_->effect, values_, texture_dirs_);
    renderer_.reset();
    watch();
}

const EnvironmentMaps& EffectSession::environment(const scene::Environment& environment) {
    if (!environment_ || environment_->source() != environment.source) {
        loaded_->resources->set_environment(nullptr);
        environment_.reset();  // a failed source leaves none rather than a stale one
        environment_ = std::make_unique<EnvironmentMaps>(environment.source, loaded_->effect->limits);
    }
    return *environment_;
}

namespace {
// Above this warned: the films under the ColorChecker room (projection error 0.14) reach CIEDE2000 11
// at saturated patches; textures/sky_cross.png (0.014) stays within 0.04 (docs/spectral.md).
constexpr double kUpliftWarningError = 0.05;
}  // namespace

std::string EffectSession::unused_environment_warning(const scene::Environment& environment) const {
    if (environment.source.empty()) return "";
    // Said per technique: in one effect some techniques may read the environment and others not.
    const TechniqueTraits& t = traits(technique_);
    if (!t.reads_environment)
        return path_ + ": warning: technique '" + technique_ + "' is lit by the point light only; the environment '" + environment.source +
               "' fills the background but does not light it";
    // Known once the environment is loaded (after the first frame).
    if (!t.reads_rgb_environment && environment_ && environment_->source() == environment.source && environment_->has_spectral_form()) {
        const double error = environment_->unfiltered().spectral->projection_error;
        if (error > kUpliftWarningError)
            return path_ + ": warning: the environment '" + environment.source + "' has more varied colours than its three spectra hold (" +
                   std::to_string(static_cast<int>(std::lround(100.0 * error))) +
                   " % RMS from each colour's own uplifted spectrum): where a film or grating filters its saturated colours, colours may be "
                   "several CIEDE2000 units off (body colours and wide lobes far less; technique '" +
                   technique_ + "', docs/spectral.md, \"Under an image\")";
    }
    return "";
}

std::string EffectSession::unused_light_radius_warning(const scene::Light& light) const {
    if (!light.has_size()) return "";
    const TechniqueTraits& t = traits(technique_);
    const std::string shape = scene::light_shape_name(light.shape);
    const std::string readers = " (cd.fx's Orders, wavelength.fx, thinfilm.fx's films, analytic.fx, measured.fx and .brdf files' Lit show a light's size and shape)";
    if (light.shape == scene::LightShape::Sphere && !t.sized_light)
        return path_ + ": warning: technique '" + technique_ + "' treats the light as a point; its radius " + std::to_string(light.radius) +
               " changes nothing here" + readers;
    if (light.shape != scene::LightShape::Sphere && !t.shaped_light)
        return path_ + ": warning: technique '" + technique_ + "' treats the " + shape + " light as " +
               (t.sized_light ? "a sphere of radius " + std::to_string(scene::light_geometry(light).equivalent_radius()) + " (of equal area)"
                              : std::string("a point at its centre")) +
               readers;
    return "";
}

std::vector<std::string> EffectSession::scene_warnings(const scene::Scene& scene) const {
    std::vector<std::string> warnings;
    for (std::string warning :
         {unused_environment_warning(scene.environment), unused_light_radius_warning(scene.light), unused_light_spectrum_warning(scene.light),
          unused_light_intensity_warning(scene.light)})
        if (!warning.empty()) warnings.push_back(std::move(warning));
    return warnings;
}

std::string EffectSession::scene_light_role(const effect::Parameter& parameter) {
    for (const effect::Annotation& a : parameter.annotations)
        if (a.name == "SceneLight" && a.value.is_string) return a.value.text;
    return "";
}

bool EffectSession::follows_scene_light(const effect::Parameter& parameter) { return scene_light_role(parameter) == "spectrum"; }

namespace {

// The luminance Y of library spectrum `index` as the spectral effects integrate it by default (CIE
// 1931, 360-830 nm at 1 nm, over Σ ȳ): 1 for a constant 1. 1 where the effect has no spectra.
double library_luminance(const EffectResources& resources, int index) {
    const spectral::PackedTexture* library = resources.generated_resource("spectral:library");
    const spectral::PackedTexture* cmf = resources.generated_resource("spectral:cmf");
    if (!library || !cmf || index < 0 || index >= library->count) return 1.0;
    double weighted = 0, ybar = 0;
    for (int nm = 360; nm <= 830; ++nm) {
        const double y = spectral::cmf_value(*cmf, 0, nm)[1];
        weighted += spectral::packed_value(*library, index, nm) * y;
        ybar += y;
    }
    return weighted > 0 ? weighted / ybar : 1.0;
}

}  // namespace

effect::ParameterValues EffectSession::values_for(const scene::Scene& scene) const {
    if (scene.light.spectrum.empty() && !scene.light.intensity) return values_;
    effect::ParameterValues values = values_;
    const effect::Parameter* spectrum_follower = nullptr;
    for (const effect::Parameter& p : loaded_->effect->parameters) {
        if (!follows_scene_light(p)) continue;
        spectrum_follower = &p;
        if (scene.light.spectrum.empty()) continue;
        if (std::find(p.ui.items.begin(), p.ui.items.end(), scene.light.spectrum) == p.ui.items.end()) {
            std::string names;
            for (const std::string& item : p.ui.items) names += (names.empty() ? "" : ", ") + item;
            throw UsageError("light spectrum '" + scene.light.spectrum + "' is not in the spectral library (" + names + ")");
        }
        effect::set_value_from_text(*loaded_->effect, values, p.name + "=" + scene.light.spectrum);
    }
    if (!scene.light.intensity) return values;
    double lux = 0;
    try {
        lux = scene::illuminance_at_origin(scene.light, *scene.light.intensity);
    } catch (const UsageError&) {
        // A unit the light cannot have (a point in nit): the CLI refuses it before, the viewer's Scene
        // tab says so under the field; the picture keeps the effect's own strength meanwhile.
        return values;
    }
    for (const effect::Parameter& p : loaded_->effect->parameters) {
        const std::string role = scene_light_role(p);
        if (role == "irradiance") {
            values.numbers[p.name] = {static_cast<float>(lux)};
        } else if (role == "spectral-brightness") {
            // The light spectrum's luminance divided out: Brightness × Y(S) = E / π.
            const auto spectrum = spectrum_follower ? values.numbers.find(spectrum_follower->name) : values.numbers.end();
            const int index = spectrum != values.numbers.end() && !spectrum->second.empty() ? static_cast<int>(spectrum->second[0]) : -1;
            values.numbers[p.name] = {static_cast<float>(lux / (std::numbers::pi * library_luminance(*loaded_->resources, index)))};
        } else if (role == "output-range") {
            // Photometric light is scene-referred: "clip" (to [0, 1]) becomes "unbounded", the other mappings stay.
            auto& mode = values.numbers[p.name];
            if (mode.empty() || mode[0] == 0.0f) mode = {3.0f};
        }
    }
    return values;
}

std::string EffectSession::unused_light_spectrum_warning(const scene::Light& light) const {
    if (light.spectrum.empty()) return "";
    for (const effect::Parameter& p : loaded_->effect->parameters)
        if (follows_scene_light(p)) return "";
    return path_ + ": warning: no parameter of this effect takes the light's spectrum (SceneLight = \"spectrum\"); the light spectrum '" +
           light.spectrum + "' changes nothing here";
}

std::string EffectSession::unused_light_intensity_warning(const scene::Light& light) const {
    if (!light.intensity) return "";
    for (const effect::Parameter& p : loaded_->effect->parameters) {
        const std::string role = scene_light_role(p);
        if (role == "irradiance" || role == "spectral-brightness") return "";
    }
    return path_ + ": warning: no parameter of this effect takes the light's intensity (SceneLight = \"irradiance\" or \"spectral-brightness\"); " +
           scene::to_string(*light.intensity) + " changes nothing here";
}

void EffectSession::render(const scene::Scene& scene, const gl::RenderTarget& target, FrameTiming timing, bool clear_target) {
    if (loaded_->resources->uses_environment()) loaded_->resources->set_environment(&environment(scene.environment));
    const effect::CompiledTechnique& technique = loaded_->techniques.at(technique_);
    if (scene.light.spectrum.empty() && !scene.light.intensity)  // the user's values as they are: no copy per frame
        renderer_.render(scene, technique, values_, *loaded_->resources, target, timing, clear_target);
    else
        renderer_.render(scene, technique, values_for(scene), *loaded_->resources, target, timing, clear_target);
}

void EffectSession::watch() {
    watched_.clear();
    std::vector<std::string> files = loaded_->effect->sources.files();
    files.push_back(path_);
    for (const auto& [name, texture] : loaded_->resources->textures()) {
        size_t start = 0;
        for (size_t i = 0; i <= texture.source.size(); ++i)
            if (i == texture.source.size() || texture.source[i] == ';') {
                files.push_back(texture.source.substr(start, i - start));
                start = i + 1;
            }
    }
    for (const auto& file : files) {
        std::error_code error;
        const auto time = fs::last_write_time(file, error);
        if (!error) watched_[file] = time;
    }
}

bool EffectSession::files_changed() const {
    for (const auto& [file, time] : watched_) {
        std::error_code error;
        const auto now = fs::last_write_time(file, error);
        if (error || now != time) return true;
    }
    return false;
}

}  // namespace fxview::render

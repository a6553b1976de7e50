// One effect as a user works with it: loaded, every technique compiled, textures uploaded, the
// user's parameter values kept. Hot reload watches the effect, its includes and its textures; a
// reload that fails keeps the last good effect running and reports why; a reload that succeeds
// keeps every value whose parameter still exists with the same type.
#pragma once
#include <filesystem>
#include <map>
#include <set>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "effect/effect_program.hpp"
#include "effect/parser.hpp"
#include "render/effect_renderer.hpp"
#include "render/environment_maps.hpp"
#include "render/effect_resources.hpp"

namespace fxview::render {

class EffectSession {
public:
    // Throws EffectError (or Error) when the first load fails: there is no last good effect yet.
    EffectSession(std::string path, effect::LoadOptions options, std::vector<std::string> texture_dirs);

    // Loads the file again. Returns the error text on failure (the previous effect stays).
    std::optional<std::string> reload();
    bool files_changed() const;
    // New include path, file-access policy or budgets for the next reload (e.g. a folder allowed).
    void set_load_options(effect::LoadOptions options) { options_ = std::move(options); }
    std::optional<std::string> reload_if_changed() { return files_changed() ? reload() : std::nullopt; }

    const effect::Effect& effect() const { return *loaded_->effect; }
    effect::ParameterValues& values() { return values_; }
    const effect::ParameterValues& values() const { return values_; }
    const std::string& technique() const { return technique_; }
    void select_technique(const std::string& name);  // UsageError naming the techniques if unknown
    // Applies changed texture overrides (--set Sampler=file, presets): reloads the textures.
    void reload_textures();

    void render(const scene::Scene& scene, const gl::RenderTarget& target, FrameTiming timing = {}, bool clear_target = true);
    const EffectResources& resources() const { return *loaded_->resources; }
    // What loading could not honour without failing (legacy effects: ignored states, placeholder
    // textures, techniques that did not translate), each "file:line: ..." (one or more lines).
    std::vector<std::string> warnings() const;
    // The scene environment's maps, made (lighting/, about a second) when the source changes; the
    // frame's effect samples them (render() calls this). Throws Error naming a bad source.
    const EnvironmentMaps& environment(const scene::Environment& environment);
    // Empty when the selected technique's shaders read the environment (or none is set); otherwise a
    // warning that it only fills the background: said, never silently ignored. Techniques that read only
    // its spectral form (thin films, the CD's orders, wavelength.fx) are warned where an image's colours
    // are more varied than its three spectra hold (known once the environment is loaded).
    std::string unused_environment_warning(const scene::Environment& environment) const;
    // The same for a sized light the selected technique treats as a point (LIGHTRADIUS unread) or, a flat
    // one, as a sphere or a point (LIGHTSHAPE unread).
    std::string unused_light_radius_warning(const scene::Light& light) const;
    // A scene light spectrum (scene::Light::spectrum) that no parameter of the effect follows; likewise
    // a scene light intensity (scene::Light::intensity).
    std::string unused_light_spectrum_warning(const scene::Light& light) const;
    std::string unused_light_intensity_warning(const scene::Light& light) const;
    std::vector<std::string> scene_warnings(const scene::Scene& scene) const;  // those of the above that apply
    // The values a frame of `scene` uses: the user's, with every parameter annotated SceneLight =
    // "spectrum" set to the scene light's spectrum where it has one, and those annotated "irradiance"
    // or "spectral-brightness" to its intensity where it has one (scene/light_intensity.hpp; the user's
    // own values are kept for when it has none). UsageError naming the library's spectra for an
    // unknown name, or for an intensity unit the light's shape cannot have.
    effect::ParameterValues values_for(const scene::Scene& scene) const;
    // Whether a parameter follows the scene light's spectrum (SceneLight = "spectrum").
    static bool follows_scene_light(const effect::Parameter& parameter);
    // Its SceneLight annotation: "spectrum", "irradiance", "spectral-brightness", or "" for none.
    static std::string scene_light_role(const effect::Parameter& parameter);
    // What a technique's compiled passes say about it, found once when it is compiled (the viewer
    // asks every frame). Unknown techniques: nothing read, not animated, no textures of their own.
    struct TechniqueTraits {
        std::set<std::string> reads;       // the parameters its programs read (active uniforms the compiler kept)
        bool animated = false;             // a TIME or FRAME semantic is read: the picture changes with time alone
        bool renders_to_textures = false;  // later passes may read neighbouring pixels: no strip-by-strip drawing
        bool sized_light = false;          // the LIGHTRADIUS semantic is read: the light's size shows
        bool shaped_light = false;         // LIGHTSHAPE is read: a flat light shows as a disc or rectangle
        bool reads_environment = false;      // it samples an "environment:..." texture
        bool reads_rgb_environment = false;  // ... one that is not the spectral form's
    };
    const TechniqueTraits& traits(const std::string& technique) const;
    const std::set<std::string>& parameters_read(const std::string& technique) const { return traits(technique).reads; }
    bool animated(const std::string& technique) const { return traits(technique).animated; }
    bool renders_to_textures(const std::string& technique) const { return traits(technique).renders_to_textures; }

private:
    struct Loaded {
        std::unique_ptr<effect::Effect> effect;  // stable address: compiled passes point into it
        std::map<std::string, effect::CompiledTechnique> techniques;
        std::map<std::string, TechniqueTraits> traits;
        std::unique_ptr<EffectResources> resources;
        std::string failed_techniques;  // legacy effects: techniques that did not translate or compile
    };
    std::string opening_technique() const;  // the default technique, else the first that compiled
    // Compiles every technique and loads the textures of a parsed effect.
    std::unique_ptr<Loaded> prepare(std::unique_ptr<effect::Effect> parsed, const effect::ParameterValues& values) const;
    void watch();

    std::string path_;
    effect::LoadOptions options_;
    std::vector<std::string> texture_dirs_;
    std::unique_ptr<Loaded> loaded_;
    effect::ParameterValues values_;
    std::string technique_;
    EffectRenderer renderer_;
    std::unique_ptr<EnvironmentMaps> environment_;
    std::map<std::string, std::filesystem::file_time_type> watched_;
};

}  // namespace fxview::render

// Options naming an effect: the file, its technique and --set NAME=VALUE overrides; and the
// include search path (effects/lib of the source tree, or $FXVIEW_EFFECTS_DIR/lib).
#pragma once
#include <CLI/CLI.hpp>

#include <memory>
#include <string>
#include <vector>

#include "effect/parser.hpp"
#include "render/effect_session.hpp"

namespace fxview::app {

// What effects may read and how much: --allow-path DIR (repeatable) and --limit NAME=VALUE.
struct AccessOptions {
    std::vector<std::string> allow_paths;
    std::vector<std::string> limits;
    std::string matrix_convention;  // Cg/HLSL effects: "row", "column" or empty (docs/legacy-effects.md)
};
void add_access_options(CLI::App& command, AccessOptions& options);
// The budgets with every --limit applied; UsageError for an unknown name or a bad value.
ResourceLimits resource_limits(const AccessOptions& options);

struct EffectOptions {
    std::string path;  // empty: the built-in debug shader
    std::string technique;
    std::vector<std::string> sets;
    std::string preset;       // JSON preset applied before --set
    std::string save_preset;  // writes the values used
    std::vector<std::string> textures;  // --texture NAME=FILE: a texture object or a sampler
    AccessOptions access;
};

void add_effect_options(CLI::App& command, EffectOptions& options);
// The include path, the file-access policy (the search roots effects/lib, textures/ and spectra/
// plus every --allow-path folder; the effect's own folder is added when it loads) and the budgets.
effect::LoadOptions effect_load_options(const AccessOptions& access);
// The same, plus read access to the files that --set names for samplers (the user's own choice).
effect::LoadOptions effect_load_options(const EffectOptions& options);
// Where texture files are searched after the effect's own folder: textures/ of the source tree
// (or $FXVIEW_TEXTURES_DIR).
std::vector<std::string> texture_folders();
// spectra/ of the source tree (or $FXVIEW_SPECTRA_DIR).
std::string spectra_folder();

// Opens the effect of `options` as a session: technique, then preset, then --set values (texture
// overrides reload the textures). Throws EffectError/UsageError like the steps it takes.
std::unique_ptr<render::EffectSession> open_effect_session(const EffectOptions& options);

}  // namespace fxview::app

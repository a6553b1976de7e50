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

struct EffectOptions {
    std::string path;  // empty: the built-in debug shader
    std::string technique;
    std::vector<std::string> sets;
    std::string preset;       // JSON preset applied before --set
    std::string save_preset;  // writes the values used
};

void add_effect_options(CLI::App& command, EffectOptions& options);
effect::LoadOptions effect_load_options();
// Where texture files are searched after the effect's own folder: textures/ of the source tree
// (or $FXVIEW_TEXTURES_DIR).
std::vector<std::string> texture_folders();

// Opens the effect of `options` as a session: technique, then preset, then --set values (texture
// overrides reload the textures). Throws EffectError/UsageError like the steps it takes.
std::unique_ptr<render::EffectSession> open_effect_session(const EffectOptions& options);

}  // namespace fxview::app

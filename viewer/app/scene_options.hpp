// The scene and output options that `render` and `pick` share, registered on a CLI11 subcommand
// and turned into a scene::Scene plus render settings after parsing.
#pragma once
#include <CLI/CLI.hpp>

#include <optional>
#include <string>

#include "app/effect_options.hpp"
#include "context/context.hpp"
#include "image/display_transform.hpp"
#include "render/debug_renderer.hpp"
#include "scene/scene.hpp"

namespace fxview::app {

struct SceneOptions {
    std::string mesh = "sphere";
    std::string size = "256x256";
    std::string backend = "egl";
    int samples = 0;
    std::string debug_view = "normals";
    float camera_distance = 3.0f;
    std::string camera_rotate = "0,0,0";
    std::string camera_pan = "0,0";
    float fov = 45.0f;
    std::string light_position = "2,2,3";
    std::string light_rotate = "0,0,0";
    std::string object_position = "0,0,0";
    std::string object_rotate = "0,0,0";
    std::string object_scale = "1,1,1";
    std::string background = "0,0,0,0";
    // Unset: the preset's "scene" settings (effect/preset.hpp), else none / 0 / 1 / none.
    std::optional<std::string> environment, tone_map, light_spectrum, light_shape, light_size, light_intensity;
    std::optional<float> environment_rotate, environment_intensity, exposure, light_radius, light_angle;
    std::optional<int> samples_given;
    bool gl_debug = false;
    EffectOptions effect;
};

void add_scene_options(CLI::App& command, SceneOptions& options);

struct RenderRequest {
    scene::Scene scene;
    render::DebugView view = render::DebugView::Normals;
    context::Backend backend = context::Backend::Egl;
    int width = 256, height = 256;
    int samples = 0;
    bool gl_debug = false;
    EffectOptions effect;  // path empty: the built-in debug view
    image::DisplaySettings display;  // for PNG output (EXR and PFM stay scene-linear)
};

RenderRequest to_render_request(const SceneOptions& options);  // throws UsageError on bad values

}  // namespace fxview::app

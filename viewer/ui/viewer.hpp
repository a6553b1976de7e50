// The interactive viewer (`fxview view`): a GLFW window with Dear ImGui panels around a render
// view. Objects, camera and light are placed independently and turned with an arcball; each object
// has its own technique and view mode (the effect, plain rendering, or a debug view); parameters
// are edited in place; the effect hot-reloads and a failing reload keeps the last good one.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/effect_options.hpp"
#include "render/debug_renderer.hpp"
#include "render/effect_session.hpp"
#include "image/display_transform.hpp"
#include "scene/scene.hpp"
#include "ui/script.hpp"

namespace fxview::ui {

struct ViewerOptions {
    std::string effect_path;  // may be empty: debug views only
    std::string technique;
    std::vector<std::string> sets;
    std::string preset;
    app::AccessOptions access;  // --allow-path folders and --limit budgets for every effect opened
    scene::Scene scene;
    int window_width = 1280, window_height = 800;
    int render_width = 0, render_height = 0;  // 0: follow the render view's size
    int frames = 0;                           // > 0: exit after this many frames (after the script)
    std::string screenshot;                   // whole window at exit
    std::string render_screenshot;            // render view at exit
    std::vector<ScriptAction> script;
    bool gl_debug = false;
    int samples = 4;         // MSAA of the render view: 0, 2, 4 or 8
    image::DisplaySettings display;  // exposure and tone mapper of the view and its PNG pictures
    std::string debug_view;  // normals, uv, camera or light: every object starts in that debug view
    float ui_scale = 0;      // 0: the monitor's content scale
    bool stats = false;      // print UI frame and render times at exit
};

// Runs until the window closes (or the frame count is reached); returns the exit code.
int run_viewer(const ViewerOptions& options);

}  // namespace fxview::ui

#include "ui/command_view.hpp"

#include "app/scene_options.hpp"
#include "app/value_parsing.hpp"
#include "ui/viewer.hpp"

namespace fxview::ui {

app::CommandRunner add_view_command(CLI::App& app) {
    struct Options {
        app::SceneOptions scene;
        std::string window = "1280x800";
        std::string render_size;
        int frames = 0;
        float ui_scale = 0;
        bool stats = false;
        std::string screenshot, render_screenshot, script;
    };
    auto o = std::make_shared<Options>();
    CLI::App* command = app.add_subcommand("view", "Open the interactive viewer (GLFW window with Dear ImGui)");
    app::add_scene_options(*command, o->scene);
    command->add_option("--window", o->window, "Window size WxH")->capture_default_str();
    command->add_option("--render-size", o->render_size, "Fixed render-view resolution WxH (default: the view's size)");
    command->add_option("--frames", o->frames, "Render this many frames, then exit (after --script)")->check(CLI::Range(0, 1000000));
    command->add_option("--screenshot", o->screenshot, "With --frames: save the whole window (UI included) at exit");
    command->add_option("--render-screenshot", o->render_screenshot, "With --frames: save the render view at exit");
    command->add_option("--script", o->script, "Play UI actions from a file (docs/viewer.md)");
    command->add_option("--ui-scale", o->ui_scale, "Size of the UI (fonts, widgets); default: the monitor's content scale")
        ->check(app::finite_range(0.5, 4.0));
    command->add_flag("--stats", o->stats, "At exit, print the UI's frame times and the render times they carried (for benchmarks)");
    return [o, command] {
        // Every render option the viewer shares with `render` takes effect (issue #13); --backend
        // cannot: the viewer is a window.
        const auto given = [command](const char* name) { return command->get_option(name)->count() > 0; };
        if (given("--backend")) throw UsageError("view: --backend does not apply: the viewer always opens a GLFW window");
        o->scene.backend = "glfw";
        o->scene.samples = 4;  // the viewer's default MSAA (a preset's or --samples wins)
        const app::RenderRequest request = app::to_render_request(o->scene);
        ViewerOptions options;
        options.effect_path = request.effect.path;
        options.technique = request.effect.technique;
        options.sets = request.effect.sets;
        options.preset = request.effect.preset;
        options.access = request.effect.access;
        options.scene = request.scene;
        const glm::ivec2 window = app::parse_size("--window", o->window);
        options.window_width = window.x;
        options.window_height = window.y;
        if (!o->render_size.empty()) {
            const glm::ivec2 render = app::parse_size("--render-size", o->render_size);
            options.render_width = render.x;
            options.render_height = render.y;
        }
        if (given("--size") && o->render_size.empty()) {  // --size is the render view's size, as in render
            options.render_width = request.width;
            options.render_height = request.height;
        }
        if (request.samples != 0 && request.samples != 2 && request.samples != 4 && request.samples != 8)
            throw UsageError("view: --samples must be 0, 2, 4 or 8 (the viewer's MSAA choices)");
        options.samples = request.samples;
        options.display = request.display;
        if (given("--debug-view")) options.debug_view = o->scene.debug_view;
        options.frames = o->frames;
        options.ui_scale = o->ui_scale;
        options.stats = o->stats;
        options.screenshot = o->screenshot;
        options.render_screenshot = o->render_screenshot;
        if ((!o->screenshot.empty() || !o->render_screenshot.empty()) && o->frames == 0)
            throw UsageError("--screenshot and --render-screenshot need --frames N");
        if (!o->script.empty()) options.script = load_script(o->script);
        options.gl_debug = request.gl_debug;
        return run_viewer(options);
    };
}

}  // namespace fxview::ui

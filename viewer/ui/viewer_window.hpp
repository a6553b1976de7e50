// The viewer window's state and loop, shared by the files that implement it: viewer.cpp (loop,
// rendering, screenshots), viewer_panels.cpp (keys and panels) and script_verbs.cpp (the script
// verbs, a table of small handlers). Private to the viewer: run_viewer (viewer.hpp) is its API.
#pragma once
#include <imgui.h>

#include <chrono>
#include <csignal>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "context/context.hpp"
#include "gl/render_target.hpp"
#include "render/skybox.hpp"
#include "ui/brdf_panel.hpp"
#include "ui/display_pass.hpp"
#include "ui/effect_state.hpp"
#include "ui/environment_panel.hpp"
#include "ui/file_browser.hpp"
#include "ui/imgui_layer.hpp"
#include "ui/panel_width.hpp"
#include "ui/pick_panel.hpp"
#include "ui/plugin_panel.hpp"
#include "ui/render_schedule.hpp"
#include "ui/scene_panel.hpp"
#include "ui/screenshot.hpp"
#include "ui/texture_panel.hpp"
#include "ui/viewer.hpp"

struct GLFWwindow;

namespace fxview::ui {

// The panel's tabs, in order (`tab NAME` takes these names).
inline constexpr const char* kTabNames[] = {"Effect", "Scene", "Textures", "Pick", "View", "Plugins", "BRDF"};

class Viewer {
public:
    explicit Viewer(const ViewerOptions& options);
    int run();
    // Idle when idle: with the picture complete and nothing running, the loop sleeps until input
    // (or half a second, for the file watcher) instead of drawing frames nobody needs. After an
    // event a few frames follow, so that ImGui's hover and release states settle. Returns the
    // seconds it slept.
    double wait_or_poll_events();
    // `view --stats`: the UI's frame times and the rendering they carried (docs/benchmarks.md).
    void print_stats() const;

private:
    // A newly opened effect: every object shows it, with its technique.
    void on_effect_opened();
    // Objects show the technique a plugin switched to (its own while it runs and after; the
    // previous one after a failure or Cancel).
    void follow_plugin_technique();
    render::EffectSession* session() { return effect_.session(); }
    const render::EffectSession* session() const { return effect_.session(); }

    // rendering and screenshots (viewer.cpp)
    void render_scene(const gl::RenderTarget& target);
    const render::GpuTexture* skybox_texture() const;
    // A hash of everything the picture depends on: scene, objects and their views, effect (a reload
    // makes a new one), parameter values, display settings and size.
    std::uint64_t render_key(int width, int height) const;
    // Where the objects are, per row, for the render schedule's cost model: a cheap render at a
    // quarter of the size, redone when the geometry changes and only for pictures that are slow.
    void update_coverage(int width, int height);
    bool picture_animated() const;
    // Coarse to fine: a picture that took long starts as a low-resolution one, drawn whole (within
    // about 50 ms, by the last complete picture's measured time) and scaled up into the view; the
    // pieces then refine it row by row. A drag, which starts a new picture at every move, so shows
    // a coarse but whole picture at once instead of a torn one. True when it drew one this frame.
    bool render_coarse_preview(std::uint64_t key, int width, int height);
    int preview_scale_for(int width, int height) const;
    double draw_preview(int width, int height);  // into preview_ at preview_scale_; returns its seconds
    bool picture_progressive() const;
    void frame();
    // The render view's picture as rendered (linear values, alpha kept).
    void write_render(const std::string& path);
    // F12 and the button: by default exactly what the view shows (its size, aspect and display
    // transform), written once its picture is complete; at a size of its own only when asked for,
    // rendered in pieces across frames (screenshot.hpp). Neither blocks the UI.
    void save_screenshot();
    void write_view_shot(const std::string& path);
    // Screenshots waiting for the view's picture, or drawing their own pieces (after the view's).
    void advance_screenshots();
    // A script action that reads the view's picture: when the picture does not show the current
    // state yet, the action is put back and runs again after the frames that render it (true).
    bool retry_once_picture_is_current();
    bool pick_at(int x, int y);

    // input and panels (viewer_panels.cpp)
    void handle_keys();
    void toggle_fullscreen();
    void draw_file_access();
    // A tab asked for by a script (`tab NAME`) is selected once, then the user's clicks rule again.
    ImGuiTabItemFlags tab_flags(const char* name);
    void draw_ui(int window_width, int window_height);
    void draw_effect_tab();
    void draw_effect_warnings();
    void draw_view_tab();
    void draw_help();

    // scripts (script_verbs.cpp)
    // The picture on screen is the current one (a refining picture is finished first).
    bool picture_done() const { return paused_ || !schedule_.pending(); }
    void run_script_step();
    void perform(const ScriptAction& action);  // one handler per verb, from a table
    std::string shown_technique() const;       // the first object's, as plugin verbs report it
    // The verbs' handlers (script.hpp lists them).
    void verb_set(const ScriptAction& action);
    void verb_technique(const ScriptAction& action);
    void verb_view(const ScriptAction& action);
    void verb_mesh(const ScriptAction& action);
    void verb_select(const ScriptAction& action);
    void verb_rotate(const ScriptAction& action);
    void verb_pick(const ScriptAction& action);
    void verb_screenshot(const ScriptAction& action);
    void verb_view_shot(const ScriptAction& action);
    void verb_skybox(const ScriptAction& action);
    void verb_tab(const ScriptAction& action);
    void verb_brdf_check(const ScriptAction& action);
    void verb_brdf_measured(const ScriptAction& action);
    void verb_environment(const ScriptAction& action);
    void verb_light_spectrum(const ScriptAction& action);
    void verb_light_shape(const ScriptAction& action);
    void verb_light_intensity(const ScriptAction& action);
    void verb_exposure(const ScriptAction& action);
    void verb_tone_map(const ScriptAction& action);
    void verb_brdf_view(const ScriptAction& action);
    void verb_brdf_keep(const ScriptAction& action);
    void verb_inspect_texture(const ScriptAction& action);
    void verb_inspect_texel(const ScriptAction& action);
    void verb_open_error(const ScriptAction& action);
    void verb_wait_effect(const ScriptAction& action);
    void verb_plugin_start(const ScriptAction& action);
    void verb_plugin_wait(const ScriptAction& action);
    void verb_plugin_run(const ScriptAction& action);
    void verb_allow_path(const ScriptAction& action);
    void verb_frames(const ScriptAction& action);
    void verb_window(const ScriptAction& action);
    void verb_ui_state(const ScriptAction& action);
    void verb_wait_key(const ScriptAction& action);

    ViewerOptions options_;
    std::unique_ptr<context::Context> context_;
    GLFWwindow* window_ = nullptr;
    std::unique_ptr<ImGuiLayer> imgui_;
    std::unique_ptr<DisplayPass> display_;
    std::unique_ptr<render::DebugRenderer> debug_;
    std::unique_ptr<render::Skybox> skybox_;
    EnvironmentPanel environment_panel_;
    image::DisplaySettings display_settings_, displayed_settings_;
    std::string skybox_name_;
    std::unique_ptr<TexturePanel> texture_panel_;
    std::unique_ptr<gl::RenderTarget> target_;
    RenderSchedule schedule_;
    std::uint64_t coverage_key_ = 0;
    std::vector<double> render_seconds_, ui_frame_seconds_;  // per UI frame: rendering (when any) and the whole frame
    ViewerScene view_;
    ViewMouse mouse_;
    std::string status_;
    glm::ivec2 view_size_{640, 480}, windowed_pos_{0}, windowed_size_{1280, 800}, shot_size_{1920, 1080};
    std::unique_ptr<gl::RenderTarget> preview_;  // the coarse picture a slow one starts with
    std::uint64_t preview_key_ = 0;
    int preview_scale_ = 1;
    double preview_pixel_seconds_ = 0;     // measured cost of a preview pixel (0: not yet)
    std::uint64_t calibrated_key_ = 0;     // the picture whose preview cost was last measured
    bool shot_at_view_size_ = true;          // screenshots: the view as it is, unless a size of their own is asked for
    std::string pending_view_shot_;          // written when the view's picture is complete
    std::unique_ptr<ScreenshotJob> shot_job_;  // a screenshot at shot_size_, rendered in pieces
    std::uint64_t shot_key_ = 0;
    bool paused_ = false, vsync_ = true, srgb_display_ = true, show_help_ = false, transparent_shots_ = false;
    int samples_ = 0, frame_number_ = 0, exit_code_ = 0;
    double frame_seconds_ = 0;
    PickPanel pick_;
    PluginPanel plugin_panel_;
    BrdfPanel brdf_panel_;
    int plugin_start_frame_ = 0;  // plugin-start: frames drawn while the plugin runs
    std::chrono::steady_clock::time_point plugin_start_time_, wait_started_;
    std::string requested_tab_;
    PanelWidth panel_width_;
    float tab_bar_width_ = 0, panel_shown_width_ = 0;  // the tabs' width with their whole names
    bool tabs_fit_ = true;     // the panel shows every tab whole
    std::vector<std::string> pending_window_shots_;
    FileBrowser file_browser_{FXVIEW_SOURCE_EFFECTS_DIR};
    char preset_input_[512] = "preset.json",
         shot_input_[512] = "out/screenshot.png", allow_input_[512] = "";
    EffectState effect_{options_.access};  // destroyed before the context (declared after it)
    std::vector<ScriptAction> script_;
    size_t script_position_ = 0;
    int wait_frames_ = 0;
    bool brdf_check_waiting_ = false;  // the script's brdf-check started a check and waits for it
    int brdf_check_start_frame_ = 0;
    int awaited_key_ = 0;  // wait-key: the GLFW key the script waits for, until key_deadline_
    std::string awaited_key_name_;
    std::chrono::steady_clock::time_point key_deadline_;
    int awake_frames_ = 3;  // frames to draw before the loop may sleep (wait_or_poll_events)
};

}  // namespace fxview::ui

// The viewer window: its loop, rendering (progressive, coarse preview first), screenshots and pick.
// Panels are in viewer_panels.cpp, script verbs in script_verbs.cpp.
#include "ui/viewer_window.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <set>

#include "app/effect_options.hpp"
#include "context/context.hpp"
#include "core/error.hpp"
#include "effect/preset.hpp"
#include "gl/render_target.hpp"
#include "image/image_file.hpp"
#include "image/pixel_info.hpp"
#include "math/arcball.hpp"
#include "render/skybox.hpp"
#include "scene/shapes.hpp"
#include "ui/display_pass.hpp"
#include "ui/environment_panel.hpp"
#include "ui/effect_state.hpp"
#include "ui/error_list.hpp"
#include "app/brdf_evaluation.hpp"
#include "ui/brdf_panel.hpp"
#include "ui/file_browser.hpp"
#include "ui/imgui_layer.hpp"
#include "ui/pick_panel.hpp"
#include "ui/render_schedule.hpp"
#include "ui/scene_panel.hpp"
#include "ui/screenshot.hpp"
#include "ui/texture_panel.hpp"
#include "ui/plugin_panel.hpp"
#include "ui/parameter_panel.hpp"

namespace fxview::ui {
namespace {

namespace fs = std::filesystem;

// SIGTERM/SIGINT end the loop like closing the window, so that `--stats` is still printed. The one
// global state of the viewer: a signal handler can reach nothing else.
volatile std::sig_atomic_t stop_requested = 0;
void request_stop(int) { stop_requested = 1; }

}  // namespace

Viewer::Viewer(const ViewerOptions& options) : options_(options) {
    context::ContextOptions context_options;
    context_options.backend = context::Backend::Glfw;
    context_options.window_width = options.window_width;
    context_options.window_height = options.window_height;
    context_options.window_title = "fxview";
    context_options.debug_output = options.gl_debug;
    context_ = context::create_context(context_options);
    window_ = context_->window();
    glfwSwapInterval(vsync_ ? 1 : 0);
    imgui_ = std::make_unique<ImGuiLayer>(window_, options.ui_scale);
    display_ = std::make_unique<DisplayPass>();
    texture_panel_ = std::make_unique<TexturePanel>();
    debug_ = std::make_unique<render::DebugRenderer>();
    skybox_ = std::make_unique<render::Skybox>();
    view_.scene = options.scene;
    view_.initial = options.scene;
    for (const auto& object : options.scene.objects) view_.objects.push_back({object, options.technique, ViewMode::Effect, false});
    if (!options.effect_path.empty() && effect_.open(options.effect_path, options.technique, options.sets, options.preset)) on_effect_opened();
    if (!session())
        for (auto& o : view_.objects) o.view = ViewMode::Normals;
    if (!options.debug_view.empty())
        for (auto& o : view_.objects) o.view = parse_view(options.debug_view);
    samples_ = options.samples;
    display_settings_ = options.display;
    script_ = options.script;
    // A bad --environment is an error of the command line, not of a frame.
    if (session() && !view_.scene.environment.source.empty()) session()->environment(view_.scene.environment);
}

int Viewer::run() {
    auto last_frame = std::chrono::steady_clock::now();
    std::signal(SIGTERM, request_stop);
    std::signal(SIGINT, request_stop);
    while (!glfwWindowShouldClose(window_) && !stop_requested) {
        const double slept = wait_or_poll_events();
        const auto now = std::chrono::steady_clock::now();
        // A frame's time is its work, not the idle wait before it.
        frame_seconds_ = std::chrono::duration<double>(now - last_frame).count() - slept;
        last_frame = now;
        if (effect_.poll()) on_effect_opened();  // hot reload; a failed start retried when its file is saved
        plugin_panel_.update(session());  // a running plugin's live parameters; its result when done
        brdf_panel_.update(session());    // a slice of a running BRDF check
        follow_plugin_technique();
        if (target_) run_script_step();  // actions need the render view, made by the first frame
        frame();
        ++frame_number_;
        ui_frame_seconds_.push_back(frame_seconds_);
        if (options_.frames > 0 && frame_number_ >= options_.frames && script_position_ >= script_.size() && awaited_key_ == 0 && picture_done()) break;
    }
    if (options_.stats) print_stats();
    return exit_code_;
}

// Idle when idle: with the picture complete and nothing running, the loop sleeps until input
// (or half a second, for the file watcher) instead of drawing frames nobody needs. After an
// event a few frames follow, so that ImGui's hover and release states settle. Returns the
// seconds it slept.
double Viewer::wait_or_poll_events() {
    const bool busy = !picture_done() || picture_animated() || plugin_panel_.running() || brdf_panel_.checking() || script_position_ < script_.size() ||
                      options_.frames > 0 || awake_frames_ > 0 || shot_job_ || !pending_view_shot_.empty();
    if (busy) {
        glfwPollEvents();
        awake_frames_ = std::max(0, awake_frames_ - 1);
        return 0.0;
    }
    const auto start = std::chrono::steady_clock::now();
    constexpr double kTimeout = 0.5;
    glfwWaitEventsTimeout(kTimeout);
    const double slept = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    awake_frames_ = slept < 0.9 * kTimeout ? 3 : 0;  // woken by an event, not by the timeout
    return slept;
}

// `view --stats`: the UI's frame times and the rendering they carried (docs/benchmarks.md).
void Viewer::print_stats() const {
    const auto summary = [](std::vector<double> v, const char* what) {
        if (v.empty()) return std::string(what) + ": none";
        std::sort(v.begin(), v.end());
        double sum = 0;
        for (const double x : v) sum += x;
        char text[200];
        std::snprintf(text, sizeof text, "%s: %zu, mean %.1f ms, median %.1f ms, 95th percentile %.1f ms, max %.1f ms", what, v.size(),
                      1e3 * sum / v.size(), 1e3 * v[v.size() / 2], 1e3 * v[std::min(v.size() - 1, v.size() * 95 / 100)], 1e3 * v.back());
        return std::string(text);
    };
    // The first frame carries the window's and the effect's start-up: left out.
    const std::vector<double> frames(ui_frame_seconds_.begin() + std::min<size_t>(1, ui_frame_seconds_.size()), ui_frame_seconds_.end());
    std::printf("%s\n%s\npictures completed: %d, the last took %.1f ms to render\n", summary(frames, "UI frames").c_str(),
                summary(render_seconds_, "frames that rendered").c_str(), schedule_.pictures(), 1e3 * schedule_.last_picture_seconds());
}

// A newly opened effect: every object shows it, with its technique.
void Viewer::on_effect_opened() {
    for (auto& o : view_.objects) {
        o.technique = session()->technique();
        if (o.view != ViewMode::Effect && o.view != ViewMode::Plain) o.view = ViewMode::Effect;
    }
}

void Viewer::render_scene(const gl::RenderTarget& target) {
    target.bind_for_drawing();
    glClearColor(view_.scene.background.r, view_.scene.background.g, view_.scene.background.b, view_.scene.background.a);
    glClearDepth(1.0);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    const render::GpuTexture* sky = skybox_texture();
    for (const auto& o : view_.objects) {
        scene::Scene single = view_.scene;
        single.objects = {o.object};
        try {
            if (o.view == ViewMode::Effect && session()) {
                const std::string previous = session()->technique();
                if (!o.technique.empty() && o.technique != previous) session()->select_technique(o.technique);
                session()->render(single, target, {static_cast<float>(glfwGetTime()), frame_number_}, false);
                if (session()->technique() != previous) session()->select_technique(previous);
            } else {
                debug_->render(single, debug_view(o.view == ViewMode::Effect ? ViewMode::Plain : o.view), target, false);
            }
        } catch (const std::exception& error) {
            effect_.set_error(error.what());
        }
    }
    if (sky) {
        skybox_->draw(sky->texture.get(), view_.scene.camera, target);
    } else if (session() && !view_.scene.environment.source.empty()) {
        try {  // the scene's environment as background
            const render::EnvironmentMaps& environment = session()->environment(view_.scene.environment);
            skybox_->draw(environment.background().texture.get(), view_.scene.camera, target,
                          {view_.scene.environment.world_to_environment(), view_.scene.environment.intensity, true});
        } catch (const std::exception& error) {
            effect_.set_error(error.what());
        }
    }
    target.resolve();
}

const render::GpuTexture* Viewer::skybox_texture() const {
    if (!session() || skybox_name_.empty()) return nullptr;
    const render::GpuTexture* texture = session()->resources().find(skybox_name_);
    return texture && texture->type == texture::TextureType::Cube ? texture : nullptr;
}

// A hash of everything the picture depends on: scene, objects and their views, effect (a reload
// makes a new one), parameter values, display settings and size.
std::uint64_t Viewer::render_key(int width, int height) const {
    StateHash h;
    h.add(width).add(height).add(samples_).add(srgb_display_).add(skybox_name_);
    view_.add_to(h);
    if (session()) {
        h.add(reinterpret_cast<std::uintptr_t>(&session()->effect())).add(reinterpret_cast<std::uintptr_t>(&session()->resources()));
        h.add(session()->technique());
        for (const auto& [name, value] : session()->values().numbers) {
            h.add(name);
            for (const double x : value) h.add(x);
        }
        for (const auto& [name, file] : session()->values().textures) h.add(name).add(file);
    }
    return h.value();
}

// Where the objects are, per row, for the render schedule's cost model: a cheap render at a
// quarter of the size, redone when the geometry changes and only for pictures that are slow.
void Viewer::update_coverage(int width, int height) {
    if (schedule_.pictures() > 0 && schedule_.last_picture_seconds() < 0.05) return;
    StateHash h;
    h.add(width).add(height);
    view_.add_to(h);  // more than the geometry (a new colour redoes it too): cheap, and only for slow pictures
    if (h.value() == coverage_key_) return;
    coverage_key_ = h.value();
    const int w = std::max(1, width / 4), ht = std::max(1, height / 4);
    gl::RenderTarget small({w, ht, 1, 0});
    scene::Scene scene = view_.scene;
    scene.background = glm::vec4(0.0f);
    scene.objects.clear();
    for (const auto& o : view_.objects) scene.objects.push_back(o.object);
    debug_->render(scene, render::DebugView::Normals, small, true);
    const image::FloatImage image = small.read_color(0);  // top row first
    std::vector<double> rows(static_cast<size_t>(height), 0.0);
    for (int y = 0; y < height; ++y) {
        const int source = std::min(ht - 1, y * ht / height);
        double count = 0;
        for (int x = 0; x < w; ++x) count += image.data[(static_cast<size_t>(source) * w + x) * 4 + 3] > 0 ? 1.0 : 0.0;
        rows[static_cast<size_t>(y)] = count * width / w;
    }
    schedule_.set_coverage(std::move(rows));
}

bool Viewer::picture_animated() const {
    if (!session()) return false;
    for (const auto& o : view_.objects)
        if (o.view == ViewMode::Effect && session()->animated(o.technique.empty() ? session()->technique() : o.technique)) return true;
    return false;
}

// Coarse to fine: a picture that took long starts as a low-resolution one, drawn whole (within
// about 50 ms, by the last complete picture's measured time) and scaled up into the view; the
// pieces then refine it row by row. A drag, which starts a new picture at every move, so shows
// a coarse but whole picture at once instead of a torn one. True when it drew one this frame.
namespace {
constexpr double kSlowPicture = 0.15, kPreviewSeconds = 0.05;
}

// The preview's resolution: from the measured cost of a preview pixel (a tiny picture is drawn by one
// thread and pays for whole 4x4 blocks at its edges: on llvmpipe 2-4 times the full picture's cost
// per pixel), else from the last picture's, 4 times over.
int Viewer::preview_scale_for(int width, int height) const {
    const double pixels = static_cast<double>(width) * height;
    const double per_pixel = preview_pixel_seconds_ > 0 ? preview_pixel_seconds_ : 4.0 * schedule_.last_picture_seconds() / pixels;
    return std::clamp(static_cast<int>(std::ceil(std::sqrt(pixels * per_pixel / kPreviewSeconds))), 2, 64);
}

double Viewer::draw_preview(int width, int height) {
    const int preview_width = (width + preview_scale_ - 1) / preview_scale_, preview_height = (height + preview_scale_ - 1) / preview_scale_;
    if (!preview_ || preview_->width() != preview_width || preview_->height() != preview_height)
        preview_ = std::make_unique<gl::RenderTarget>(gl::RenderTargetDesc{preview_width, preview_height, 1, 0});
    const auto start = std::chrono::steady_clock::now();
    render_scene(*preview_);
    glFinish();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    preview_pixel_seconds_ = seconds / (static_cast<double>(preview_width) * preview_height);
    render_seconds_.push_back(seconds);
    return seconds;
}

bool Viewer::render_coarse_preview(std::uint64_t key, int width, int height) {
    const double last = schedule_.last_picture_seconds();
    if (!picture_progressive() || last < kSlowPicture) return false;
    if (!schedule_.pending()) {
        // A slow picture just completed: a preview of it is measured once (not shown), so that the
        // first preview of a drag already has the resolution that keeps it near 50 ms.
        if (calibrated_key_ != key) {
            calibrated_key_ = key;
            preview_scale_ = preview_scale_for(width, height);
            draw_preview(width, height);
        }
        return false;
    }
    if (schedule_.refining() || key == preview_key_) return false;
    preview_scale_ = preview_scale_for(width, height);
    draw_preview(width, height);
    glBlitNamedFramebuffer(preview_->framebuffer(), target_->framebuffer(), 0, 0, preview_->width(), preview_->height(), 0, 0, width, height,
                           GL_COLOR_BUFFER_BIT, GL_LINEAR);
    preview_key_ = key;
    return true;
}

bool Viewer::picture_progressive() const {
    if (!session()) return true;
    for (const auto& o : view_.objects)
        if (o.view == ViewMode::Effect && session()->renders_to_textures(o.technique.empty() ? session()->technique() : o.technique)) return false;
    return true;
}

void Viewer::frame() {
    int window_width = 0, window_height = 0;
    glfwGetFramebufferSize(window_, &window_width, &window_height);
    const int width = options_.render_width > 0 ? options_.render_width : std::max(16, view_size_.x);
    const int height = options_.render_height > 0 ? options_.render_height : std::max(16, view_size_.y);
    if (!target_ || target_->width() != width || target_->height() != height || target_->multisampled() != (samples_ > 1))
        target_ = std::make_unique<gl::RenderTarget>(gl::RenderTargetDesc{width, height, 1, samples_});
    if (!paused_) {
        // Render only what changed: nothing while the picture is current, strips across UI frames
        // while a slow picture refines (render_schedule.hpp).
        const std::uint64_t key = render_key(width, height);
        schedule_.update(key, picture_animated(), picture_progressive());
        update_coverage(width, height);
        const bool coarse = render_coarse_preview(key, width, height);
        const RenderSchedule::Work work = coarse ? RenderSchedule::Work{} : schedule_.next(width, height);
        if (coarse) {
            display_->run(target_->color_texture(0), width, height, srgb_display_, display_settings_);
            displayed_settings_ = display_settings_;
        } else if (work.height > 0) {
            const auto start = std::chrono::steady_clock::now();
            const bool piece = work.width < width || work.height < height;
            if (piece) {  // y counts from the top of the picture, GL's from the bottom
                glEnable(GL_SCISSOR_TEST);
                glScissor(work.x, height - work.y - work.height, work.width, work.height);
            }
            render_scene(*target_);  // clears and resolves inside the scissor only
            glDisable(GL_SCISSOR_TEST);
            glFinish();  // the strip's cost, for the next strip's size
            const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            schedule_.done(work, seconds);
            render_seconds_.push_back(seconds);
            display_->run(target_->color_texture(0), width, height, srgb_display_, display_settings_);
            displayed_settings_ = display_settings_;
        } else if (displayed_settings_.exposure_ev != display_settings_.exposure_ev || displayed_settings_.tone_map != display_settings_.tone_map) {
            display_->run(target_->color_texture(0), width, height, srgb_display_, display_settings_);  // no new render needed
            displayed_settings_ = display_settings_;
        }
    }
    advance_screenshots();
    imgui_->begin_frame();
    draw_ui(window_width, window_height);
    handle_keys();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, window_width, window_height);
    glDisable(GL_FRAMEBUFFER_SRGB);
    glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    imgui_->end_frame();
    for (const auto& path : pending_window_shots_) write_window_png(path, window_width, window_height);
    pending_window_shots_.clear();
    const bool last = options_.frames > 0 && frame_number_ + 1 >= options_.frames && script_position_ >= script_.size() && picture_done();
    if (last && !options_.screenshot.empty()) write_window_png(options_.screenshot, window_width, window_height);
    if (last && !options_.render_screenshot.empty()) write_render(options_.render_screenshot);
    context_->swap_buffers();
}

// F12 and the button: by default exactly what the view shows (its size, aspect and display
// transform), written once its picture is complete; at a size of its own only when asked for,
// rendered in pieces across frames (screenshot.hpp). Neither blocks the UI.
void Viewer::write_render(const std::string& path) {
    write_picture(path, target_->read_color(0), srgb_display_, true, display_settings_);
}

void Viewer::save_screenshot() {
    if (shot_at_view_size_) {
        pending_view_shot_ = shot_input_;
        status_ = "screenshot " + pending_view_shot_ + ": when the picture is complete";
        return;
    }
    shot_job_ = std::make_unique<ScreenshotJob>(shot_input_, shot_size_.x, shot_size_.y, samples_, transparent_shots_);
    shot_key_ = render_key(shot_size_.x, shot_size_.y);
}

void Viewer::write_view_shot(const std::string& path) {
    write_picture(path, target_->read_color(0), srgb_display_, transparent_shots_, display_settings_);
    status_ = "saved " + path;
}

// Screenshots waiting for the view's picture, or drawing their own pieces (after the view's).
void Viewer::advance_screenshots() {
    try {
        if (!pending_view_shot_.empty() && target_ && picture_done()) {
            const std::string path = std::move(pending_view_shot_);
            pending_view_shot_.clear();
            write_view_shot(path);
        }
        if (!shot_job_ || !picture_done()) return;
        if (render_key(shot_size_.x, shot_size_.y) != shot_key_) {  // the scene changed: start over, never a torn picture
            shot_job_ = std::make_unique<ScreenshotJob>(shot_job_->path(), shot_size_.x, shot_size_.y, samples_, transparent_shots_);
            shot_key_ = render_key(shot_size_.x, shot_size_.y);
        }
        if (shot_job_->step([&](const gl::RenderTarget& target) { render_scene(target); }, picture_progressive(), srgb_display_,
                            display_settings_)) {
            status_ = "saved " + shot_job_->path();
            shot_job_.reset();
        }
    } catch (const std::exception& e) {
        status_ = e.what();
        shot_job_.reset();
    }
}

// A script action that reads the view's picture: when the picture does not show the current
// state yet, the action is put back and runs again after the frames that render it (true).
bool Viewer::retry_once_picture_is_current() {
    schedule_.update(render_key(target_->width(), target_->height()), false, picture_progressive());
    if (picture_done()) return false;
    --script_position_;
    wait_frames_ = 1;
    return true;
}

bool Viewer::pick_at(int x, int y) {
    return pick_.pick(target_->read_color(0), x, y, srgb_display_, render_key(target_->width(), target_->height()));
}

void Viewer::follow_plugin_technique() {
    const std::string technique = plugin_panel_.take_technique_change();
    if (!technique.empty())
        for (auto& o : view_.objects) o.technique = technique;
}

int run_viewer(const ViewerOptions& options) {
    Viewer viewer(options);
    return viewer.run();
}

}  // namespace fxview::ui

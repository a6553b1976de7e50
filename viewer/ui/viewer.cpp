#include "ui/viewer.hpp"

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

class Viewer {
public:
    explicit Viewer(const ViewerOptions& options) : options_(options) {
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

    int run() {
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
            if (target_) run_script_step();  // actions need the render view, made by the first frame
            frame();
            ++frame_number_;
            ui_frame_seconds_.push_back(frame_seconds_);
            if (options_.frames > 0 && frame_number_ >= options_.frames && script_position_ >= script_.size() && picture_done()) break;
        }
        if (options_.stats) print_stats();
        return exit_code_;
    }

    // Idle when idle: with the picture complete and nothing running, the loop sleeps until input
    // (or half a second, for the file watcher) instead of drawing frames nobody needs. After an
    // event a few frames follow, so that ImGui's hover and release states settle. Returns the
    // seconds it slept.
    double wait_or_poll_events() {
        const bool busy = !picture_done() || picture_animated() || plugin_panel_.running() || script_position_ < script_.size() ||
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
    void print_stats() const {
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

private:
    // A newly opened effect: every object shows it, with its technique.
    void on_effect_opened() {
        for (auto& o : view_.objects) {
            o.technique = session()->technique();
            if (o.view != ViewMode::Effect && o.view != ViewMode::Plain) o.view = ViewMode::Effect;
        }
    }

    render::EffectSession* session() { return effect_.session(); }
    const render::EffectSession* session() const { return effect_.session(); }

    void draw_file_access() {
        if (!ImGui::CollapsingHeader("File access")) return;
        ImGui::TextWrapped("Effects read includes, textures and data only from their own folder and these folders:");
        for (const auto& folder : effect_.allowed_folders()) ImGui::BulletText("%s", folder.c_str());
        ImGui::InputText("##allow", allow_input_, sizeof allow_input_);
        ImGui::SameLine();
        if (ImGui::Button("Allow folder")) {
            try {
                const bool had_effect = session() != nullptr;
                effect_.allow_folder(allow_input_);
                if (!had_effect && session()) on_effect_opened();
            } catch (const std::exception& error) {
                status_ = error.what();
            }
        }
    }

    // --- rendering -------------------------------------------------------------------------
    void render_scene(const gl::RenderTarget& target) {
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
                skybox_->draw(environment.texture("environment:specular")->texture.get(), view_.scene.camera, target,
                              {view_.scene.environment.world_to_environment(), view_.scene.environment.intensity, true});
            } catch (const std::exception& error) {
                effect_.set_error(error.what());
            }
        }
        target.resolve();
    }

    const render::GpuTexture* skybox_texture() const {
        if (!session() || skybox_name_.empty()) return nullptr;
        const render::GpuTexture* texture = session()->resources().find(skybox_name_);
        return texture && texture->type == texture::TextureType::Cube ? texture : nullptr;
    }

    // A hash of everything the picture depends on: scene, objects and their views, effect (a reload
    // makes a new one), parameter values, display settings and size.
    std::uint64_t render_key(int width, int height) const {
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
    void update_coverage(int width, int height) {
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

    bool picture_animated() const {
        if (!session()) return false;
        for (const auto& o : view_.objects)
            if (o.view == ViewMode::Effect && session()->animated(o.technique.empty() ? session()->technique() : o.technique)) return true;
        return false;
    }

    // Coarse to fine: a picture that took long starts as a low-resolution one, drawn whole (within
    // about 50 ms, by the last complete picture's measured time) and scaled up into the view; the
    // pieces then refine it row by row. A drag, which starts a new picture at every move, so shows
    // a coarse but whole picture at once instead of a torn one. True when it drew one this frame.
    bool render_coarse_preview(std::uint64_t key, int width, int height) {
        constexpr double kSlowPicture = 0.15, kPreviewSeconds = 0.05;
        const double last = schedule_.last_picture_seconds();
        if (!schedule_.pending() || schedule_.refining() || key == preview_key_ || last < kSlowPicture || !picture_progressive()) return false;
        preview_scale_ = std::clamp(static_cast<int>(std::ceil(std::sqrt(last / kPreviewSeconds))), 2, 32);
        const int preview_width = (width + preview_scale_ - 1) / preview_scale_, preview_height = (height + preview_scale_ - 1) / preview_scale_;
        if (!preview_ || preview_->width() != preview_width || preview_->height() != preview_height)
            preview_ = std::make_unique<gl::RenderTarget>(gl::RenderTargetDesc{preview_width, preview_height, 1, 0});
        render_scene(*preview_);
        glBlitNamedFramebuffer(preview_->framebuffer(), target_->framebuffer(), 0, 0, preview_width, preview_height, 0, 0, width, height,
                               GL_COLOR_BUFFER_BIT, GL_LINEAR);
        glFinish();
        preview_key_ = key;
        return true;
    }

    bool picture_progressive() const {
        if (!session()) return true;
        for (const auto& o : view_.objects)
            if (o.view == ViewMode::Effect && session()->renders_to_textures(o.technique.empty() ? session()->technique() : o.technique)) return false;
        return true;
    }

    void frame() {
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

    // The render view's picture as rendered (linear values, alpha kept).
    void write_render(const std::string& path) { write_picture(path, target_->read_color(0), srgb_display_, true, display_settings_); }

    // F12 and the button: by default exactly what the view shows (its size, aspect and display
    // transform), written once its picture is complete; at a size of its own only when asked for,
    // rendered in pieces across frames (screenshot.hpp). Neither blocks the UI.
    void save_screenshot() {
        if (shot_at_view_size_) {
            pending_view_shot_ = shot_input_;
            status_ = "screenshot " + pending_view_shot_ + ": when the picture is complete";
            return;
        }
        shot_job_ = std::make_unique<ScreenshotJob>(shot_input_, shot_size_.x, shot_size_.y, samples_, transparent_shots_);
        shot_key_ = render_key(shot_size_.x, shot_size_.y);
    }

    void write_view_shot(const std::string& path) {
        write_picture(path, target_->read_color(0), srgb_display_, transparent_shots_, display_settings_);
        status_ = "saved " + path;
    }

    // Screenshots waiting for the view's picture, or drawing their own pieces (after the view's).
    void advance_screenshots() {
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

    // Whether the view's picture shows the current state (a script action that reads it waits
    // for the frames that render it otherwise).
    bool picture_current() {
        schedule_.update(render_key(target_->width(), target_->height()), false, picture_progressive());
        return picture_done();
    }

    bool pick_at(int x, int y) {
        return pick_.pick(target_->read_color(0), x, y, srgb_display_, render_key(target_->width(), target_->height()));
    }

    // --- input -----------------------------------------------------------------------------
    void handle_keys() {
        if (ImGui::GetIO().WantCaptureKeyboard) return;
        const bool shift = ImGui::GetIO().KeyShift;
        if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Space))) paused_ = !paused_;
        const auto pressed = [](int key) { return ImGui::IsKeyPressed(key); };
        if (pressed(GLFW_KEY_C)) view_.selected = Target::Camera;
        if (pressed(GLFW_KEY_L)) view_.selected = Target::Light;
        if (pressed(GLFW_KEY_O) && !view_.objects.empty()) view_.selected = Target::Object;
        if (pressed(GLFW_KEY_TAB) && !view_.objects.empty()) {
            view_.selected = Target::Object;
            view_.selected_object = (view_.selected_object + 1) % static_cast<int>(view_.objects.size());
        }
        if (pressed(GLFW_KEY_R)) {
            if (shift) {
                view_.reset_all();
            } else {
                view_.reset_selected();
            }
        }
        if (pressed(GLFW_KEY_V)) {
            vsync_ = !vsync_;
            glfwSwapInterval(vsync_ ? 1 : 0);
        }
        if (pressed(GLFW_KEY_G)) srgb_display_ = !srgb_display_;
        if (pressed(GLFW_KEY_H) || pressed(GLFW_KEY_F1)) show_help_ = !show_help_;
        if (pressed(GLFW_KEY_F11)) toggle_fullscreen();
        if (pressed(GLFW_KEY_F12)) save_screenshot();
    }

    void toggle_fullscreen() {
        GLFWmonitor* monitor = glfwGetWindowMonitor(window_);
        if (monitor) {
            glfwSetWindowMonitor(window_, nullptr, windowed_pos_.x, windowed_pos_.y, windowed_size_.x, windowed_size_.y, 0);
            return;
        }
        GLFWmonitor* primary = glfwGetPrimaryMonitor();
        if (!primary) return;
        glfwGetWindowPos(window_, &windowed_pos_.x, &windowed_pos_.y);
        glfwGetWindowSize(window_, &windowed_size_.x, &windowed_size_.y);
        const GLFWvidmode* mode = glfwGetVideoMode(primary);
        glfwSetWindowMonitor(window_, primary, 0, 0, mode->width, mode->height, mode->refreshRate);
    }

    // --- panels ----------------------------------------------------------------------------
    // A tab asked for by a script (`tab NAME`) is selected once, then the user's clicks rule again.
    ImGuiTabItemFlags tab_flags(const char* name) {
        if (requested_tab_ != name) return 0;
        requested_tab_.clear();
        return ImGuiTabItemFlags_SetSelected;
    }

    void draw_ui(int window_width, int window_height) {
        // The panel is as wide as the user drags its right edge (labels need room), the full height.
        const float height = static_cast<float>(window_height), scale = imgui_->scale();
        ImGui::SetNextWindowPos(ImVec2(0, 0));
        ImGui::SetNextWindowSize(ImVec2(std::min(460.0f * scale, window_width * 0.45f), height), ImGuiCond_FirstUseEver);
        ImGui::SetNextWindowSizeConstraints(ImVec2(std::min(240.0f * scale, window_width * 0.5f), height),
                                            ImVec2(std::max(240.0f * scale, window_width * 0.8f), height));
        ImGui::Begin("fxview", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse);
        const float panel_width = ImGui::GetWindowWidth();
        ImGui::Text("%.1f FPS  frame %.1f ms  picture %.1f ms%s", frame_seconds_ > 0 ? 1.0 / frame_seconds_ : 0.0, frame_seconds_ * 1e3,
                    schedule_.last_picture_seconds() * 1e3, paused_ ? "  (paused)" : "");
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("frame: the UI's frame time; picture: what the last complete picture took to render (the view is "
                              "drawn only when something changed, slow pictures in strips across frames)");
        {
            // Always drawn, so that the widgets below keep their place when a picture starts refining.
            char text[96];
            const bool coarse = schedule_.pending() && preview_key_ == render_key(target_ ? target_->width() : 0, target_ ? target_->height() : 0);
            if (!schedule_.pending()) std::snprintf(text, sizeof text, "picture complete");
            else if (coarse) std::snprintf(text, sizeof text, "preview at 1/%d resolution, refining %.0f %%", preview_scale_, schedule_.progress() * 100);
            else std::snprintf(text, sizeof text, "refining %.0f %%", schedule_.progress() * 100);
            ImGui::ProgressBar(schedule_.pending() ? static_cast<float>(schedule_.progress()) : 1.0f, ImVec2(-1, 0), text);
        }
        if (imgui_->font_fallback())
            ImGui::TextDisabled("UI font %s missing (fonts-dejavu-core): Greek letters show as '?'", FXVIEW_UI_FONT);
        if (ImGui::BeginTabBar("tabs")) {
            if (ImGui::BeginTabItem("Effect", nullptr, tab_flags("Effect"))) {
                draw_effect_tab();
                ImGui::EndTabItem();
            }
            if (ImGui::BeginTabItem("Scene", nullptr, tab_flags("Scene"))) {
                draw_scene_panel(view_, session() ? session()->technique() : "", session() != nullptr, status_);
                environment_panel_.draw(view_.scene.environment, session());
                ImGui::EndTabItem();
            }
            if (ImGui::BeginTabItem("Textures", nullptr, tab_flags("Textures"))) {
                if (session()) texture_panel_->draw(*session(), skybox_name_, status_);
                else ImGui::TextUnformatted("No effect loaded.");
                ImGui::EndTabItem();
            }
            if (ImGui::BeginTabItem("Pick", nullptr, tab_flags("Pick"))) {
                pick_.draw(target_ ? render_key(target_->width(), target_->height()) : 0);
                ImGui::EndTabItem();
            }
            if (ImGui::BeginTabItem("View", nullptr, tab_flags("View"))) {
                draw_view_tab();
                ImGui::EndTabItem();
            }
            if (ImGui::BeginTabItem("Plugins", nullptr, tab_flags("Plugins"))) {
                plugin_panel_.draw(session());
                ImGui::EndTabItem();
            }
            if (ImGui::BeginTabItem("BRDF", nullptr, tab_flags("BRDF"))) {
                brdf_panel_.draw(session());
                ImGui::EndTabItem();
            }
            ImGui::EndTabBar();
        }
        if (!status_.empty()) {
            ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
            ImGui::TextWrapped("%s", status_.c_str());
            ImGui::PopStyleColor();
        }
        ImGui::End();

        ImGui::SetNextWindowPos(ImVec2(panel_width, 0));
        ImGui::SetNextWindowSize(ImVec2(window_width - panel_width, static_cast<float>(window_height)));
        ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
        ImGui::Begin("Render", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                                            ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoTitleBar);
        const ImVec2 available = ImGui::GetContentRegionAvail();
        view_size_ = glm::ivec2(static_cast<int>(available.x), static_cast<int>(available.y));
        // A fixed render size is shown scaled to fit, keeping its aspect.
        ImVec2 shown = available;
        if (target_) {
            const float scale = std::min(available.x / target_->width(), available.y / target_->height());
            shown = ImVec2(target_->width() * scale, target_->height() * scale);
        }
        const ImVec2 origin = ImGui::GetCursorScreenPos();
        if (display_->texture())
            ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(display_->texture())), shown, ImVec2(0, 1), ImVec2(1, 0));
        else
            ImGui::Dummy(shown);
        if (const auto click = mouse_.handle(view_, origin, shown); click && target_)
            pick_at(static_cast<int>(click->x * target_->width()), static_cast<int>(click->y * target_->height()));
        draw_light_gizmo(view_, ImGui::GetWindowDrawList(), origin, shown);
        if (target_) {
            pick_.draw_marker(ImGui::GetWindowDrawList(), origin, shown, target_->width(), target_->height());
            if (ImGui::IsItemHovered() && !mouse_.dragging() && !ImGui::IsMouseDown(ImGuiMouseButton_Right))
                PickPanel::draw_hover_readout(*target_, origin, shown);
        }
        if (!effect_.error().empty()) {  // compile errors overlay; the last good effect keeps rendering
            ImGui::SetCursorScreenPos(ImVec2(origin.x + 8, origin.y + 8));
            ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
            ImGui::TextWrapped("%s", effect_.error().c_str());
            ImGui::PopStyleColor();
        }
        ImGui::End();
        ImGui::PopStyleVar();
        if (show_help_) draw_help();
    }

    void draw_effect_tab() {
        ImGui::TextWrapped("Effect: %s", effect_.path().empty() ? "(none: built-in views)" : effect_.path().c_str());
        const std::vector<ErrorLocation>& errors = effect_.error_places();
        if (!errors.empty() && ImGui::CollapsingHeader(("Errors (" + std::to_string(errors.size()) + "): click to open in your editor").c_str(),
                                                       ImGuiTreeNodeFlags_DefaultOpen)) {
            for (size_t i = 0; i < errors.size(); ++i) {
                ImGui::PushID(static_cast<int>(i));
                if (ImGui::SmallButton("Open")) status_ = open_in_editor(errors[i].file, errors[i].line);
                if (ImGui::IsItemHovered()) ImGui::SetTooltip("Open %s at line %d in $VISUAL / $EDITOR", errors[i].file.c_str(), errors[i].line);
                ImGui::SameLine();
                ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.55f, 0.5f, 1.0f));
                ImGui::TextWrapped("%s", errors[i].message.c_str());
                ImGui::PopStyleColor();
                ImGui::PopID();
            }
        }
        if (ImGui::Button("Open...")) ImGui::OpenPopup("Open effect");
        if (ImGui::BeginPopup("Open effect")) {
            if (const auto file = file_browser_.draw()) {
                if (effect_.open(*file)) on_effect_opened();
                ImGui::CloseCurrentPopup();
            }
            ImGui::EndPopup();
        }
        if (!session()) {
            if (!effect_.requested_path().empty()) {
                // The file is watched; Reload also retries after fixing an include or a texture.
                if (ImGui::Button("Reload") && effect_.retry()) on_effect_opened();
                ImGui::SameLine();
                ImGui::TextDisabled("%s failed to load (watched: saving it retries)", effect_.requested_path().c_str());
            }
            draw_file_access();
            return;
        }
        ImGui::SameLine();
        if (ImGui::Button("Reload")) {
            effect_.reload();
        }
        if (!view_.objects.empty()) {
            auto& object = view_.objects[static_cast<size_t>(view_.selected_object)];
            // A technique's UIName annotation, where it has one, is what the user reads; its name (for the
            // command line) is in the tooltip.
            const effect::Technique* current = session()->effect().find_technique(object.technique);
            if (ImGui::BeginCombo("technique", current ? current->label().c_str() : object.technique.c_str())) {
                for (const auto& t : session()->effect().techniques) {
                    if (ImGui::Selectable((t.label() + "##" + t.name).c_str(), t.name == object.technique)) {
                        for (auto& o : view_.objects)
                            if (&o == &object || ImGui::GetIO().KeyShift) o.technique = t.name;
                    }
                    if (ImGui::IsItemHovered()) ImGui::SetTooltip("--technique %s", t.name.c_str());
                }
                ImGui::EndCombo();
            }
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("Technique of the selected object (Shift: all objects): --technique %s", object.technique.c_str());
        }
        ImGui::InputText("preset", preset_input_, sizeof preset_input_);
        if (ImGui::Button("Save preset")) {
            try {
                effect::save_preset(preset_input_, session()->effect(), session()->technique(), session()->values());
                status_ = std::string("saved ") + preset_input_;
            } catch (const std::exception& e) {
                status_ = e.what();
            }
        }
        ImGui::SameLine();
        if (ImGui::Button("Load preset")) {
            try {
                effect::load_preset(preset_input_, session()->effect(), session()->values());
                session()->reload_textures();
                status_ = std::string("loaded ") + preset_input_;
            } catch (const std::exception& e) {
                status_ = e.what();
            }
        }
        draw_file_access();
        ImGui::Separator();
        std::vector<std::string> shown;  // the techniques on screen
        for (const auto& o : view_.objects) {
            const std::string& t = o.technique.empty() ? session()->technique() : o.technique;
            if (o.view == ViewMode::Effect && std::find(shown.begin(), shown.end(), t) == shown.end()) shown.push_back(t);
        }
        if (shown.empty()) shown.push_back(session()->technique());
        draw_parameter_panel(*session(), shown);
    }

    void draw_view_tab() {
        ImGui::Checkbox("pause rendering (Space)", &paused_);
        if (ImGui::Checkbox("vsync (V)", &vsync_)) glfwSwapInterval(vsync_ ? 1 : 0);
        ImGui::Checkbox("sRGB display (G: legacy linear)", &srgb_display_);
        const char* sample_counts[] = {"off", "2", "4", "8"};
        int msaa = samples_ == 0 ? 0 : samples_ == 2 ? 1 : samples_ == 4 ? 2 : 3;
        if (ImGui::Combo("MSAA", &msaa, sample_counts, 4)) samples_ = msaa == 0 ? 0 : 1 << msaa;
        ImGui::SliderFloat("exposure", &display_settings_.exposure_ev, -10.0f, 10.0f, "%+.1f EV");
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Scales the picture by 2^EV before tone mapping (the view and PNG screenshots; EXR stays linear)");
        const char* tone_maps[] = {"none (clip)", "ACES filmic (Hill's fit)", "Khronos PBR Neutral"};
        int tone_map = static_cast<int>(display_settings_.tone_map);
        if (ImGui::Combo("tone mapping", &tone_map, tone_maps, 3)) display_settings_.tone_map = static_cast<image::ToneMap>(tone_map);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("PBR Neutral keeps colours below 0.76 (less a toe offset of 0.04) and compresses highlights");
        if (ImGui::Button("Fullscreen (F11)")) toggle_fullscreen();
        ImGui::Separator();
        ImGui::Checkbox("screenshot at the view's size", &shot_at_view_size_);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Off: render the screenshot at a size of its own, in pieces, while the UI goes on");
        ImGui::BeginDisabled(shot_at_view_size_);
        ImGui::InputInt2("screenshot size", &shot_size_.x);
        ImGui::EndDisabled();
        shot_size_ = glm::clamp(shot_size_, glm::ivec2(1), glm::ivec2(16384));
        ImGui::InputText("file (.png/.exr)", shot_input_, sizeof shot_input_);
        ImGui::Checkbox("transparent background", &transparent_shots_);
        if (ImGui::Button("Save screenshot (F12)")) save_screenshot();
        if (shot_job_) {
            char text[64];
            std::snprintf(text, sizeof text, "screenshot %.0f %%", shot_job_->progress() * 100);
            ImGui::ProgressBar(static_cast<float>(shot_job_->progress()), ImVec2(-1, 0), text);
        }
    }

    void draw_help() {
        ImGui::Begin("Keys", &show_help_, ImGuiWindowFlags_AlwaysAutoResize);
        ImGui::TextUnformatted(
            "Mouse (render view)\n"
            "  left drag      turn the selected camera / light / object (arcball)\n"
            "  right drag     move it in the view plane (camera: pan)\n"
            "  wheel          zoom (camera Z translation)\n"
            "  left click     pick the pixel\n"
            "Keys\n"
            "  C / L / O      select camera / light / object\n"
            "  Tab            next object\n"
            "  R              reset the selection     Shift+R  reset all\n"
            "  Space          pause rendering         V        vsync\n"
            "  G              sRGB / legacy display   F11      fullscreen\n"
            "  F12            save screenshot\n"
            "  H or F1        this help");
        ImGui::End();
    }

    // --- scripts ---------------------------------------------------------------------------
    // The picture on screen is the current one (a refining picture is finished first).
    bool picture_done() const { return paused_ || !schedule_.pending(); }

    void run_script_step() {
        if (!picture_done()) return;  // actions see the picture their predecessors asked for
        if (wait_frames_ > 0) {
            --wait_frames_;
            return;
        }
        while (script_position_ < script_.size() && wait_frames_ == 0) {
            const ScriptAction& a = script_[script_position_++];
            try {
                perform(a);
            } catch (const std::exception& error) {
                std::cerr << "fxview: script line " << a.line << ": " << error.what() << "\n";
                exit_code_ = 1;
            }
        }
    }

    void perform(const ScriptAction& a) {
        const auto& args = a.arguments;
        if (a.verb == "set") {
            if (!session()) throw UsageError("no effect loaded");
            effect::ParameterValues edited = session()->values();
            effect::set_value_from_text(session()->effect(), edited, args[0] + "=" + args[1]);
            effect::check_constraints(session()->effect(), edited);
            session()->values() = std::move(edited);
            if (!session()->values().textures.empty()) session()->reload_textures();
        } else if (a.verb == "technique") {
            if (!session()) throw UsageError("no effect loaded");
            session()->select_technique(args[0]);  // validates the name
            for (auto& o : view_.objects) o.technique = args[0];
        } else if (a.verb == "view") {
            for (auto& o : view_.objects) o.view = parse_view(args[0]);
        } else if (a.verb == "mesh") {
            scene::load_mesh(args[0]);
            view_.objects[static_cast<size_t>(view_.selected_object)].object.mesh = args[0];
        } else if (a.verb == "select") {
            if (args[0] == "camera") view_.selected = Target::Camera;
            else if (args[0] == "light") view_.selected = Target::Light;
            else if (args[0] == "object") {
                view_.selected = Target::Object;
                if (args.size() == 2) view_.selected_object = std::clamp(std::stoi(args[1]), 0, static_cast<int>(view_.objects.size()) - 1);
            } else throw UsageError("select camera, light or object");
        } else if (a.verb == "rotate") {
            const Target saved = view_.selected;
            view_.selected = args[0] == "camera" ? Target::Camera : args[0] == "light" ? Target::Light : Target::Object;
            view_.rotate_selected(math::rotation_from_euler_degrees({std::stof(args[1]), std::stof(args[2]), std::stof(args[3])}));
            view_.selected = saved;
        } else if (a.verb == "pick") {
            if (!picture_current()) {  // the picture the pick reads is rendered first, in pieces
                --script_position_;
                wait_frames_ = 1;
                return;
            }
            if (!pick_at(std::stoi(args[0]), std::stoi(args[1]))) throw UsageError("pick outside the render view");
            const auto& p = pick_.info();
            std::cout << nlohmann::json{{"x", p.x}, {"y", p.y}, {"width", target_->width()}, {"height", target_->height()},
                                        {"rgba", p.rgba}, {"rgba8", p.rgba8}, {"packed", p.packed},
                                        {"normal", {p.normal.x, p.normal.y, p.normal.z}}, {"xy", pick_.chromaticity()}}
                             .dump()
                      << std::endl;
        } else if (a.verb == "screenshot") {
            pending_window_shots_.push_back(args[0]);
            wait_frames_ = 1;
        } else if (a.verb == "save-screenshot" || a.verb == "render-screenshot") {  // the view's picture, once current
            if (!picture_current()) {
                --script_position_;  // again after the frames that render it
                wait_frames_ = 1;
                return;
            }
            if (a.verb == "save-screenshot") write_view_shot(args[0]);  // as the Save screenshot button
            else write_render(args[0]);
        } else if (a.verb == "skybox") {
            skybox_name_ = args[0] == "off" ? "" : args[0];
            if (!skybox_name_.empty() && !skybox_texture()) throw UsageError("no cube map texture '" + args[0] + "' in the effect");
        } else if (a.verb == "tab") {
            static const std::set<std::string> tabs = {"Effect", "Scene", "Textures", "Pick", "View", "Plugins", "BRDF"};
            if (!tabs.count(args[0])) throw UsageError("no tab '" + args[0] + "' (Effect, Scene, Textures, Pick, View, Plugins, BRDF)");
            requested_tab_ = args[0];
            wait_frames_ = 1;
        } else if (a.verb == "brdf-check") {  // as the BRDF tab's Check button; prints the figures as JSON
            if (!session() || !app::has_brdf_grid(*session())) throw UsageError("brdf-check: the effect has no BRDF grid (open a .brdf file)");
            const app::BrdfCheck& c = brdf_panel_.check(*session());
            std::cout << nlohmann::json{{"brdf_check", {{"max_albedo", c.max_albedo}, {"conserves_energy", c.conserves_energy},
                                                        {"reciprocity_max_relative", c.reciprocity}, {"reciprocal", c.reciprocal},
                                                        {"negative_samples", c.negative},
                                                        {"non_finite_samples", c.non_finite}}}}
                             .dump()
                      << std::endl;
            requested_tab_ = "BRDF";
            wait_frames_ = 1;
        } else if (a.verb == "brdf-measured") {  // as the BRDF tab's Load measured
            brdf_panel_.load_measured(args[0]);
            std::cout << nlohmann::json{{"brdf_measured", args[0]}}.dump() << std::endl;
            requested_tab_ = "BRDF";
            wait_frames_ = 1;
        } else if (a.verb == "environment") {  // as the Scene tab's environment controls
            EnvironmentPanel::apply(view_.scene.environment, args[0], session());
        } else if (a.verb == "exposure") {
            display_settings_.exposure_ev = std::stof(args[0]);
        } else if (a.verb == "tone-map") {
            display_settings_.tone_map = image::parse_tone_map(args[0]);
        } else if (a.verb == "brdf-view") {  // as the BRDF tab's View combo
            static const std::map<std::string, BrdfPanel::View> views = {
                {"polar", BrdfPanel::View::Polar}, {"lobe", BrdfPanel::View::Lobe}, {"slice", BrdfPanel::View::Slice}, {"sphere", BrdfPanel::View::Sphere}};
            if (!views.count(args[0])) throw UsageError("brdf-view: polar, lobe, slice or sphere");
            if (!session() || !app::has_brdf_grid(*session())) throw UsageError("brdf-view: the effect has no BRDF grid (open a .brdf file)");
            std::cout << nlohmann::json{{"brdf_view", args[0]}, {"caption", brdf_panel_.show(views.at(args[0]), *session())}}.dump() << std::endl;
            requested_tab_ = "BRDF";
            wait_frames_ = 1;
        } else if (a.verb == "brdf-keep") {  // as the BRDF tab's Keep curve
            if (!session() || !app::has_brdf_grid(*session())) throw UsageError("brdf-keep: the effect has no BRDF grid (open a .brdf file)");
            brdf_panel_.keep_curve(*session());
            std::cout << nlohmann::json{{"brdf_kept_curves", brdf_panel_.kept_curves()}}.dump() << std::endl;
            requested_tab_ = "BRDF";
            wait_frames_ = 1;
        } else if (a.verb == "inspect-texture") {
            if (!session() || !session()->resources().find(args[0])) throw UsageError("inspect-texture: the effect has no texture '" + args[0] + "'");
            const char* channels[] = {"rgba", "r", "g", "b", "a"};
            int channel = 0;
            if (args.size() > 1) {
                channel = static_cast<int>(std::find(std::begin(channels), std::end(channels), args[1]) - std::begin(channels));
                if (channel == 5) throw UsageError("inspect-texture: channel rgba, r, g, b or a");
            }
            texture_panel_->inspect(args[0], channel, args.size() > 2 ? std::stof(args[2]) : 0.0f);
            requested_tab_ = "Textures";
            wait_frames_ = 1;
        } else if (a.verb == "open-error") {
            const std::vector<ErrorLocation>& errors = effect_.error_places();
            const int n = std::stoi(args[0]);
            if (n < 1 || n > static_cast<int>(errors.size()))
                throw UsageError("open-error " + args[0] + ": there are " + std::to_string(errors.size()) + " error places");
            status_ = open_in_editor(errors[static_cast<size_t>(n - 1)].file, errors[static_cast<size_t>(n - 1)].line);
        } else if (a.verb == "wait-effect") {
            // Waits, frame by frame, until an effect is loaded (e.g. a failed one was fixed on disk).
            const double limit = std::stod(args[0]);
            if (!session()) {
                if (wait_started_ == std::chrono::steady_clock::time_point{}) wait_started_ = std::chrono::steady_clock::now();
                if (std::chrono::duration<double>(std::chrono::steady_clock::now() - wait_started_).count() < limit) {
                    --script_position_;
                    wait_frames_ = 1;
                    return;
                }
                wait_started_ = {};
                throw Error("no effect loaded after " + args[0] + " s");
            }
            wait_started_ = {};
        } else if (a.verb == "plugin-start") {
            // Starts a plugin and goes on: the window keeps drawing while it runs (plugin-wait).
            if (!plugin_panel_.start(session(), args[0])) throw UsageError(plugin_panel_.error());
            plugin_start_frame_ = frame_number_;
            plugin_start_time_ = std::chrono::steady_clock::now();
        } else if (a.verb == "plugin-wait") {
            if (plugin_panel_.running()) {  // retried next frame; the frames drawn meanwhile are counted
                --script_position_;
                wait_frames_ = 1;
                return;
            }
            if (!plugin_panel_.result()) throw Error(plugin_panel_.last_plugin() + ": " + plugin_panel_.error());
            const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - plugin_start_time_).count();
            const int frames = frame_number_ - plugin_start_frame_;
            std::cout << nlohmann::json{{"plugin", {{"name", plugin_panel_.last_plugin()}, {"parameters", plugin_panel_.result()->parameters},
                                                       {"converged", plugin_panel_.result()->converged}}},
                                        {"frames_while_running", frames}, {"seconds", seconds}}
                             .dump()
                      << std::endl;
        } else if (a.verb == "plugin" || a.verb == "fit") {
            // plugin NAME: runs the effect's plugin as the Run button does, and waits for it.
            // fit FILE: the effect's first plugin on that data file (the Data file field).
            const std::string name = a.verb == "plugin" ? args[0] : "", file = a.verb == "fit" ? args[0] : "";
            if (!plugin_panel_.start(session(), name, file)) throw UsageError(plugin_panel_.error());
            plugin_panel_.wait(session());
            if (!plugin_panel_.result()) throw Error(plugin_panel_.last_plugin() + ": " + plugin_panel_.error());
            const plugin::Result& r = *plugin_panel_.result();
            for (auto& o : view_.objects) o.technique = session()->technique();
            std::cout << nlohmann::json{{"plugin", {{"name", plugin_panel_.last_plugin()}, {"parameters", r.parameters},
                                                       {"converged", r.converged}, {"warnings", r.warnings}}}}
                             .dump()
                      << std::endl;
        } else if (a.verb == "allow-path") {
            const bool had_effect = session() != nullptr;
            effect_.allow_folder(args[0]);
            if (!had_effect && session()) on_effect_opened();
        } else if (a.verb == "frames") {
            wait_frames_ = std::max(0, std::stoi(args[0]));
        }
    }

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
    std::vector<std::string> pending_window_shots_;
    FileBrowser file_browser_{FXVIEW_SOURCE_EFFECTS_DIR};
    char preset_input_[512] = "preset.json",
         shot_input_[512] = "out/screenshot.png", allow_input_[512] = "";
    EffectState effect_{options_.access};  // destroyed before the context (declared after it)
    std::vector<ScriptAction> script_;
    size_t script_position_ = 0;
    int wait_frames_ = 0;
    int awake_frames_ = 3;  // frames to draw before the loop may sleep (wait_or_poll_events)
};

}  // namespace

int run_viewer(const ViewerOptions& options) {
    Viewer viewer(options);
    return viewer.run();
}

}  // namespace fxview::ui

// The viewer's script verbs (`view --script`, docs/cli.md): a table from verb to a small handler,
// each doing what the matching button or key does. script.cpp checks the verbs' argument counts.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <chrono>
#include <iostream>
#include <map>
#include <set>

#include "app/brdf_evaluation.hpp"
#include "app/value_parsing.hpp"
#include "core/error.hpp"
#include "effect/parameter_values.hpp"
#include "math/arcball.hpp"
#include "scene/shapes.hpp"
#include "ui/error_list.hpp"
#include "ui/viewer_window.hpp"

namespace fxview::ui {
namespace {

// A whole number argument, or a UsageError naming the verb (std::stoi would accept "3x" and throw
// a bare "stoi" for "x").
int whole_number(const ScriptAction& action, const std::string& text) {
    int value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size())
        throw UsageError(action.verb + ": '" + text + "' is not a whole number");
    return value;
}

float number(const ScriptAction& action, const std::string& text) { return app::parse_floats(action.verb, text, 1)[0]; }

void require_brdf_grid(const render::EffectSession* session, const std::string& verb) {
    if (!session || !app::has_brdf_grid(*session)) throw UsageError(verb + ": the effect has no BRDF grid (open a .brdf file)");
}

}  // namespace

std::string Viewer::shown_technique() const {
    return view_.objects.empty() ? session()->technique() : view_.objects.front().technique;
}

void Viewer::run_script_step() {
    if (!picture_done()) return;  // actions see the picture their predecessors asked for
    if (awaited_key_ != 0) {
        if (std::chrono::steady_clock::now() < key_deadline_) return;
        std::cerr << "fxview: script: wait-key: no key " << awaited_key_name_ << " pressed in time\n";
        awaited_key_ = 0;
        exit_code_ = 1;
    }
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

void Viewer::perform(const ScriptAction& action) {
    using Handler = void (Viewer::*)(const ScriptAction&);
    static const std::map<std::string, Handler> handlers = {
        {"set", &Viewer::verb_set},
        {"technique", &Viewer::verb_technique},
        {"view", &Viewer::verb_view},
        {"mesh", &Viewer::verb_mesh},
        {"select", &Viewer::verb_select},
        {"rotate", &Viewer::verb_rotate},
        {"pick", &Viewer::verb_pick},
        {"screenshot", &Viewer::verb_screenshot},
        {"save-screenshot", &Viewer::verb_view_shot},
        {"render-screenshot", &Viewer::verb_view_shot},
        {"skybox", &Viewer::verb_skybox},
        {"tab", &Viewer::verb_tab},
        {"brdf-check", &Viewer::verb_brdf_check},
        {"brdf-measured", &Viewer::verb_brdf_measured},
        {"environment", &Viewer::verb_environment},
        {"light-spectrum", &Viewer::verb_light_spectrum},
        {"light-shape", &Viewer::verb_light_shape},
        {"light-intensity", &Viewer::verb_light_intensity},
        {"exposure", &Viewer::verb_exposure},
        {"tone-map", &Viewer::verb_tone_map},
        {"brdf-view", &Viewer::verb_brdf_view},
        {"brdf-keep", &Viewer::verb_brdf_keep},
        {"inspect-texture", &Viewer::verb_inspect_texture},
        {"inspect-texel", &Viewer::verb_inspect_texel},
        {"open-error", &Viewer::verb_open_error},
        {"wait-effect", &Viewer::verb_wait_effect},
        {"plugin-start", &Viewer::verb_plugin_start},
        {"plugin-wait", &Viewer::verb_plugin_wait},
        {"plugin", &Viewer::verb_plugin_run},
        {"fit", &Viewer::verb_plugin_run},
        {"allow-path", &Viewer::verb_allow_path},
        {"frames", &Viewer::verb_frames},
        {"window", &Viewer::verb_window},
        {"ui-state", &Viewer::verb_ui_state},
        {"wait-key", &Viewer::verb_wait_key},
    };
    const auto found = handlers.find(action.verb);
    if (found == handlers.end()) throw UsageError("unknown script action '" + action.verb + "'");
    (this->*found->second)(action);
}

void Viewer::verb_set(const ScriptAction& a) {
    if (!session()) throw UsageError("no effect loaded");
    effect::ParameterValues edited = session()->values();
    effect::set_value_from_text(session()->effect(), edited, a.arguments[0] + "=" + a.arguments[1]);
    effect::check_constraints(session()->effect(), edited);
    session()->values() = std::move(edited);
    if (!session()->values().textures.empty()) session()->reload_textures();
}

void Viewer::verb_technique(const ScriptAction& a) {
    if (!session()) throw UsageError("no effect loaded");
    session()->select_technique(a.arguments[0]);  // validates the name
    for (auto& o : view_.objects) o.technique = a.arguments[0];
}

void Viewer::verb_view(const ScriptAction& a) {
    for (auto& o : view_.objects) o.view = parse_view(a.arguments[0]);
}

void Viewer::verb_mesh(const ScriptAction& a) {
    scene::load_mesh(a.arguments[0]);
    view_.objects[static_cast<size_t>(view_.selected_object)].object.mesh = a.arguments[0];
}

void Viewer::verb_select(const ScriptAction& a) {
    const std::string& what = a.arguments[0];
    if (what == "camera") view_.selected = Target::Camera;
    else if (what == "light") view_.selected = Target::Light;
    else if (what == "object") {
        view_.selected = Target::Object;
        if (a.arguments.size() == 2)
            view_.selected_object = std::clamp(whole_number(a, a.arguments[1]), 0, static_cast<int>(view_.objects.size()) - 1);
    } else throw UsageError("select camera, light or object");
}

void Viewer::verb_rotate(const ScriptAction& a) {
    const std::string& what = a.arguments[0];
    if (what != "camera" && what != "light" && what != "object") throw UsageError("rotate camera, light or object");
    const glm::vec3 degrees{number(a, a.arguments[1]), number(a, a.arguments[2]), number(a, a.arguments[3])};
    const Target saved = view_.selected;
    view_.selected = what == "camera" ? Target::Camera : what == "light" ? Target::Light : Target::Object;
    view_.rotate_selected(math::rotation_from_euler_degrees(degrees));
    view_.selected = saved;
}

void Viewer::verb_pick(const ScriptAction& a) {
    const int x = whole_number(a, a.arguments[0]), y = whole_number(a, a.arguments[1]);
    if (retry_once_picture_is_current()) return;  // the picture the pick reads is rendered first, in pieces
    if (!pick_at(x, y)) throw UsageError("pick outside the render view");
    const auto& p = pick_.info();
    std::cout << nlohmann::json{{"x", p.x}, {"y", p.y}, {"width", target_->width()}, {"height", target_->height()},
                                {"rgba", p.rgba}, {"rgba8", p.rgba8}, {"packed", p.packed},
                                {"normal", {p.normal.x, p.normal.y, p.normal.z}}, {"xy", pick_.chromaticity()}}
                     .dump()
              << std::endl;
}

void Viewer::verb_screenshot(const ScriptAction& a) {
    pending_window_shots_.push_back(a.arguments[0]);
    wait_frames_ = 1;
}

// save-screenshot: as the Save screenshot button; render-screenshot: the picture as rendered.
void Viewer::verb_view_shot(const ScriptAction& a) {
    if (retry_once_picture_is_current()) return;  // the view's picture, once current
    if (a.verb == "save-screenshot") write_view_shot(a.arguments[0]);
    else write_render(a.arguments[0]);
}

void Viewer::verb_skybox(const ScriptAction& a) {
    skybox_name_ = a.arguments[0] == "off" ? "" : a.arguments[0];
    if (!skybox_name_.empty() && !skybox_texture()) throw UsageError("no cube map texture '" + a.arguments[0] + "' in the effect");
}

void Viewer::verb_tab(const ScriptAction& a) {
    if (std::none_of(std::begin(kTabNames), std::end(kTabNames), [&a](const char* name) { return a.arguments[0] == name; }))
        throw UsageError("no tab '" + a.arguments[0] + "' (Effect, Scene, Textures, Pick, View, Plugins, BRDF)");
    requested_tab_ = a.arguments[0];
    wait_frames_ = 1;
}

void Viewer::verb_brdf_check(const ScriptAction& a) {  // as the BRDF tab's Check button; prints the figures as JSON
    require_brdf_grid(session(), a.verb);
    if (!brdf_check_waiting_) {
        brdf_panel_.start_check(*session());
        brdf_check_waiting_ = true;
        brdf_check_start_frame_ = frame_number_;
    }
    if (brdf_panel_.checking()) {  // retried next frame: the check runs across frames
        --script_position_;
        wait_frames_ = 1;
        return;
    }
    brdf_check_waiting_ = false;
    if (!brdf_panel_.last_check()) throw Error("brdf-check: " + brdf_panel_.check_error());
    const app::BrdfCheck& c = *brdf_panel_.last_check();
    std::cout << nlohmann::json{{"brdf_check", {{"max_albedo", c.max_albedo}, {"conserves_energy", c.conserves_energy},
                                                {"energy", app::energy_verdict(c.energy)}, {"unresolved_reason", c.unresolved_reason},
                                                {"reciprocity_max_relative", c.reciprocity}, {"reciprocal", c.reciprocal},
                                                {"negative_samples", c.negative}, {"non_finite_samples", c.non_finite},
                                                {"file_sampling", c.file_sampling}, {"file_sampling_note", c.file_sampling_note}}},
                                {"frames_while_checking", frame_number_ - brdf_check_start_frame_}}
                     .dump()
              << std::endl;
    requested_tab_ = "BRDF";
    wait_frames_ = 1;
}

void Viewer::verb_brdf_measured(const ScriptAction& a) {  // as the BRDF tab's Load measured
    brdf_panel_.load_measured(a.arguments[0]);
    std::cout << nlohmann::json{{"brdf_measured", a.arguments[0]}}.dump() << std::endl;
    requested_tab_ = "BRDF";
    wait_frames_ = 1;
}

void Viewer::verb_environment(const ScriptAction& a) {  // as the Scene tab's environment controls
    EnvironmentPanel::apply(view_.scene.environment, a.arguments[0], session());
}

void Viewer::verb_light_spectrum(const ScriptAction& a) {  // as the Scene tab's light-spectrum combo
    const std::string name = a.arguments[0] == "none" ? "" : a.arguments[0];
    if (!name.empty() && session()) {
        scene::Scene probe = view_.scene;
        probe.light.spectrum = name;
        (void)session()->values_for(probe);  // an unknown name: UsageError naming the library, the light unchanged
    }
    view_.scene.light.spectrum = name;
}

void Viewer::verb_light_shape(const ScriptAction& a) {  // as the Scene tab's light shape and size
    const std::optional<scene::LightShape> shape = scene::parse_light_shape(a.arguments[0]);
    if (!shape) throw UsageError("light-shape: sphere R, disc R or rectangle W H");
    const bool rectangle = *shape == scene::LightShape::Rectangle;
    if (a.arguments.size() != (rectangle ? 3u : 2u)) throw UsageError(rectangle ? "light-shape rectangle W H" : "light-shape " + a.arguments[0] + " R");
    const float first = number(a, a.arguments[1]), second = rectangle ? number(a, a.arguments[2]) : 0.0f;
    if (!(first >= 0 && first <= 1e3f && second >= 0 && second <= 1e3f)) throw UsageError("light-shape: sizes from 0 to 1000 world units");
    view_.scene.light.shape = *shape;
    if (rectangle) view_.scene.light.size = glm::vec2(first, second);
    else view_.scene.light.radius = first;
}

void Viewer::verb_light_intensity(const ScriptAction& a) {  // as the Scene tab's light intensity
    if (a.arguments[0] == "none") {
        view_.scene.light.intensity.reset();
        return;
    }
    const std::optional<scene::LightIntensity> intensity = scene::parse_light_intensity(a.arguments[0]);
    if (!intensity) throw UsageError("light-intensity: a number with a unit, lx, lm, cd or nit (500lx), or none");
    scene::Light probe = view_.scene.light;
    (void)scene::illuminance_at_origin(probe, *intensity);  // a unit the light cannot have: refused, the light unchanged
    view_.scene.light.intensity = intensity;
}

void Viewer::verb_exposure(const ScriptAction& a) { display_settings_.exposure_ev = number(a, a.arguments[0]); }

void Viewer::verb_tone_map(const ScriptAction& a) { display_settings_.tone_map = image::parse_tone_map(a.arguments[0]); }

void Viewer::verb_brdf_view(const ScriptAction& a) {  // as the BRDF tab's View combo
    static const std::map<std::string, BrdfPanel::View> views = {
        {"polar", BrdfPanel::View::Polar}, {"lobe", BrdfPanel::View::Lobe}, {"slice", BrdfPanel::View::Slice}, {"sphere", BrdfPanel::View::Sphere}};
    if (!views.count(a.arguments[0])) throw UsageError("brdf-view: polar, lobe, slice or sphere");
    require_brdf_grid(session(), a.verb);
    std::cout << nlohmann::json{{"brdf_view", a.arguments[0]}, {"caption", brdf_panel_.show(views.at(a.arguments[0]), *session())}}.dump() << std::endl;
    requested_tab_ = "BRDF";
    wait_frames_ = 1;
}

void Viewer::verb_brdf_keep(const ScriptAction& a) {  // as the BRDF tab's Keep curve
    require_brdf_grid(session(), a.verb);
    brdf_panel_.keep_curve(*session());
    std::cout << nlohmann::json{{"brdf_kept_curves", brdf_panel_.kept_curves()}, {"labels", brdf_panel_.kept_labels()}}.dump() << std::endl;
    requested_tab_ = "BRDF";
    wait_frames_ = 1;
}

void Viewer::verb_inspect_texture(const ScriptAction& a) {
    const auto& args = a.arguments;
    if (!session() || !session()->resources().find(args[0])) throw UsageError("inspect-texture: the effect has no texture '" + args[0] + "'");
    const char* channels[] = {"rgba", "r", "g", "b", "a"};
    int channel = 0;
    if (args.size() > 1) {
        channel = static_cast<int>(std::find(std::begin(channels), std::end(channels), args[1]) - std::begin(channels));
        if (channel == 5) throw UsageError("inspect-texture: channel rgba, r, g, b or a");
    }
    texture_panel_->inspect(args[0], channel, args.size() > 2 ? number(a, args[2]) : 0.0f, args.size() > 3 ? whole_number(a, args[3]) : 0);
    requested_tab_ = "Textures";
    wait_frames_ = 2;  // the tab opens, then the inspector draws its preview
}

// inspect-texel X Y: the texel the inspector shows at (X, Y), fractions of its preview from the top
// left, as its tooltip gives it; prints JSON.
void Viewer::verb_inspect_texel(const ScriptAction& a) {
    const auto texel = texture_panel_->texel_at({number(a, a.arguments[0]), number(a, a.arguments[1])});
    if (!texel) throw UsageError("inspect-texel: no texture shown there (open the inspector with inspect-texture first)");
    std::cout << nlohmann::json{{"texel", {texel->x, texel->y}}, {"level", texel->level}, {"levels", texel->levels},
                                {"generated_levels", texel->generated_levels},
                                {"value", {texel->value.r, texel->value.g, texel->value.b, texel->value.a}}}
                     .dump()
              << std::endl;
}

void Viewer::verb_open_error(const ScriptAction& a) {
    const std::vector<ErrorLocation>& errors = effect_.error_places();
    const int n = whole_number(a, a.arguments[0]);
    if (n < 1 || n > static_cast<int>(errors.size()))
        throw UsageError("open-error " + a.arguments[0] + ": there are " + std::to_string(errors.size()) + " error places");
    status_ = open_in_editor(errors[static_cast<size_t>(n - 1)].file, errors[static_cast<size_t>(n - 1)].line);
}

// Waits, frame by frame, until an effect is loaded (e.g. a failed one was fixed on disk).
void Viewer::verb_wait_effect(const ScriptAction& a) {
    const double limit = number(a, a.arguments[0]);
    if (!session()) {
        if (wait_started_ == std::chrono::steady_clock::time_point{}) wait_started_ = std::chrono::steady_clock::now();
        if (std::chrono::duration<double>(std::chrono::steady_clock::now() - wait_started_).count() < limit) {
            --script_position_;
            wait_frames_ = 1;
            return;
        }
        wait_started_ = {};
        throw Error("no effect loaded after " + a.arguments[0] + " s");
    }
    wait_started_ = {};
}

// Starts a plugin and goes on: the window keeps drawing while it runs (plugin-wait).
void Viewer::verb_plugin_start(const ScriptAction& a) {
    if (!plugin_panel_.start(session(), a.arguments[0])) throw UsageError(plugin_panel_.error());
    follow_plugin_technique();
    plugin_start_frame_ = frame_number_;
    plugin_start_time_ = std::chrono::steady_clock::now();
}

void Viewer::verb_plugin_wait(const ScriptAction&) {
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
                                {"technique", shown_technique()},
                                {"frames_while_running", frames}, {"seconds", seconds}}
                     .dump()
              << std::endl;
}

// plugin NAME: runs the effect's plugin as the Run button does, and waits for it.
// fit FILE: the effect's first plugin on that data file (the Data file field).
void Viewer::verb_plugin_run(const ScriptAction& a) {
    const std::string name = a.verb == "plugin" ? a.arguments[0] : "", file = a.verb == "fit" ? a.arguments[0] : "";
    if (!plugin_panel_.start(session(), name, file)) throw UsageError(plugin_panel_.error());
    plugin_panel_.wait(session());
    if (!plugin_panel_.result()) throw Error(plugin_panel_.last_plugin() + ": " + plugin_panel_.error());
    const plugin::Result& r = *plugin_panel_.result();
    follow_plugin_technique();
    std::cout << nlohmann::json{{"plugin", {{"name", plugin_panel_.last_plugin()}, {"parameters", r.parameters},
                                            {"converged", r.converged}, {"warnings", r.warnings}}},
                                {"technique", shown_technique()}}
                     .dump()
              << std::endl;
}

void Viewer::verb_allow_path(const ScriptAction& a) {
    const bool had_effect = session() != nullptr;
    effect_.allow_folder(a.arguments[0]);
    if (!had_effect && session()) on_effect_opened();
}

void Viewer::verb_frames(const ScriptAction& a) { wait_frames_ = std::max(0, whole_number(a, a.arguments[0])); }

void Viewer::verb_window(const ScriptAction& a) {
    const int width = whole_number(a, a.arguments[0]), height = whole_number(a, a.arguments[1]);
    if (width < 200 || height < 150 || width > 16384 || height > 16384)
        throw UsageError("window: " + a.arguments[0] + "x" + a.arguments[1] + " is outside 200x150 to 16384x16384");
    glfwSetWindowSize(window_, width, height);
    wait_frames_ = 3;  // the window system's resize arrives as an event
}

void Viewer::verb_ui_state(const ScriptAction&) {
    int width = 0, height = 0;
    glfwGetWindowSize(window_, &width, &height);
    std::cout << nlohmann::json{{"window", {width, height}}, {"ui_scale", imgui_->scale()}, {"panel_width", panel_shown_width_},
                                {"panel_preferred_width", panel_width_.preferred()}, {"tab_bar_width", tab_bar_width_}, {"tabs_fit", tabs_fit_},
                                {"help", show_help_}, {"warnings", session() ? session()->warnings().size() : 0}}
                     .dump()
              << std::endl;
}

// `wait-key KEY [SECONDS]`: the script waits until the viewer has acted on a press of KEY (a letter,
// a digit, F1-F12, space or tab), at most SECONDS (default 30); then it goes on, with exit code 1
// when no press came.
void Viewer::verb_wait_key(const ScriptAction& a) {
    std::string name = a.arguments[0];
    std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    int key = 0;
    if (name.size() == 1 && std::isalnum(static_cast<unsigned char>(name[0])))
        key = std::isalpha(static_cast<unsigned char>(name[0])) ? GLFW_KEY_A + (name[0] - 'A') : GLFW_KEY_0 + (name[0] - '0');
    else if (name == "SPACE") key = GLFW_KEY_SPACE;
    else if (name == "TAB") key = GLFW_KEY_TAB;
    else if (name.size() >= 2 && name[0] == 'F' && name.find_first_not_of("0123456789", 1) == std::string::npos) {
        const int n = std::stoi(name.substr(1));
        if (n >= 1 && n <= 12) key = GLFW_KEY_F1 + n - 1;
    }
    if (key == 0) throw UsageError("wait-key: unknown key '" + a.arguments[0] + "' (a letter, a digit, F1-F12, space or tab)");
    const float seconds = a.arguments.size() > 1 ? number(a, a.arguments[1]) : 30.0f;
    if (!(seconds > 0 && seconds <= 3600)) throw UsageError("wait-key: the time is in seconds, 0 to 3600");
    awaited_key_ = key;
    awaited_key_name_ = a.arguments[0];
    key_deadline_ = std::chrono::steady_clock::now() + std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<float>(seconds));
}

}  // namespace fxview::ui

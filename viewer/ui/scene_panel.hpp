// The scene the viewer shows and how the user changes it: the camera, the light and the objects
// (each with its own technique or a built-in view), the Scene tab, the mouse on the render view
// (drag turns and moves what is selected, the wheel zooms, a click picks) and the light's gizmo.
#pragma once
#include <imgui.h>

#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "render/debug_renderer.hpp"
#include "scene/scene.hpp"
#include "ui/render_schedule.hpp"

namespace fxview::render {
class EffectSession;
}

namespace fxview::ui {

// What each object shows: the effect (with its own technique) or one of the built-in views.
enum class ViewMode { Effect, Plain, Normals, TexCoords, ToCamera, ToLight };
inline constexpr const char* kViewNames[] = {"effect", "plain", "normals", "uv", "camera", "light"};
ViewMode parse_view(const std::string& name);  // UsageError for an unknown name
render::DebugView debug_view(ViewMode mode);

struct ObjectState {
    scene::SceneObject object;
    std::string technique;
    ViewMode view = ViewMode::Effect;
    bool grouped = false;  // turned and moved with the selected object when it is grouped too
};

enum class Target { Camera, Light, Object };

struct ViewerScene {
    scene::Scene scene, initial;  // the camera, light and background now and at start (R resets)
    std::vector<ObjectState> objects;
    Target selected = Target::Object;  // what drags move
    int selected_object = 0;
    bool show_light = true;

    void rotate_selected(const glm::quat& view_rotation);
    void move_selected(const glm::vec3& view_move);  // in the view plane (right drag)
    void reset_selected();
    void reset_all();
    glm::vec3 beside_the_others(const glm::vec3& scale) const;  // where an added object goes
    void add_to(StateHash& hash) const;                         // everything a picture of it depends on
};

// The Scene tab. Added objects show `technique` (the effect's current one; empty without an effect);
// `light_warning` (EffectSession::unused_light_radius_warning) is noted under the light's radius.
void draw_scene_panel(ViewerScene& view, const std::string& technique, bool has_effect, const std::string& light_warning,
                      std::string& status);

// The light's spectrum (scene::Light::spectrum): "the effect's own" or a library name, listed from
// the effect's parameter that follows it; where the effect has none, a note that it changes nothing.
void draw_light_spectrum(scene::Light& light, const render::EffectSession* session);

// The light as a small sun where it projects into the render view; off screen (or behind the camera,
// or in its plane) a sun with an arrow on the view's edge, pointing to it.
void draw_light_gizmo(const ViewerScene& view, ImDrawList* list, ImVec2 origin, ImVec2 shown);

// The mouse on the render view (the last ImGui item, shown at `origin` with size `size`): a left drag
// turns the selected camera, light or object (arcball), a right drag moves it, the wheel zooms.
// Returns where a click without a drag happened, in 0..1 of the view (a pick).
class ViewMouse {
public:
    std::optional<glm::vec2> handle(ViewerScene& view, ImVec2 origin, ImVec2 size);
    bool dragging() const { return dragging_; }

private:
    bool dragging_ = false, moved_ = false;
    glm::vec2 last_{0.0f};
};

}  // namespace fxview::ui

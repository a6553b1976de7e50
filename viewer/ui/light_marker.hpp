// Where the render view shows the light: its projection when it is in front of the camera and inside
// the view, else a point on the view's edge in the light's direction (the default light sits in the
// camera's plane, so it never projects). No ImGui: scene_panel.cpp draws it, tests check it.
#pragma once
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.hpp"

namespace fxview::ui {

struct LightMarker {
    glm::vec2 at{0.0f};     // pixels from the view's top left
    bool on_screen = true;  // false: `at` is on the edge, `direction` points to the light
    bool behind = false;    // the light is behind the camera (not merely beside it, in its plane)
    glm::vec2 direction{0.0f};  // unit, screen axes (x right, y down)
};

// `margin`: how far inside the view's edge an off-screen marker is put, in pixels.
LightMarker light_marker(const scene::Camera& camera, glm::vec3 light_position, glm::vec2 view_size, float margin);

// The light's outline in the render view, in pixels from its top left: a flat light's disc or
// rectangle as the camera sees it, a sphere's silhouette (a circle about its centre, across the view
// direction); `facing` the end of a short arrow from its centre along a flat light's emitting normal.
// Empty where any of it is behind the camera, or the light is a point.
struct LightOutline {
    std::vector<glm::vec2> points;
    glm::vec2 centre{0.0f}, facing{0.0f};
    bool flat = false;
};
LightOutline light_outline(const scene::Camera& camera, const scene::Light& light, glm::vec2 view_size);

}  // namespace fxview::ui

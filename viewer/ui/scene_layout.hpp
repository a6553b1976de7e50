// Where the viewer puts an object the user adds: right of every other object, so that it never sits
// inside one (built-in meshes fit the unit sphere; an object's extent is that times its largest scale).
#pragma once
#include <algorithm>
#include <cmath>
#include <vector>

#include "scene/scene.hpp"

namespace fxview::ui {

inline float object_extent(const glm::vec3& scale) { return std::max({std::abs(scale.x), std::abs(scale.y), std::abs(scale.z)}); }

inline glm::vec3 place_beside(const std::vector<scene::SceneObject>& objects, const glm::vec3& scale, float gap = 0.25f) {
    if (objects.empty()) return glm::vec3(0.0f);
    float right = -1e30f;
    for (const auto& o : objects) right = std::max(right, o.pose.position.x + object_extent(o.scale));
    const glm::vec3& first = objects.front().pose.position;
    return glm::vec3(right + gap + object_extent(scale), first.y, first.z);
}

}  // namespace fxview::ui

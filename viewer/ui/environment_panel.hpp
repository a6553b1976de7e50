// The environment controls of the Scene tab: a built-in environment (studio, daylight sky, furnace) or
// an image file, its rotation and intensity. A new source is made at once on the effect's session:
// when it cannot be (a missing or malformed file) the message stays in the panel and the last good
// environment stays in the scene.
#pragma once
#include <string>

#include "render/effect_session.hpp"
#include "scene/scene.hpp"

namespace fxview::ui {

class EnvironmentPanel {
public:
    void draw(scene::Environment& environment, render::EffectSession* session);
    // Sets the source ("none" for none) after making its maps; throws Error naming it when it cannot
    // be made, leaving `environment` as it was (the script verb `environment`).
    static void apply(scene::Environment& environment, const std::string& source, render::EffectSession* session);

private:
    char file_[1024] = "";
    float sun_elevation_ = 35.0f, sun_cct_ = 5500.0f;
    bool sky_edited_ = false;
    std::string error_;
};

}  // namespace fxview::ui

// One frame of a RenderRequest into a float render target, read back exactly. With the glfw
// backend the frame is also shown in the window (blitted to its back buffer and swapped).
#pragma once
#include "app/scene_options.hpp"
#include "image/image.hpp"

namespace fxview::app {

image::FloatImage render_offscreen(const RenderRequest& request);

}  // namespace fxview::app

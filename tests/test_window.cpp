// Under xvfb-run: the glfw backend opens a real window with a 4.5 core context, renders frames
// offscreen, shows them in the window and reads the window's back buffer back.
#include <doctest/doctest.h>

#define GLFW_INCLUDE_NONE  // glad provides the GL declarations
#include <GLFW/glfw3.h>

#include "context/context.hpp"
#include "gl/render_target.hpp"
#include "render/debug_renderer.hpp"

using namespace fxview;

TEST_CASE("frames render into a GLFW window and read back non-empty") {
    context::ContextOptions options;
    options.backend = context::Backend::Glfw;
    options.window_width = 128;
    options.window_height = 96;
    const auto context = context::create_context(options);
    REQUIRE(context->window() != nullptr);
    int width = 0, height = 0;
    glfwGetFramebufferSize(context->window(), &width, &height);
    REQUIRE(width > 0);

    scene::Scene scene;
    gl::RenderTarget target({width, height, 1, 0});
    render::DebugRenderer renderer;
    std::vector<unsigned char> pixels(static_cast<size_t>(width) * height * 4);
    for (int frame = 0; frame < 5; ++frame) {
        scene.objects.front().pose.rotation = glm::angleAxis(0.2f * frame, glm::vec3(0, 1, 0));
        renderer.render(scene, render::DebugView::Normals, target);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glClearColor(0, 0, 0, 1);
        glClear(GL_COLOR_BUFFER_BIT);
        glBlitNamedFramebuffer(target.framebuffer(), 0, 0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT,
                               GL_NEAREST);
        if (frame == 4) {  // read the finished frame from the window's back buffer before showing it
            glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
            glReadBuffer(GL_BACK);
            glPixelStorei(GL_PACK_ALIGNMENT, 1);
            glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
        }
        context->swap_buffers();
        glfwPollEvents();
    }
    CHECK(glGetError() == GL_NO_ERROR);
    size_t lit = 0;
    for (size_t i = 0; i < pixels.size(); i += 4)
        if (pixels[i] + pixels[i + 1] + pixels[i + 2] > 0) ++lit;
    // The sphere covers roughly pi*(0.41*96)^2 ~ 4800 of 12288 pixels; demand a clear fraction.
    CHECK(lit > pixels.size() / 4 / 5);
    // The window's centre shows the facing normal colour (0.5, 0.5, 1.0) as 8 bits: 128, 128, 255.
    const unsigned char* centre = &pixels[(static_cast<size_t>(height / 2) * width + width / 2) * 4];
    CHECK(centre[2] > 240);
}

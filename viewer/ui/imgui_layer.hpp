// Dear ImGui on a GLFW window with the OpenGL 3 backend (compiled from libimgui-dev's shipped
// sources, drawing through our glad loader). Owns the ImGui context; one per window.
#pragma once

struct GLFWwindow;
struct ImGuiContext;

namespace fxview::ui {

class ImGuiLayer {
public:
    explicit ImGuiLayer(GLFWwindow* window);
    ~ImGuiLayer();
    ImGuiLayer(const ImGuiLayer&) = delete;
    ImGuiLayer& operator=(const ImGuiLayer&) = delete;

    void begin_frame();
    void end_frame();  // renders the UI into the current framebuffer

private:
    ImGuiContext* context_ = nullptr;
};

}  // namespace fxview::ui

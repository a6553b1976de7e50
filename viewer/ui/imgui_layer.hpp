// Dear ImGui on a GLFW window with the OpenGL 3 backend (compiled from libimgui-dev's shipped
// sources, drawing through our glad loader). Owns the ImGui context; one per window.
#pragma once
#include <utility>
#include <vector>

struct GLFWwindow;
struct ImGuiContext;

namespace fxview::ui {

class ImGuiLayer {
public:
    // `ui_scale` 0: the monitor's content scale (glfwGetWindowContentScale); else that factor. The
    // font is DejaVu Sans (Latin, Greek, arrows, mathematical operators) when it is installed, else
    // ImGui's built-in ASCII font (font_fallback() says so).
    explicit ImGuiLayer(GLFWwindow* window, float ui_scale = 0);
    ~ImGuiLayer();
    ImGuiLayer(const ImGuiLayer&) = delete;
    ImGuiLayer& operator=(const ImGuiLayer&) = delete;

    void begin_frame();
    void end_frame();  // renders the UI into the current framebuffer

    // The keys pressed since the last call (GLFW key codes, in order): taps shorter than a frame
    // included, which ImGui::IsKeyPressed misses.
    std::vector<int> take_key_presses() { return std::exchange(presses_, {}); }
    void record_press(int key) { presses_.push_back(key); }

    float scale() const { return scale_; }
    bool font_fallback() const { return font_fallback_; }

private:
    GLFWwindow* window_ = nullptr;
    ImGuiContext* context_ = nullptr;
    std::vector<int> presses_;
    float scale_ = 1;
    bool font_fallback_ = false;
};

}  // namespace fxview::ui

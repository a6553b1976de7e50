#include "ui/imgui_layer.hpp"

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <filesystem>

#include "core/error.hpp"

namespace fxview::ui {

namespace {

// Latin-1, Greek (κ, λ, θ in parameter names), general punctuation, super- and subscripts, arrows,
// mathematical operators.
const ImWchar kGlyphRanges[] = {0x0020, 0x00FF, 0x0370, 0x03FF, 0x2000, 0x206F, 0x2070, 0x209F, 0x2190, 0x21FF, 0x2200, 0x22FF, 0};

// Every key press, also those released before the next frame: Dear ImGui 1.86 (Debian 12) has no
// input queue, so it only sees keys still down when a frame starts. ImGui's own callback, installed
// after this one, calls it first.
void record_key_press(GLFWwindow* window, int key, int, int action, int) {
    if (action != GLFW_PRESS) return;
    if (auto* layer = static_cast<ImGuiLayer*>(glfwGetWindowUserPointer(window))) layer->record_press(key);
}

}  // namespace

ImGuiLayer::ImGuiLayer(GLFWwindow* window, float ui_scale) : window_(window) {
    IMGUI_CHECKVERSION();
    context_ = ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // the layout is ours: no imgui.ini appearing in the user's folder
    ImGui::StyleColorsDark();
    float content_x = 1, content_y = 1;
    glfwGetWindowContentScale(window, &content_x, &content_y);
    scale_ = ui_scale > 0 ? ui_scale : std::clamp(std::max(content_x, content_y), 0.5f, 4.0f);
    ImGui::GetStyle().ScaleAllSizes(scale_);
    std::error_code missing;
    if (std::filesystem::is_regular_file(FXVIEW_UI_FONT, missing) && io.Fonts->AddFontFromFileTTF(FXVIEW_UI_FONT, 15.0f * scale_, nullptr, kGlyphRanges)) {
        font_fallback_ = false;
    } else {
        ImFontConfig config;
        config.SizePixels = 13.0f * scale_;
        io.Fonts->AddFontDefault(&config);
        font_fallback_ = true;
    }
    glfwSetWindowUserPointer(window, this);
    glfwSetKeyCallback(window, record_key_press);
    if (!ImGui_ImplGlfw_InitForOpenGL(window, true) || !ImGui_ImplOpenGL3_Init("#version 450 core")) {
        ImGui::DestroyContext(context_);
        throw Error("viewer: cannot initialise Dear ImGui");
    }
}

ImGuiLayer::~ImGuiLayer() {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();  // puts record_key_press back
    glfwSetKeyCallback(window_, nullptr);
    glfwSetWindowUserPointer(window_, nullptr);
    ImGui::DestroyContext(context_);
}

void ImGuiLayer::begin_frame() {
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
}

void ImGuiLayer::end_frame() {
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

}  // namespace fxview::ui

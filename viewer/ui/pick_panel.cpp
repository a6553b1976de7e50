#include "ui/pick_panel.hpp"

#include <glad/gl.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "image/color_encoding.hpp"

namespace fxview::ui {
namespace {

ImU32 display_colour(const std::array<float, 4>& rgba, bool srgb) {
    const auto encode = [srgb](float v) {
        const float shown = srgb ? image::srgb_encode(v) : std::clamp(v, 0.0f, 1.0f);
        return static_cast<int>(std::lround(shown * 255.0f));
    };
    return IM_COL32(encode(rgba[0]), encode(rgba[1]), encode(rgba[2]), 255);
}

}  // namespace

std::array<double, 2> chromaticity_of(const std::array<float, 4>& rgb) {
    const double r = rgb[0], g = rgb[1], b = rgb[2];
    const double x = 0.412453 * r + 0.357580 * g + 0.180423 * b;
    const double y = 0.212671 * r + 0.715160 * g + 0.072169 * b;
    const double z = 0.019334 * r + 0.119193 * g + 0.950227 * b;
    const double sum = x + y + z;
    return sum > 0 ? std::array<double, 2>{x / sum, y / sum} : std::array<double, 2>{0.0, 0.0};
}

bool PickPanel::pick(const image::FloatImage& picture, int x, int y, bool srgb_display, std::uint64_t key) {
    if (x < 0 || y < 0 || x >= picture.width || y >= picture.height) return false;
    info_ = image::inspect_pixel(picture, x, y, srgb_display ? image::Encoding::Srgb : image::Encoding::Linear);
    xy_ = chromaticity_of(info_.rgba);
    srgb_ = srgb_display;
    key_ = key;
    neighbourhood_.clear();
    for (int dy = -kRadius; dy <= kRadius; ++dy)
        for (int dx = -kRadius; dx <= kRadius; ++dx) {
            const int px = x + dx, py = y + dy;
            std::array<float, 4> value{};
            if (px >= 0 && py >= 0 && px < picture.width && py < picture.height) {
                const size_t at = (static_cast<size_t>(py) * picture.width + px) * 4;
                value = {picture.data[at], picture.data[at + 1], picture.data[at + 2], picture.data[at + 3]};
            }
            neighbourhood_.push_back(value);
        }
    valid_ = true;
    return true;
}

void PickPanel::draw(std::uint64_t current_key) const {
    ImGui::TextWrapped("Click the render view (without dragging) to pick a pixel; hovering shows the value under the cursor.");
    if (!valid_) return;
    const auto& p = info_;
    if (current_key != key_) ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.3f, 1.0f), "The view changed since this pick: click to pick again.");
    ImGui::Text("pixel      %d, %d", p.x, p.y);
    ImGui::Text("float RGBA %.6g %.6g %.6g %.6g", p.rgba[0], p.rgba[1], p.rgba[2], p.rgba[3]);
    ImGui::Text("8-bit      %u %u %u %u (%s)", p.rgba8[0], p.rgba8[1], p.rgba8[2], p.rgba8[3], srgb_ ? "sRGB" : "linear");
    ImGui::Text("packed     %u (0x%08X)", p.packed, p.packed);
    ImGui::Text("normal     %.4f %.4f %.4f", p.normal.x, p.normal.y, p.normal.z);
    ImGui::Text("xy         %.4f %.4f", xy_[0], xy_[1]);
    // The magnifier: the snapshot's neighbourhood, the picked pixel outlined.
    const int side = 2 * kRadius + 1;
    const float cell = std::floor(ImGui::GetFontSize() * 0.8f);
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    ImDrawList* list = ImGui::GetWindowDrawList();
    for (int row = 0; row < side; ++row)
        for (int column = 0; column < side; ++column) {
            const ImVec2 a(origin.x + column * cell, origin.y + row * cell), b(a.x + cell, a.y + cell);
            list->AddRectFilled(a, b, display_colour(neighbourhood_[static_cast<size_t>(row * side + column)], srgb_));
        }
    const ImVec2 centre(origin.x + kRadius * cell, origin.y + kRadius * cell);
    list->AddRect(centre, ImVec2(centre.x + cell, centre.y + cell), IM_COL32(255, 255, 0, 255), 0.0f, 0, 2.0f);
    ImGui::Dummy(ImVec2(side * cell, side * cell));
    if (ImGui::IsItemHovered()) {
        const ImVec2 mouse = ImGui::GetIO().MousePos;
        const int column = static_cast<int>((mouse.x - origin.x) / cell), row = static_cast<int>((mouse.y - origin.y) / cell);
        if (column >= 0 && row >= 0 && column < side && row < side) {
            const auto& v = neighbourhood_[static_cast<size_t>(row * side + column)];
            ImGui::SetTooltip("pixel %d, %d\n%.6g %.6g %.6g %.6g", p.x + column - kRadius, p.y + row - kRadius, v[0], v[1], v[2], v[3]);
        }
    }
}

void PickPanel::draw_marker(ImDrawList* list, ImVec2 origin, ImVec2 shown, int width, int height) const {
    if (!valid_ || width <= 0 || height <= 0) return;
    const float x = origin.x + (info_.x + 0.5f) / width * shown.x, y = origin.y + (info_.y + 0.5f) / height * shown.y;
    const float r = std::max(8.0f, ImGui::GetFontSize() * 0.7f);
    // A cross with a gap at the pixel, dark under light, so that it shows on bright highlights and on
    // black alike.
    for (const auto& [colour, thickness] : {std::pair{IM_COL32(0, 0, 0, 220), 4.0f}, std::pair{IM_COL32(255, 255, 255, 255), 1.5f}}) {
        list->AddLine(ImVec2(x - r, y), ImVec2(x - 3, y), colour, thickness);
        list->AddLine(ImVec2(x + 3, y), ImVec2(x + r, y), colour, thickness);
        list->AddLine(ImVec2(x, y - r), ImVec2(x, y - 3), colour, thickness);
        list->AddLine(ImVec2(x, y + 3), ImVec2(x, y + r), colour, thickness);
    }
}

void PickPanel::draw_hover_readout(const gl::RenderTarget& target, ImVec2 origin, ImVec2 shown) {
    const ImVec2 mouse = ImGui::GetIO().MousePos;
    const int x = static_cast<int>((mouse.x - origin.x) / shown.x * target.width());
    const int y = static_cast<int>((mouse.y - origin.y) / shown.y * target.height());
    if (x < 0 || y < 0 || x >= target.width() || y >= target.height()) return;
    float value[4] = {};
    // The texture's rows run from the bottom.
    glGetTextureSubImage(target.color_texture(0), 0, x, target.height() - 1 - y, 0, 1, 1, 1, GL_RGBA, GL_FLOAT, sizeof value, value);
    char text[160];
    std::snprintf(text, sizeof text, "%d, %d: %.5g %.5g %.5g %.5g", x, y, value[0], value[1], value[2], value[3]);
    const ImVec2 size = ImGui::CalcTextSize(text);
    const ImVec2 at(origin.x + 4, origin.y + shown.y - size.y - 6);
    ImDrawList* list = ImGui::GetWindowDrawList();
    list->AddRectFilled(ImVec2(at.x - 3, at.y - 2), ImVec2(at.x + size.x + 3, at.y + size.y + 2), IM_COL32(0, 0, 0, 170));
    list->AddText(at, IM_COL32(255, 255, 255, 255), text);
}

}  // namespace fxview::ui

#include "ui/panel_width.hpp"

#include <algorithm>
#include <cmath>

namespace fxview::ui {

std::optional<float> PanelWidth::impose(float window_width) {
    imposed_ = window_width != window_width_;
    if (!imposed_) return std::nullopt;
    window_width_ = window_width;
    return std::min(preferred_, kMaxShare * window_width);
}

void PanelWidth::shown(float width) {
    // Half a pixel: ImGui keeps sizes in floats, an untouched edge reports the same width.
    if (!imposed_ && current_ >= 0 && std::abs(width - current_) > 0.5f) preferred_ = width;
    current_ = width;
    imposed_ = false;
}

}  // namespace fxview::ui

// The parameter panel's width: the user's (the width they dragged its edge to, first the width its
// widgets and tabs need) while the window has room for it; after the window shrinks, a share of the
// window, and the user's width again when it grows back. No ImGui: viewer_panels.cpp applies it,
// tests check it.
#pragma once
#include <optional>

namespace fxview::ui {

class PanelWidth {
public:
    // The most of the window a panel takes by itself (a user may drag it wider).
    static constexpr float kMaxShare = 0.55f;

    bool has_preferred() const { return preferred_ > 0; }
    void prefer(float width) { preferred_ = width; }
    float preferred() const { return preferred_; }

    // Before the panel is drawn: the width to give it this frame, or nothing to keep its own (the
    // user may be dragging its edge). A width is given when the window's width changed (and on the
    // first frame).
    std::optional<float> impose(float window_width);
    // After: the width the panel has. A change on a frame without an imposed width is the user's
    // drag, which becomes the preferred width.
    void shown(float width);

private:
    float preferred_ = 0, window_width_ = -1, current_ = -1;
    bool imposed_ = false;
};

}  // namespace fxview::ui

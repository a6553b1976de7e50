#include "x_input.hpp"

#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <X11/extensions/XTest.h>

#include <chrono>
#include <thread>

namespace fxview::test {
namespace {

// The mapped window titled `title` among the root's children (no window manager under Xvfb: the
// application's window is a direct child), or 0.
Window find_window(Display* display, const std::string& title) {
    Window root = DefaultRootWindow(display), parent = 0, *children = nullptr, found = 0;
    unsigned count = 0;
    if (!XQueryTree(display, root, &root, &parent, &children, &count)) return 0;
    for (unsigned i = 0; i < count && !found; ++i) {
        char* name = nullptr;
        XWindowAttributes attributes;
        if (XFetchName(display, children[i], &name) && name && title == name && XGetWindowAttributes(display, children[i], &attributes) &&
            attributes.map_state == IsViewable)
            found = children[i];
        if (name) XFree(name);
    }
    if (children) XFree(children);
    return found;
}

}  // namespace

bool tap_key_in_window(const std::string& title, const std::string& keysym, double seconds) {
    Display* display = XOpenDisplay(nullptr);
    if (!display) return false;
    int event_base = 0, error_base = 0, major = 0, minor = 0;
    bool tapped = false;
    if (XTestQueryExtension(display, &event_base, &error_base, &major, &minor)) {
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
        Window window = 0;
        while (!(window = find_window(display, title)) && std::chrono::steady_clock::now() < deadline)
            std::this_thread::sleep_for(std::chrono::milliseconds(100));
        const KeyCode code = XKeysymToKeycode(display, XStringToKeysym(keysym.c_str()));
        if (window && code) {
            std::this_thread::sleep_for(std::chrono::milliseconds(500));  // the viewer's first frames
            XWindowAttributes attributes;
            XGetWindowAttributes(display, window, &attributes);
            // The pointer over the window's right part (the render view, not a text field), the focus on it.
            XTestFakeMotionEvent(display, -1, attributes.x + attributes.width * 3 / 4, attributes.y + attributes.height / 2, 0);
            XSetInputFocus(display, window, RevertToPointerRoot, CurrentTime);
            XTestFakeKeyEvent(display, code, True, 0);
            XTestFakeKeyEvent(display, code, False, 0);
            XFlush(display);
            XSync(display, False);
            tapped = true;
        }
    }
    XCloseDisplay(display);
    return tapped;
}

}  // namespace fxview::test

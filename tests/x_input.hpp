// Real keyboard input for the viewer tests: XTest events on the X display the viewer runs on
// (xvfb-run's), as a user's keyboard would send them. Kept out of the test files: Xlib's macros
// (None, Bool, Status) clash with everything else.
#pragma once
#include <string>

namespace fxview::test {

// Waits up to `seconds` for a mapped top-level window titled `title` on $DISPLAY, then presses and
// releases the key `keysym` (an X keysym name: "h", "F1") over it at once, the release sent with
// the press: a tap shorter than any frame. False when there is no display or no such window.
bool tap_key_in_window(const std::string& title, const std::string& keysym, double seconds);

}  // namespace fxview::test

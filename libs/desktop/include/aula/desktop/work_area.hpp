#pragma once
// The part of the screen windows may use: the window manager's _NET_WORKAREA (the screen less its
// panels), else the whole screen, from the X server named by DISPLAY. libX11 is opened here, only
// when asked (dlopen), so a headless process never loads it.

#include <aula/desktop/window_layout.hpp>

#include <optional>

namespace aula::desktop {

// nullopt when there is no X display (DISPLAY unset, a Wayland session without XWayland, no libX11).
std::optional<Rect> workArea();

}  // namespace aula::desktop

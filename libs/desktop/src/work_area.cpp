#include "aula/desktop/work_area.hpp"

#include <X11/Xatom.h>
#include <X11/Xlib.h>

#include <dlfcn.h>

#include <cstdlib>

namespace aula::desktop {
namespace {

// The few calls of libX11 this needs, opened at run time (the header gives only the types).
struct Xlib {
  void* library = dlopen("libX11.so.6", RTLD_LAZY | RTLD_LOCAL);
  template <class F>
  F get(const char* name) const {
    return library == nullptr ? nullptr : reinterpret_cast<F>(dlsym(library, name));
  }
  decltype(&XOpenDisplay) open = get<decltype(&XOpenDisplay)>("XOpenDisplay");
  decltype(&XCloseDisplay) close = get<decltype(&XCloseDisplay)>("XCloseDisplay");
  decltype(&XInternAtom) atom = get<decltype(&XInternAtom)>("XInternAtom");
  decltype(&XGetWindowProperty) property = get<decltype(&XGetWindowProperty)>("XGetWindowProperty");
  decltype(&XFree) free = get<decltype(&XFree)>("XFree");
  decltype(&XDefaultScreen) screen = get<decltype(&XDefaultScreen)>("XDefaultScreen");
  decltype(&XRootWindow) root = get<decltype(&XRootWindow)>("XRootWindow");
  decltype(&XDisplayWidth) width = get<decltype(&XDisplayWidth)>("XDisplayWidth");
  decltype(&XDisplayHeight) height = get<decltype(&XDisplayHeight)>("XDisplayHeight");

  Xlib() = default;
  Xlib(const Xlib&) = delete;
  Xlib& operator=(const Xlib&) = delete;
  ~Xlib() {
    if (library != nullptr) dlclose(library);
  }
  bool usable() const {
    return open && close && atom && property && free && screen && root && width && height;
  }
};

// The root window's CARDINAL list `name` (empty when the window manager does not set it).
std::vector<long> cardinals(const Xlib& x, Display* display, Window root, const char* name) {
  Atom type = None;
  int format = 0;
  unsigned long count = 0, after = 0;
  unsigned char* data = nullptr;
  std::vector<long> out;
  const Atom property = x.atom(display, name, True);  // None without a window manager that sets it
  if (property == None) return out;
  if (x.property(display, root, property, 0, 1024, False, XA_CARDINAL, &type, &format, &count,
                 &after, &data) == Success &&
      data != nullptr && format == 32) {
    const auto* items = reinterpret_cast<const long*>(data);  // Xlib hands format 32 over as longs
    out.assign(items, items + count);
  }
  if (data != nullptr) x.free(data);
  return out;
}

}  // namespace

std::optional<Rect> workArea() {
  const char* name = std::getenv("DISPLAY");
  if (name == nullptr || *name == '\0') return std::nullopt;
  const Xlib x;
  if (!x.usable()) return std::nullopt;
  Display* display = x.open(name);
  if (display == nullptr) return std::nullopt;
  const int screen = x.screen(display);
  const Window root = x.root(display, screen);
  Rect area{0, 0, x.width(display, screen), x.height(display, screen)};
  // _NET_WORKAREA: x, y, width, height per desktop; the current desktop's.
  const auto work = cardinals(x, display, root, "_NET_WORKAREA");
  const auto current = cardinals(x, display, root, "_NET_CURRENT_DESKTOP");
  const size_t desktop = current.empty() ? 0 : static_cast<size_t>(current[0]);
  if (work.size() >= 4 * (desktop + 1) && work[4 * desktop + 2] > 0 && work[4 * desktop + 3] > 0) {
    area = {static_cast<int>(work[4 * desktop]), static_cast<int>(work[4 * desktop + 1]),
            static_cast<int>(work[4 * desktop + 2]), static_cast<int>(work[4 * desktop + 3])};
  }
  x.close(display);
  return area;
}

}  // namespace aula::desktop

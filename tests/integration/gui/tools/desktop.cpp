// aula-test-desktop windows | grab FILE.png: what a window manager shows, for the GUI tests.
//   windows    one line per managed window (the WM's _NET_CLIENT_LIST, mapped only):
//              FRAME_X FRAME_Y FRAME_W FRAME_H CLIENT_W CLIENT_H TITLE
//              the frame is the window with the WM's decorations (_NET_FRAME_EXTENTS), in root
//              coordinates; the client is the program's own area. Exit 1 without a WM.
//   grab FILE  the whole screen as a PNG.
#include <aula/image/png.hpp>

#include <X11/Xatom.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace {

// A window's CARDINAL or WINDOW list property (empty when absent).
std::vector<unsigned long> listProperty(Display* display, Window window, const char* name, Atom type) {
  Atom actual = None;
  int format = 0;
  unsigned long count = 0, after = 0;
  unsigned char* data = nullptr;
  std::vector<unsigned long> out;
  if (XGetWindowProperty(display, window, XInternAtom(display, name, False), 0, 4096, False, type, &actual, &format,
                         &count, &after, &data) == Success &&
      data != nullptr && format == 32) {
    const auto* items = reinterpret_cast<const unsigned long*>(data);  // Xlib gives format 32 as longs
    out.assign(items, items + count);
  }
  if (data != nullptr) XFree(data);
  return out;
}

std::string titleOf(Display* display, Window window) {
  Atom actual = None;
  int format = 0;
  unsigned long count = 0, after = 0;
  unsigned char* data = nullptr;
  std::string title;
  if (XGetWindowProperty(display, window, XInternAtom(display, "_NET_WM_NAME", False), 0, 1024, False,
                         XInternAtom(display, "UTF8_STRING", False), &actual, &format, &count, &after, &data) == Success &&
      data != nullptr) {
    title.assign(reinterpret_cast<const char*>(data), count);
  }
  if (data != nullptr) XFree(data);
  char* name = nullptr;
  if (title.empty() && XFetchName(display, window, &name) && name != nullptr) title = name;
  if (name != nullptr) XFree(name);
  return title;
}

int listWindows(Display* display) {
  const Window root = DefaultRootWindow(display);
  const auto clients = listProperty(display, root, "_NET_CLIENT_LIST", XA_WINDOW);
  if (clients.empty() && listProperty(display, root, "_NET_SUPPORTING_WM_CHECK", XA_WINDOW).empty()) {
    std::fprintf(stderr, "aula-test-desktop: no window manager (no _NET_SUPPORTING_WM_CHECK)\n");
    return 1;
  }
  for (unsigned long id : clients) {
    const Window window = static_cast<Window>(id);
    XWindowAttributes attributes{};
    if (!XGetWindowAttributes(display, window, &attributes) || attributes.map_state != IsViewable) continue;
    int x = 0, y = 0;
    Window child = 0;
    XTranslateCoordinates(display, window, root, 0, 0, &x, &y, &child);
    auto extents = listProperty(display, window, "_NET_FRAME_EXTENTS", XA_CARDINAL);  // left, right, top, bottom
    if (extents.size() != 4) extents = {0, 0, 0, 0};
    const long left = static_cast<long>(extents[0]), right = static_cast<long>(extents[1]);
    const long top = static_cast<long>(extents[2]), bottom = static_cast<long>(extents[3]);
    std::printf("%ld %ld %ld %ld %d %d %s\n", x - left, y - top, attributes.width + left + right,
                attributes.height + top + bottom, attributes.width, attributes.height, titleOf(display, window).c_str());
  }
  return 0;
}

int grab(Display* display, const std::string& path) {
  const Window root = DefaultRootWindow(display);
  XWindowAttributes attributes{};
  XGetWindowAttributes(display, root, &attributes);
  XImage* image = XGetImage(display, root, 0, 0, attributes.width, attributes.height, AllPlanes, ZPixmap);
  if (image == nullptr) {
    std::fprintf(stderr, "aula-test-desktop: cannot read the screen\n");
    return 1;
  }
  cv::Mat bgr(attributes.height, attributes.width, CV_8UC3);
  auto channel = [](unsigned long pixel, unsigned long mask) {
    int shift = 0;
    while (mask != 0 && (mask & 1) == 0) {
      mask >>= 1;
      ++shift;
    }
    return static_cast<uint8_t>(((pixel >> shift) & mask) * 255 / (mask == 0 ? 1 : mask));
  };
  for (int y = 0; y < attributes.height; ++y) {
    for (int x = 0; x < attributes.width; ++x) {
      const unsigned long pixel = XGetPixel(image, x, y);
      bgr.at<cv::Vec3b>(y, x) = {channel(pixel, image->blue_mask), channel(pixel, image->green_mask),
                                 channel(pixel, image->red_mask)};
    }
  }
  XDestroyImage(image);
  if (!aula::image::writePng(path, bgr)) {
    std::fprintf(stderr, "aula-test-desktop: cannot write %s\n", path.c_str());
    return 1;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const bool list = argc == 2 && std::strcmp(argv[1], "windows") == 0;
  if (!list && !(argc == 3 && std::strcmp(argv[1], "grab") == 0)) {
    std::fprintf(stderr, "usage: aula-test-desktop windows | grab FILE.png\n");
    return 2;
  }
  Display* display = XOpenDisplay(nullptr);
  if (display == nullptr) {
    std::fprintf(stderr, "aula-test-desktop: no display\n");
    return 1;
  }
  const int code = list ? listWindows(display) : grab(display, argv[2]);
  XCloseDisplay(display);
  return code;
}

// The window platform (built when libx11 is found, see ui/CMakeLists.txt).
#include <chrono>
#include <cstdlib>

#include "core/common/error.h"
#include "ui/platform/egl_context.h"
#include "ui/platform/framebuffer.h"
#include "ui/tablet_app.h"
#include "ui/touch_input.h"
#include "ui/window_runner.h"

// Last: Xlib defines macros (None, Success, Status) that clash with Eigen.
#include <X11/Xlib.h>
#include <X11/Xutil.h>

namespace rockface::ui {

namespace {

// A 10" tablet's screen; the window manager may make it full screen.
constexpr int kDefaultWidth = 1280, kDefaultHeight = 800;

struct X11Window {
  Display* display = nullptr;
  Window window = 0;
  Atom wm_delete = 0;
  ~X11Window() {
    if (window) XDestroyWindow(display, window);
    if (display) XCloseDisplay(display);
  }
};

}  // namespace

void run_in_window(const UiOptions& options, const FieldServices& services) {
  const char* name = std::getenv("DISPLAY");
  X11Window x;
  x.display = name ? XOpenDisplay(name) : nullptr;
  if (!x.display)
    throw Error(std::string("no display to show the UI on (DISPLAY ") +
                (name ? std::string("is ") + name + " but cannot be opened)" : "is not set)") +
                "; run it headless: rockface ui --headless --script STEPS.json --screenshots DIR");
  const int screen = DefaultScreen(x.display);
  x.window = XCreateSimpleWindow(x.display, RootWindow(x.display, screen), 0, 0, kDefaultWidth,
                                 kDefaultHeight, 0, BlackPixel(x.display, screen),
                                 WhitePixel(x.display, screen));
  XStoreName(x.display, x.window, "rockface");
  XSelectInput(
      x.display, x.window,
      ButtonPressMask | ButtonReleaseMask | PointerMotionMask | StructureNotifyMask | KeyPressMask);
  x.wm_delete = XInternAtom(x.display, "WM_DELETE_WINDOW", False);
  XSetWMProtocols(x.display, x.window, &x.wm_delete, 1);
  XMapWindow(x.display, x.window);

  EglContext egl = EglContext::on_x11_window(x.display, x.window);
  TabletApp app(options, services);
  TouchInput input;
  int width = kDefaultWidth, height = kDefaultHeight;
  auto last = std::chrono::steady_clock::now();
  for (bool open = true; open;) {
    while (XPending(x.display)) {
      XEvent e;
      XNextEvent(x.display, &e);
      switch (e.type) {
        case ButtonPress:
          if (e.xbutton.button == Button1)
            input.push({TouchEvent::Kind::down, 0, float(e.xbutton.x), float(e.xbutton.y)});
          else if (e.xbutton.button == Button4)
            input.push_wheel(1);
          else if (e.xbutton.button == Button5)
            input.push_wheel(-1);
          break;
        case ButtonRelease:
          if (e.xbutton.button == Button1)
            input.push({TouchEvent::Kind::up, 0, float(e.xbutton.x), float(e.xbutton.y)});
          break;
        case MotionNotify:
          input.push({TouchEvent::Kind::move, 0, float(e.xmotion.x), float(e.xmotion.y)});
          break;
        case ConfigureNotify:
          width = e.xconfigure.width;
          height = e.xconfigure.height;
          break;
        case ClientMessage:
          if (static_cast<Atom>(e.xclient.data.l[0]) == x.wm_delete) open = false;
          break;
        default:
          break;
      }
    }
    const auto now = std::chrono::steady_clock::now();
    const float dt = std::chrono::duration<float>(now - last).count();
    last = now;
    app.build_frame(input, width, height, dt);
    Framebuffer::unbind();
    app.draw();
    egl.swap_buffers();  // paced by the display (swap interval 1)
  }
}

}  // namespace rockface::ui

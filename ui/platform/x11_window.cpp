// The window platform (built when libx11 is found, see ui/CMakeLists.txt).
#include <chrono>
#include <cstdlib>
#include <memory>

#include "core/common/error.h"
#include "ui/app/tablet_app.h"
#include "ui/platform/egl_context.h"
#include "ui/platform/frame_pacer.h"
#include "ui/platform/framebuffer.h"
#include "ui/platform/window_runner.h"

// Last: Xlib defines macros (None, Success, Status) that clash with Eigen.
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <X11/extensions/XInput2.h>

namespace rockface::ui {

namespace {

// A 10" tablet's screen; the window manager may make it full screen.
constexpr int kDefaultWidth = 1280, kDefaultHeight = 800;

struct X11Window {
  Display* display = nullptr;
  Window window = 0;
  Atom wm_delete = 0;
  int xi_opcode = -1;
  bool touch = false;  // XInput 2.2 touch events selected

  X11Window(int width, int height) {
    const char* name = std::getenv("DISPLAY");
    display = name ? XOpenDisplay(name) : nullptr;
    if (!display)
      throw Error(
          std::string("no display to show the UI on (DISPLAY ") +
          (name ? std::string("is ") + name + " but cannot be opened)" : "is not set)") +
          "; run it headless: rockface ui --headless --script STEPS.json --screenshots DIR");
    const int screen = DefaultScreen(display);
    window = XCreateSimpleWindow(display, RootWindow(display, screen), 0, 0, width, height, 0,
                                 BlackPixel(display, screen), WhitePixel(display, screen));
    XStoreName(display, window, "rockface");
    XSelectInput(display, window,
                 ButtonPressMask | ButtonReleaseMask | PointerMotionMask | StructureNotifyMask |
                     ExposureMask);
    wm_delete = XInternAtom(display, "WM_DELETE_WINDOW", False);
    XSetWMProtocols(display, window, &wm_delete, 1);
    select_touch();
    XMapWindow(display, window);
  }

  // Multi-touch through XInput 2.2 where the server has it (the tablet's
  // touch screen): every finger is its own touch sequence. Without it the
  // server still emulates the pointer from the first finger.
  void select_touch() {
    int event = 0, error = 0;
    if (!XQueryExtension(display, "XInputExtension", &xi_opcode, &event, &error)) return;
    int major = 2, minor = 2;
    if (XIQueryVersion(display, &major, &minor) != 0 || major * 100 + minor < 202) return;
    unsigned char bits[XIMaskLen(XI_LASTEVENT)] = {};
    XISetMask(bits, XI_TouchBegin);
    XISetMask(bits, XI_TouchUpdate);
    XISetMask(bits, XI_TouchEnd);
    XIEventMask mask{XIAllMasterDevices, static_cast<int>(sizeof bits), bits};
    touch = XISelectEvents(display, window, &mask, 1) == 0;
  }
  // The screen's pixels per inch from its size in millimetres (what the X
  // server knows of the panel); 0 when it does not say.
  float dpi() const {
    const int screen = DefaultScreen(display);
    const int mm = DisplayWidthMM(display, screen);
    return mm > 0 ? DisplayWidth(display, screen) * 25.4f / mm : 0;
  }
  X11Window(const X11Window&) = delete;
  X11Window& operator=(const X11Window&) = delete;
  ~X11Window() {
    XDestroyWindow(display, window);
    XCloseDisplay(display);
  }
};

// Frames go into a framebuffer of the window's size and are copied to the
// window, so that a screenshot reads what was shown.
// Touch targets of 9 mm need the screen's density: the window's, unless
// --dpi gave one.
UiOptions with_screen_dpi(UiOptions options, const X11Window& x) {
  if (options.dpi <= 0) options.dpi = x.dpi();
  return options;
}

class WindowSession final : public UiDriver {
 public:
  WindowSession(const UiOptions& options, const FieldServices& services, int width, int height)
      : x_(width, height),
        egl_(EglContext::on_x11_window(x_.display, x_.window)),
        target_(std::make_unique<Framebuffer>(width, height)),
        app_(std::make_unique<TabletApp>(with_screen_dpi(options, x_), services)),
        width_(width),
        height_(height),
        last_(std::chrono::steady_clock::now()) {}
  ~WindowSession() override { app_.reset(); }  // before the GL context goes

  bool open() const { return open_; }

  void frame() override {
    pump_events();
    if (target_->width() != width_ || target_->height() != height_) {
      target_ = std::make_unique<Framebuffer>(width_, height_);
      app_->draw_again();
    }
    const auto now = std::chrono::steady_clock::now();
    const float dt = std::chrono::duration<float>(now - last_).count();
    last_ = now;
    app_->build_frame(input_, width_, height_, dt);
    target_->bind();
    // A frame that draws what the window shows is not drawn or swapped:
    // the window keeps showing it (issue 45).
    if (!app_->draw()) return;
    target_->blit_to_window();
    egl_.swap_buffers();  // paced by the display (swap interval 1)
  }
  cv::Mat screenshot() const override { return target_->read_bgr(); }
  AppState& state() override { return app_->state(); }

 private:
  void pump_events() {
    while (XPending(x_.display)) {
      XEvent e;
      XNextEvent(x_.display, &e);
      if (x_.touch && e.type == GenericEvent && e.xcookie.extension == x_.xi_opcode) {
        touch_event(e);
        continue;
      }
      const auto x = static_cast<float>(e.xbutton.x), y = static_cast<float>(e.xbutton.y);
      switch (e.type) {
        case ButtonPress:
          if (e.xbutton.button == Button1) input_.push({TouchEvent::Kind::down, 0, x, y});
          if (e.xbutton.button == Button4) input_.push_wheel(1);
          if (e.xbutton.button == Button5) input_.push_wheel(-1);
          break;
        case ButtonRelease:
          if (e.xbutton.button == Button1) input_.push({TouchEvent::Kind::up, 0, x, y});
          break;
        case MotionNotify:
          input_.push({TouchEvent::Kind::move, 0, static_cast<float>(e.xmotion.x),
                       static_cast<float>(e.xmotion.y)});
          break;
        case ConfigureNotify:
          width_ = e.xconfigure.width;
          height_ = e.xconfigure.height;
          break;
        case Expose:  // uncovered: what it showed is gone, draw it again
          app_->draw_again();
          break;
        case ClientMessage:
          if (static_cast<Atom>(e.xclient.data.l[0]) == x_.wm_delete) open_ = false;
          break;
        default:
          break;
      }
    }
  }

  void touch_event(XEvent& e) {
    if (!XGetEventData(x_.display, &e.xcookie)) return;
    const auto* d = static_cast<const XIDeviceEvent*>(e.xcookie.data);
    const auto x = static_cast<float>(d->event_x), y = static_cast<float>(d->event_y);
    const int finger = d->detail;  // the touch id, the same from begin to end
    switch (e.xcookie.evtype) {
      case XI_TouchBegin:
        input_.push({TouchEvent::Kind::down, finger, x, y});
        break;
      case XI_TouchUpdate:
        input_.push({TouchEvent::Kind::move, finger, x, y});
        break;
      case XI_TouchEnd:
        input_.push({TouchEvent::Kind::up, finger, x, y});
        break;
      default:
        break;
    }
    XFreeEventData(x_.display, &e.xcookie);
  }

  X11Window x_;
  EglContext egl_;
  std::unique_ptr<Framebuffer> target_;
  std::unique_ptr<TabletApp> app_;
  int width_, height_;
  bool open_ = true;
  std::chrono::steady_clock::time_point last_;
};

}  // namespace

void run_in_window(const UiOptions& options, const FieldServices& services) {
  WindowSession session(options, services, kDefaultWidth, kDefaultHeight);
  FramePacer pacer;
  while (session.open()) {
    session.frame();
    pacer.wait();
  }
}

ScriptRun run_script_in_window(const UiOptions& options, const FieldServices& services,
                               const UiScript& script,
                               const std::filesystem::path& screenshots_dir) {
  WindowSession session(options, services, script.width, script.height);
  return run_ui_script(session, script, screenshots_dir);
}

}  // namespace rockface::ui

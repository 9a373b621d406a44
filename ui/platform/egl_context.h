#pragma once
// One EGL display with a GLES 3 context, current on the thread that made it.
//
// Two kinds: on a window (the tablet's screen, through the native display
// the window belongs to), and surfaceless (Mesa's EGL_MESA_platform_surfaceless,
// used for headless runs and tests with the software renderer: nothing is
// shown, frames go into a framebuffer object, see OffscreenTarget).
#include <cstdint>
#include <string>

namespace rockface::ui {

class EglContext {
 public:
  // Throws rockface::Error saying which EGL step failed and why.
  static EglContext surfaceless();
  // native_display: an X11 Display*; native_window: its Window id.
  static EglContext on_x11_window(void* native_display, std::uintptr_t native_window);

  EglContext(EglContext&& other) noexcept;
  EglContext& operator=(EglContext&& other) noexcept;
  EglContext(const EglContext&) = delete;
  EglContext& operator=(const EglContext&) = delete;
  ~EglContext();

  bool has_window() const { return surface_ != nullptr; }
  // Shows the frame drawn into the window (no-op when surfaceless).
  void swap_buffers();
  // GL_RENDERER and GL_VERSION, e.g. "llvmpipe (LLVM 15.0.6, 256 bits), OpenGL ES 3.2 Mesa".
  std::string describe() const;

 private:
  EglContext() = default;
  void release();

  void* display_ = nullptr;  // EGLDisplay
  void* context_ = nullptr;  // EGLContext
  void* surface_ = nullptr;  // EGLSurface, null when surfaceless
};

}  // namespace rockface::ui

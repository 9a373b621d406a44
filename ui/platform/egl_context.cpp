#include "ui/platform/egl_context.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GLES3/gl3.h>

#include <utility>

#include "core/common/error.h"

namespace rockface::ui {
namespace {

std::string egl_error_text(EGLint code) {
  switch (code) {
    case EGL_NOT_INITIALIZED:
      return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS:
      return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC:
      return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE:
      return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG:
      return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT:
      return "EGL_BAD_CONTEXT";
    case EGL_BAD_DISPLAY:
      return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH:
      return "EGL_BAD_MATCH";
    case EGL_BAD_NATIVE_WINDOW:
      return "EGL_BAD_NATIVE_WINDOW";
    case EGL_BAD_PARAMETER:
      return "EGL_BAD_PARAMETER";
    case EGL_BAD_SURFACE:
      return "EGL_BAD_SURFACE";
    default:
      return "EGL error " + std::to_string(code);
  }
}

[[noreturn]] void fail(const std::string& step) {
  throw Error("EGL: " + step + " failed (" + egl_error_text(eglGetError()) + ")");
}

EGLDisplay platform_display(EGLenum platform, void* native) {
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  const std::string extensions = client ? client : "";
  if (extensions.find("EGL_EXT_platform_base") == std::string::npos)
    throw Error("EGL: the EGL library has no EGL_EXT_platform_base (Mesa's libegl-mesa0 has)");
  auto get_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
      eglGetProcAddress("eglGetPlatformDisplayEXT"));
  EGLDisplay display = get_display(platform, native, nullptr);
  if (display == EGL_NO_DISPLAY) fail("eglGetPlatformDisplayEXT");
  EGLint major = 0, minor = 0;
  if (!eglInitialize(display, &major, &minor)) fail("eglInitialize");
  return display;
}

EGLConfig choose_config(EGLDisplay display, EGLint surface_type) {
  const EGLint attributes[] = {EGL_RENDERABLE_TYPE,
                               EGL_OPENGL_ES3_BIT,
                               EGL_SURFACE_TYPE,
                               surface_type,
                               EGL_RED_SIZE,
                               8,
                               EGL_GREEN_SIZE,
                               8,
                               EGL_BLUE_SIZE,
                               8,
                               EGL_DEPTH_SIZE,
                               24,
                               EGL_NONE};
  EGLConfig config = nullptr;
  EGLint count = 0;
  if (!eglChooseConfig(display, attributes, &config, 1, &count)) fail("eglChooseConfig");
  if (count == 0) throw Error("EGL: no GLES 3 configuration with an 8-bit RGB and 24-bit depth");
  return config;
}

EGLContext make_context(EGLDisplay display, EGLConfig config) {
  if (!eglBindAPI(EGL_OPENGL_ES_API)) fail("eglBindAPI(GLES)");
  const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_NONE};
  EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, attributes);
  if (context == EGL_NO_CONTEXT) fail("eglCreateContext(GLES 3)");
  return context;
}

}  // namespace

EglContext EglContext::surfaceless() {
  EglContext c;
  c.display_ = platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY);
  // Surfaceless: the pbuffer bit only asks for a configuration that renders
  // off screen; no surface is ever made, frames go into framebuffer objects.
  const EGLConfig config = choose_config(c.display_, EGL_PBUFFER_BIT);
  c.context_ = make_context(c.display_, config);
  if (!eglMakeCurrent(c.display_, EGL_NO_SURFACE, EGL_NO_SURFACE, c.context_))
    fail("eglMakeCurrent (surfaceless)");
  return c;
}

EglContext EglContext::on_x11_window(void* native_display, std::uintptr_t native_window) {
  EglContext c;
  c.display_ = platform_display(EGL_PLATFORM_X11_KHR, native_display);
  const EGLConfig config = choose_config(c.display_, EGL_WINDOW_BIT);
  c.context_ = make_context(c.display_, config);
  c.surface_ = eglCreateWindowSurface(c.display_, config,
                                      static_cast<EGLNativeWindowType>(native_window), nullptr);
  if (c.surface_ == EGL_NO_SURFACE) fail("eglCreateWindowSurface");
  if (!eglMakeCurrent(c.display_, c.surface_, c.surface_, c.context_)) fail("eglMakeCurrent");
  eglSwapInterval(c.display_, 1);
  return c;
}

EglContext::EglContext(EglContext&& other) noexcept
    : display_(std::exchange(other.display_, nullptr)),
      context_(std::exchange(other.context_, nullptr)),
      surface_(std::exchange(other.surface_, nullptr)) {}

EglContext& EglContext::operator=(EglContext&& other) noexcept {
  if (this != &other) {
    release();
    display_ = std::exchange(other.display_, nullptr);
    context_ = std::exchange(other.context_, nullptr);
    surface_ = std::exchange(other.surface_, nullptr);
  }
  return *this;
}

EglContext::~EglContext() {
  release();
}

void EglContext::release() {
  if (!display_) return;
  eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  if (surface_) eglDestroySurface(display_, surface_);
  if (context_) eglDestroyContext(display_, context_);
  eglTerminate(display_);
  display_ = context_ = surface_ = nullptr;
}

void EglContext::swap_buffers() {
  if (surface_) eglSwapBuffers(display_, surface_);
}

std::string EglContext::describe() const {
  auto text = [](GLenum name) {
    const auto* s = reinterpret_cast<const char*>(glGetString(name));
    return std::string(s ? s : "?");
  };
  return text(GL_RENDERER) + ", " + text(GL_VERSION);
}

}  // namespace rockface::ui

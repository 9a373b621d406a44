#include "ui/view3d/gles_program.h"

#include <GLES3/gl3.h>

#include <string>

#include "core/common/error.h"

namespace rockface::ui {

namespace {

unsigned compile(GLenum kind, const char* source, const char* what) {
  const unsigned shader = glCreateShader(kind);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[1024] = {};
    glGetShaderInfoLog(shader, sizeof log, nullptr, log);
    glDeleteShader(shader);
    throw Error(std::string("GLES: ") + what + " shader does not compile: " + log);
  }
  return shader;
}

}  // namespace

unsigned link_gles_program(const char* vertex_source, const char* fragment_source,
                           const char* what) {
  const unsigned vs = compile(GL_VERTEX_SHADER, vertex_source, what);
  unsigned fs = 0;
  try {
    fs = compile(GL_FRAGMENT_SHADER, fragment_source, what);
  } catch (...) {
    glDeleteShader(vs);
    throw;
  }
  const unsigned program = glCreateProgram();
  glAttachShader(program, vs);
  glAttachShader(program, fs);
  glLinkProgram(program);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = 0;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) {
    glDeleteProgram(program);
    throw Error(std::string("GLES: ") + what + " shader does not link");
  }
  return program;
}

}  // namespace rockface::ui

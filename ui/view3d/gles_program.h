#pragma once
// A GLES 3 shader program from its two sources; throws rockface::Error with
// the compiler's log naming `what` ("model", "overlay").
namespace rockface::ui {

unsigned link_gles_program(const char* vertex_source, const char* fragment_source,
                           const char* what);

}  // namespace rockface::ui

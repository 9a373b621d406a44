#pragma once
// Owning handles of libgphoto2's lists, files and widgets: released by
// their own unref / free when the handle goes.
#include <memory>

#include <gphoto2/gphoto2.h>

namespace rockface::camera::gphoto2 {

struct ListDeleter {
  void operator()(CameraList* l) const { gp_list_unref(l); }
};
using ListPtr = std::unique_ptr<CameraList, ListDeleter>;
inline ListPtr new_list() {
  CameraList* l = nullptr;
  gp_list_new(&l);
  return ListPtr(l);
}

struct FileDeleter {
  void operator()(CameraFile* f) const { gp_file_unref(f); }
};
using FilePtr = std::unique_ptr<CameraFile, FileDeleter>;
inline FilePtr new_file() {
  CameraFile* f = nullptr;
  gp_file_new(&f);
  return FilePtr(f);
}

struct WidgetDeleter {
  void operator()(CameraWidget* w) const { gp_widget_free(w); }
};
using WidgetPtr = std::unique_ptr<CameraWidget, WidgetDeleter>;

}  // namespace rockface::camera::gphoto2

#include "storage/exchange/model_texture.h"

#include "core/common/atomic_file.h"
#include "storage/project/project_store.h"

namespace rockface::storage {

std::string write_model_texture(ProjectStore& store, const Model& model,
                                const std::filesystem::path& file) {
  if (!model.texture_capture_id || model.mesh.texcoords.empty()) return {};
  const ImageBlob image = store.load_capture_image(*model.texture_capture_id, model.texture_side);
  std::filesystem::path texture = file;
  texture.replace_filename(file.stem().string() + "-texture" +
                           (image.format == "png" ? ".png" : ".jpg"));
  write_bytes_atomically(texture, image.bytes.data(), image.bytes.size());
  return texture.filename().string();
}

}  // namespace rockface::storage

#include "storage/exchange/import_reader.h"

#include <algorithm>
#include <cctype>

#include "core/common/error.h"
#include "storage/exchange/intensity_grey.h"
#include "storage/exchange/las_reader.h"
#include "storage/exchange/obj_reader.h"
#include "storage/exchange/pcd_reader.h"
#include "storage/exchange/ply_reader.h"
#include "storage/exchange/ptx_reader.h"

namespace rockface::storage {

std::string imported_surface_extensions() {
  return ".ply, .obj, .pcd, .xyz, .txt, .csv, .asc, .pts, .ptx, .las";
}

namespace {

std::string lower_extension(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

}  // namespace

std::string imported_surface_format_by_name(const std::filesystem::path& file) {
  const std::string ext = lower_extension(file);
  if (ext == ".ply") return "PLY";
  if (ext == ".obj") return "OBJ";
  if (ext == ".pcd") return "PCD";
  if (ext == ".xyz" || ext == ".txt" || ext == ".csv" || ext == ".asc") return "text cloud";
  if (ext == ".pts") return "PTS";
  if (ext == ".ptx") return "PTX";
  if (ext == ".las") return "LAS";
  if (ext == ".laz") return "LAZ";
  if (ext == ".e57") return "E57";
  return {};
}

ImportedSurface read_imported_surface(const std::filesystem::path& file,
                                      const ImportFileOptions& options) {
  const std::string source = file.string();
  const std::string ext = lower_extension(file);
  if (ext == ".laz")
    throw InputError(source,
                     "LAZ (compressed LAS) is not read: decompress it to LAS first, e.g. `laszip "
                     "-i " +
                         source + " -o cloud.las` (LAStools), `pdal translate " + source +
                         " cloud.las` (PDAL) or CloudCompare's Save as LAS");
  if (ext == ".e57")
    throw InputError(source,
                     "E57 is not read: convert it to LAS, PLY or PTX first, e.g. `pdal translate " +
                         source +
                         " cloud.las` (PDAL) or CloudCompare's Save as PLY "
                         "(`CloudCompare -SILENT -O " +
                         source + " -C_EXPORT_FMT PLY -SAVE_CLOUDS`)");
  if (!options.columns.empty() && ext != ".xyz" && ext != ".txt" && ext != ".csv" &&
      ext != ".asc" && ext != ".pts")
    throw InputError("--columns",
                     "only for a text cloud (.xyz, .txt, .csv, .asc, .pts), not " + source);
  if (!std::filesystem::is_regular_file(file)) throw InputError(source, "no such file");
  ImportedSurface out;
  if (ext == ".obj") {
    out = read_obj(file);
  } else if (ext == ".las") {
    out = read_las_file(file);  // in chunks: the largest clouds come as LAS
  } else {
    const std::string bytes = read_whole_file(source);
    if (ext == ".ply") {
      PlyModel ply = parse_ply(bytes, source);
      out.mesh = std::move(ply.mesh);
      out.datum = ply.datum;
      out.texture_file = ply.texture_file;
      if (!out.texture_file.empty() && file.has_parent_path() &&
          std::filesystem::path(out.texture_file).is_relative())
        out.texture_file = (file.parent_path() / out.texture_file).string();
      out.format = "PLY";
    } else if (ext == ".pcd") {
      out = parse_pcd(bytes, source);
    } else if (ext == ".ptx") {
      out = parse_ptx(bytes, source);
    } else if (ext == ".xyz" || ext == ".txt" || ext == ".csv" || ext == ".asc") {
      out = parse_xyz(bytes, source, options.columns, false);
    } else if (ext == ".pts") {
      out = parse_xyz(bytes, source, options.columns, true);
    } else {
      throw InputError(source, "'" + ext + "' is no format read (" + imported_surface_extensions() +
                                   "; LAZ and E57 converted "
                                   "first)");
    }
  }
  if (options.offset) out.datum += *options.offset;
  if (out.mesh.vertices.empty()) throw InputError(source, "no points in the file");
  grey_from_intensity(out, source);  // a scanner's cloud without colours: its intensity
  return out;
}

}  // namespace rockface::storage

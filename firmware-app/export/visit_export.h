#pragma once
// `rockface export` and the tablet's export to a USB stick: what the office
// opens of one visit, written into one folder.
//   mesh     visit-N-model-M.obj (+ .mtl + -texture.jpg) and visit-N-model-M.ply
//            (binary, faces, texture named): CloudCompare, MeshLab, Blender
//   cloud    visit-N-model-M-cloud.ply: the vertices with their colours
//   traces   3D polylines in visit-N.dxf (a layer per set), visit-N-traces.csv
//   joints   discs in visit-N.dxf (a layer per set), visit-N-joints.csv (Dips)
//   blocks   closed meshes in visit-N.dxf (a layer per verdict)
//   profile  the design and measured cross-sections in visit-N.dxf,
//            visit-N-profile.csv (over / underbreak per section)
// Survey coordinates throughout where the project has them (the datum added
// back, named in each file's comment).
#include <filesystem>
#include <string>
#include <vector>

#include "core/common/preset.h"
#include "firmware-app/tunnel/round_start.h"
#include "storage/project/project_store.h"

namespace rockface::app {

struct ExportRequest {
  storage::RecordId visit = 0;
  std::filesystem::path out_dir;
  // Items asked for; empty: every item the visit has (those it lacks are
  // named in the notes). An item asked for by name that the visit lacks is
  // an InputError.
  std::vector<std::string> what;
  Preset preset = Preset::standard;  // of the profile's cross-sections
  // The drive's faces, where the round starts, when the store does not hold
  // the whole drive (the office's copy of a visit); null: read from it.
  const DriveFaces* drive = nullptr;
};

struct ExportResult {
  std::vector<std::filesystem::path> files;
  std::vector<std::string> notes;  // what was left out and why
};

// The item names, in the order they are written.
const std::vector<std::string>& export_items();

// Throws InputError for an unknown visit or item, or an item asked for that
// the visit does not have; Error naming the file for one that cannot be
// written (the files written before it stay).
ExportResult export_visit(storage::ProjectStore& store, const ExportRequest& request);

}  // namespace rockface::app

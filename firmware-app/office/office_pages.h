#pragma once
// The office web pages' data (issue 46) as JSON: what the browser's modules
// (ui/web/) lay out with textContent. Every figure is formatted here by
// core/common/number_format with its unit and a precision that fits what
// it was measured to, so the page never shows a raw number or a key; the
// numbers the drawings need (chainage, dip) travel beside the text.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "storage/field_report/field_report.h"
#include "storage/office/pg_connection.h"
#include "storage/office/server_drive.h"

namespace rockface::app::office_web {

// The tunnels the connection's role may read: name, visits, last visit,
// length of the drive mapped (first to last placed visit).
nlohmann::json tunnels_page(storage::office::Connection& c);

struct DriveFilter {
  std::string from, to;  // visit dates (YYYY-MM-DD), inclusive; empty = open
  std::string tablet;    // a tablet's role; empty = every tablet
  // The heading the visits were taken at (storage/tunnel/visit_heading.h);
  // empty = every heading, kNoHeading = the visits without one.
  std::string heading;
};
// How the drive lists a visit without a heading, and the filter that
// keeps only those (no heading takes this name: checked_heading).
inline constexpr const char* kNoHeading = "—";

// The drive of a tunnel: every visit (date, tablet, project, chainage,
// blocks and the blocks that move, the largest removable block), the sets
// along the drive (server_drive's tracks, flags for new, vanishing and
// turning sets) and `stamp`, which changes when a tablet syncs (the page
// polls it). Throws InputError when the role may not read the tunnel.
nlohmann::json drive_page(storage::office::Connection& c, const std::string& tunnel,
                          const DriveFilter& filter);
// The same in two halves, so that the connection goes back to the pool
// before the sets are tracked along the drive (issue 46): the rows read on
// `c` (the page's visits, the drive's records of sets), then the page put
// together without the server.
struct DriveRead {
  nlohmann::json page;  // all but the sets
  std::optional<storage::office::ServerDrive> drive;
  std::string sets_note;  // why there are no sets, when `drive` is empty
};
DriveRead read_drive_page(storage::office::Connection& c, const std::string& tunnel,
                          const DriveFilter& filter);
nlohmann::json drive_page(DriveRead read);

// The state of the tunnel's records: changes with every sync.
std::string tunnel_stamp(storage::office::Connection& c, const std::string& tunnel);

// One visit from its field report (firmware-app/office/visit_report.h):
// its figures, joints, sets with the stereonet's poles, blocks with
// verdict, margin, mode, FoS and motion after failure, the tunnel's round,
// the wedges, the rock mass and the support, and the 3D face's overlays
// (traces by set, blocks by verdict) in the mesh's local frame (`origin`
// subtracted, see face_mesh).
nlohmann::json visit_page(const storage::FieldReport& report, const std::string& visit_uuid,
                          const Eigen::Vector3d& origin);

// The 3D face for the browser: the visit's first model, its vertices
// relative to `origin` (the mesh's centre, project frame) as float32, its
// texture coordinates and triangles. Decimated by vertex clustering on a
// grid (one vertex per cell, the cell's first; triangles whose corners
// merge dropped) so that at most `max_triangles` remain; 0 keeps the full
// mesh. Binary little-endian: "RFM1", uint32 vertices, uint32 triangles,
// uint32 has_texcoords, float64 origin[3], float32 xyz[3 n], float32
// uv[2 n] (when present), uint32 index[3 t].
struct FaceMesh {
  std::vector<std::uint8_t> bytes;
  std::size_t vertices = 0, triangles = 0, full_triangles = 0;
};
FaceMesh face_mesh(storage::ProjectStore& store, storage::RecordId visit_id,
                   std::size_t max_triangles);

// The range pole that scaled the model, for the 3D face: its two targets
// (the reconstruction's record, project frame) in the mesh's local frame
// (`origin` subtracted) and its length; null when the model was not scaled
// by a pole or its record does not hold both targets.
nlohmann::json range_pole_overlay(const storage::Model& model, const Eigen::Vector3d& origin);

// The origin the overlays of visit_page and the mesh of face_mesh share:
// the centre of the visit's first model's bounding box (project frame).
Eigen::Vector3d face_origin(storage::ProjectStore& store, storage::RecordId visit_id);

}  // namespace rockface::app::office_web

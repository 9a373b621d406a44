#pragma once
// Helpers shared by the files of ProjectStore (one file per kind of record):
// validation of what is saved and conversions of stored columns. Internal to
// storage; not part of the store's interface.
#include <cmath>
#include <optional>
#include <string>

#include <Eigen/Core>

#include "core/common/error.h"
#include "storage/project/project_records.h"
#include "storage/project/project_sqlite.h"

namespace rockface::storage {

std::string utc_now_iso8601();

namespace rows {

// The SQLite wrappers every ProjectStore file uses.
using sqlite::Connection;
using sqlite::ReadTransaction;
using sqlite::RowReader;
using sqlite::Statement;
using sqlite::WriteTransaction;

inline std::string or_now(const std::string& stamp) {
  return stamp.empty() ? utc_now_iso8601() : stamp;
}

inline void require_finite(double value, const std::string& where) {
  if (!std::isfinite(value)) throw InputError(where, "must be a finite number");
}

inline void require_orientation(double dip, double dipdir, const std::string& where) {
  require_finite(dip, where + ".dip");
  require_finite(dipdir, where + ".dipdir");
  if (dip < 0 || dip > 90)
    throw InputError(where + ".dip", "must be in [0, 90] degrees, got " + std::to_string(dip));
  if (dipdir < 0 || dipdir >= 360)
    throw InputError(where + ".dipdir",
                     "must be in [0, 360) degrees, got " + std::to_string(dipdir));
}

inline void require_finite(const Eigen::Vector3d& p, const std::string& where) {
  if (!p.allFinite()) throw InputError(where, "must be finite coordinates");
}

inline std::string kind_text(Measurement::Kind kind) {
  switch (kind) {
    case Measurement::Kind::trace:
      return "trace";
    case Measurement::Kind::area:
      return "area";
    case Measurement::Kind::point_orientation:
      return "point_orientation";
  }
  return "trace";
}

inline Measurement::Kind kind_of(const std::string& text, const std::string& where) {
  if (text == "trace") return Measurement::Kind::trace;
  if (text == "area") return Measurement::Kind::area;
  if (text == "point_orientation") return Measurement::Kind::point_orientation;
  throw Error(where + ": unknown measurement kind '" + text + "'");
}

// Three REAL columns (x, y, z) as a point or a vector.
inline Eigen::Vector3d next_vector3(RowReader& row) {
  Eigen::Vector3d v;
  for (int i = 0; i < 3; ++i) v[i] = row.next_double();
  return v;
}

// Four REAL columns (w, x, y, z) of a quaternion.
inline Eigen::Vector4d next_vector4(RowReader& row) {
  Eigen::Vector4d v;
  for (int i = 0; i < 4; ++i) v[i] = row.next_double();
  return v;
}

// Three nullable REAL columns as a point that may be absent: absent when the
// first is NULL (the three columns are then passed over).
inline std::optional<Eigen::Vector3d> next_optional_vector3(RowReader& row) {
  if (row.next_is_null()) {
    row.skip(3);
    return std::nullopt;
  }
  return next_vector3(row);
}

}  // namespace rows
}  // namespace rockface::storage

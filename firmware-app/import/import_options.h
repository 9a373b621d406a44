#pragma once
// `rockface import`'s options as typed (the points as text E,N,Z or
// X1,Y1,Z1,X2,Y2,Z2) turned into an ImportRequest (import_surface.h). Every
// value is checked here, naming the option at fault, before the file is
// read or the project is opened.
#include <optional>
#include <string>

#include "firmware-app/import/import_surface.h"
#include "storage/project/project_records.h"

namespace rockface::app {

struct ImportOptions {
  std::string project, file, columns, offset, view_from, frame, gcp, pole, reference_line,
      geologist;
  std::optional<double> range_pole, azimuth, declination;
  storage::RecordId visit = 0;  // 0: a new visit
  bool new_visit = false;
};

// Throws InputError naming the option: a point that is not its count of
// finite numbers, --range-pole without --pole, --azimuth without
// --reference-line (or the other way), --declination without --azimuth,
// a --geologist name storage/project/visit_geologist.h refuses or given
// with --visit (a new visit's geologist).
ImportRequest import_request(const ImportOptions& options);

}  // namespace rockface::app

#pragma once
// Picks measured on a 3D image, start to end: the picks file read, the 3D
// images loaded (a model file, or a project's visit with one model per
// pair, measure_models.h), every pick measured on its pair's image in the
// face frame (the first pair's), the measurements stored in the project as
// one new visit (or added to the visit measured on), and the output files written
// (rockface-measures/1, the stereonet, the Dips-style CSV). Everything is measured before anything
// is stored or written: a bad pick throws InputError naming it, with nothing stored and no output
// file. Run by `rockface measure`.
#include <functional>
#include <optional>
#include <string>

#include "core/measure/pick_measurement.h"
#include "firmware-app/measure/measure_models.h"
#include "storage/project/project_records.h"

namespace rockface::app {

struct MeasureRequest {
  ModelSource on;     // the 3D images
  std::string picks;  // the PICKS file (rockface-picks/1)
  std::string out;    // the measurements (rockface-measures/1)
  std::string png;    // the stereonet picture; none when empty
  std::string csv;    // the Dips-style CSV of the measured planes; none when empty
  // The joint sets wanted: a count in [1, 12]; else automatic when
  // automatic_sets, or the picks' own `sets`.
  std::optional<int> sets;
  bool automatic_sets = false;
  double friction_deg = 30;  // the stereonet's sliding overlay
  // Project: store the measurements in the visit measured on (on.visit),
  // not in a new one, so that one visit carries its camera, scale, north
  // and the traces mapped later at a desk (issue 42). Refused, nothing
  // stored, for a visit without a 3D image, and for a label the visit
  // already holds (a measurement, joint or joint set).
  bool add_to_visit = false;
  // Project: the geologist who mapped the new visit ("" none; checked by
  // measure_options.h, storage/project/visit_geologist.h).
  std::string geologist;
  // Called once the measurements are stored in the project (the new
  // visit, or the visit added to), before the output files are written.
  std::function<void(storage::RecordId visit)> stored;
};

struct MeasureOutcome {
  measure::MeasuredPicks measured;
  std::optional<storage::RecordId> visit;  // the visit stored (project only)
};

MeasureOutcome measure_picks_file(const MeasureRequest& request);

}  // namespace rockface::app

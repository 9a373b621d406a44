#pragma once
// The field report of one visit as every route gathers it — `rockface
// report`, `rockface propose --report`, the tablet's Field report and the
// office's visit page: the store's figures, then the tunnel, the wedges,
// the rock mass and the support added by their workflows, so the printed,
// the tablet's and the browser's reports agree (issue 37: four copies of
// these steps).
#include "firmware-app/tunnel/round_start.h"
#include "storage/field_report/field_report.h"
#include "storage/project/project_store.h"

namespace rockface::app {

// `drive`: the drive's faces, where the visit's round starts, when `store`
// does not hold the whole drive (the office's copy of a visit); else read
// from the store.
storage::FieldReport collect_visit_report(storage::ProjectStore& store, storage::RecordId visit,
                                          const DriveFaces* drive = nullptr);

}  // namespace rockface::app

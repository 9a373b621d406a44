#pragma once
// The tunnel's part of a visit's field report: the tunnel, how the visit
// was placed in it, its round against the design (the figures and the
// developed view), each joint and set against the drive (Bieniawski's
// classes), and each block in survey coordinates and relative to the tunnel.
#include "core/common/preset.h"
#include "firmware-app/tunnel/round_start.h"
#include "storage/field_report/field_report.h"
#include "storage/project/project_store.h"

namespace rockface::app {

// Fills report.tunnel when the project has a tunnel; leaves it empty
// otherwise. A visit not placed gets the tunnel without the round. `faces`:
// the drive's faces where the round starts (round_start.h) when the store
// does not hold every visit of the drive (the office's copy of a visit);
// else read from the store.
void add_tunnel_to_report(storage::ProjectStore& store, storage::FieldReport& report,
                          Preset preset = Preset::standard, const DriveFaces* faces = nullptr);

}  // namespace rockface::app

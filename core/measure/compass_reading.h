#pragma once
// A compass reading of a trace (issue 27): what a geologist does at the
// face where a trace gives no plane of its own (a straight trace on a flat
// face, plane_measurement.h): a Clar compass held on the exposed joint where
// the trace runs, read as dip / dip direction (degrees, DESIGN.md). The
// trace's plane is then the reading's orientation through the trace's
// points, with the compass's accuracy as its sigma (tolerances.h); the
// trace must lie in it, and how far it leaves it is kept as the margin.
#include <optional>
#include <string>

namespace rockface::measure {

struct TraceMeasurement;  // plane_measurement.h (picks.h needs only the reading)

struct CompassReading {
  double dip_deg = 0;            // [0, 90]
  double dip_direction_deg = 0;  // [0, 360]; 360 is north, as 0
};

// How the trace lies against the plane read (degrees).
struct CompassCheck {
  CompassReading reading;
  // The angle between the trace's own line (its points' direction of
  // largest spread) and the plane read.
  double trace_off_deg = 0;
  // The angle between the plane fitted to the trace (where it has one of
  // its own) and the plane read.
  std::optional<double> fitted_off_deg;
  // kMaxTraceOffCompassDeg less the larger of the two angles: negative
  // when the trace leaves the plane by more than the tolerance.
  double margin_deg = 0;
  bool marginal() const { return margin_deg < 0; }
};

// Throws InputError at `where` + ".dip" / ".dip_direction" for a reading
// that no compass gives: not finite, a dip outside [0, 90], a dip
// direction outside [0, 360].
void check_compass_reading(const CompassReading& reading, const std::string& where);

// The trace's plane from the reading (replacing the fitted one, whose
// difference is reported): known, through the centroid of the trace's
// points, sigma kCompassSigmaDeg; its `problem` (the measurement's note)
// says that it is a compass reading and how far the trace leaves it, and
// "check the reading" when beyond kMaxTraceOffCompassDeg. `where` names the
// reading in messages ("traces[2].compass").
CompassCheck apply_compass_reading(TraceMeasurement& trace, const CompassReading& reading,
                                   const std::string& where);

}  // namespace rockface::measure

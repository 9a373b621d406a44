#pragma once
// The joint sets along the drive of a project (`rockface drive`, the
// tablet's Project screen): every visit placed in the tunnel gives its sets
// (those stored with its joints, else its measured planes clustered as the
// field report clusters them), and core/tunnel matches them across visits
// by orientation and flags a set that appears, vanishes or turns.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "core/tunnel/drive_sets.h"
#include "storage/project/project_store.h"

namespace rockface::app {

// One visit's sets; empty when it has fewer than two measured planes.
std::vector<tunnel::SetObservation> visit_set_observations(storage::ProjectStore& store,
                                                           storage::RecordId visit_id);
// The same from a visit's records wherever they were read (a project, the
// office server): its stored sets, else its measured planes clustered.
std::vector<tunnel::SetObservation> set_observations(
    const std::vector<storage::JointSet>& sets,
    const std::vector<storage::Measurement>& measurements);

// Issue 39: a visit's measured joints as the tablet plots them along the
// drive: its joints (the joint table), else its measured planes (traces and
// point readings with an orientation).
struct JointOrientation {
  std::string label;
  double dip_deg = 0, dipdir_deg = 0;
};
std::vector<JointOrientation> visit_joint_orientations(storage::ProjectStore& store,
                                                       storage::RecordId visit_id);

// Throws InputError naming the project when it has no tunnel.
tunnel::DriveSets project_drive(storage::ProjectStore& store);

// Who mapped each visit of the drive (issue 46), by the drive's visit id; a
// visit nobody named is absent, and shown as storage::kGeologistNotRecorded.
using DriveGeologists = std::map<std::int64_t, std::string>;
DriveGeologists drive_geologists(storage::ProjectStore& store);

// One row per set and visit (and one per event), for a spreadsheet; the
// last column the geologist of the row's visit (RFC 4180 quoting).
std::string drive_csv(const tunnel::DriveSets& drive, const DriveGeologists& geologists);

// The lines the verb prints: the visits' geologists, each set's track and
// its events (each naming who mapped the visit where it was found).
std::vector<std::string> drive_summary(const tunnel::DriveSets& drive,
                                       const DriveGeologists& geologists);

}  // namespace rockface::app

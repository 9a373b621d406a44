#pragma once
// The rock mass of one visit as the project holds it (`rockface rockmass`,
// the tablet's Rock mass view, the field report): the visit's traces, its
// joint sets (stored, else its joints' planes clustered, else its measured
// planes clustered), its face window (the hull of the mapped traces),
// the finite blocks of its latest analysis, the sets against the drive
// where the visit is placed in a tunnel, and the form entered for it.
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "core/rockmass/rock_mass_figures.h"
#include "core/tunnel/alignment.h"
#include "storage/project/project_store.h"

namespace rockface::app {

// What the visits of one project share for their rock mass: which visits
// there are, the tunnel's alignment and its span. Read and built once for
// a drive's rounds (issue 46: read per visit, the rounds of a 3,000-visit
// drive listed every visit and rebuilt the tunnel 3,000 times).
struct RockMassProject {
  std::set<storage::RecordId> visits;
  std::optional<tunnel::Alignment> alignment;  // when the project has a tunnel
  double tunnel_span_m = 0;
};
RockMassProject rock_mass_project(storage::ProjectStore& store);

// What the project gives core/rockmass for a visit (the form: the one
// stored for the visit, or `form` when given).
rockmass::RockMassInput visit_rock_mass_input(
    storage::ProjectStore& store, storage::RecordId visit_id,
    const std::optional<rockmass::ClassificationForm>& form = {});
// The same with what the project's visits share read before.
rockmass::RockMassInput visit_rock_mass_input(
    storage::ProjectStore& store, const RockMassProject& project, storage::RecordId visit_id,
    const std::optional<rockmass::ClassificationForm>& form = {});

// Throws InputError naming the visit when it has no traces, or a form field
// out of range.
rockmass::RockMassFigures visit_rock_mass(
    storage::ProjectStore& store, storage::RecordId visit_id,
    const std::optional<rockmass::ClassificationForm>& form = {});
rockmass::RockMassFigures visit_rock_mass(storage::ProjectStore& store,
                                          const RockMassProject& project,
                                          storage::RecordId visit_id);

}  // namespace rockface::app

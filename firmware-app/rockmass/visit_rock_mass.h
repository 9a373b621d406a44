#pragma once
// The rock mass of one visit as the project holds it (`rockface rockmass`,
// the tablet's Rock mass view, the field report): the visit's traces, its
// joint sets (stored, else its joints' planes clustered, else its measured
// planes clustered), its face window (the hull of the mapped traces),
// the finite blocks of its latest analysis, the sets against the drive
// where the visit is placed in a tunnel, and the form entered for it.
#include <optional>
#include <string>
#include <vector>

#include "core/rockmass/rock_mass_figures.h"
#include "storage/project/project_store.h"

namespace rockface::app {

// What the project gives core/rockmass for a visit (the form: the one
// stored for the visit, or `form` when given).
rockmass::RockMassInput visit_rock_mass_input(
    storage::ProjectStore& store, storage::RecordId visit_id,
    const std::optional<rockmass::ClassificationForm>& form = {});

// Throws InputError naming the visit when it has no traces, or a form field
// out of range.
rockmass::RockMassFigures visit_rock_mass(
    storage::ProjectStore& store, storage::RecordId visit_id,
    const std::optional<rockmass::ClassificationForm>& form = {});

}  // namespace rockface::app

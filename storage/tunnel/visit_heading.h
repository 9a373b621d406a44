#pragma once
// The heading a visit was taken at (issue 46: the office's drive "filtered
// by date, heading, tablet"). A tunnel driven from more than one face — from
// the north and the south portal towards each other, or a top heading with
// its bench behind it — has one alignment and one design; its visits are
// told apart by the name of the face they were taken at, as the site names
// it ("North portal", "Bench"). A visit without one (the tunnel has one
// face, or it was not said) has none; the office lists it as "—".
//
// Kept in a table of its own (visit_heading, project schema 12), one row
// per named visit, and synced as a record of its own (kind "visit_heading"):
// a visit's own row is unchanged, so the visits and rounds already on the
// office server stay as they were when a tablet is upgraded.
#include <cstddef>
#include <map>
#include <string>

#include "storage/project/project_store.h"

namespace rockface::storage {

// A heading's longest name: a face's name, not a note.
inline constexpr std::size_t kHeadingMaxChars = 40;

// The name as kept: trimmed of spaces; "" for none. InputError naming
// `field` for a name over kHeadingMaxChars characters or with a control
// character (a line break, a tab).
std::string checked_heading(const std::string& name, const std::string& field);

// Names the heading of a visit ("" takes its name away). InputError naming
// the visit when the project has no such visit or the project is read-only.
void save_visit_heading(ProjectStore& store, RecordId visit_id, const std::string& heading);
// "" when the visit has none.
std::string load_visit_heading(ProjectStore& store, RecordId visit_id);
// Every named visit's heading.
std::map<RecordId, std::string> list_visit_headings(ProjectStore& store);

}  // namespace rockface::storage

#pragma once
// The geologist who mapped a visit (issue 46: the office's drive lists
// "every visit (date, tablet, geologist)"), by name as the site knows them:
// typed once on the tablet and carried to each new visit, changeable per
// visit, or given to the command line (`--geologist`) and the visit file.
//
// Kept in a table of its own (visit_geologist, project schema 13), one row
// per visit with a geologist, read and written by ProjectStore's visit code
// (Visit::geologist, begin_visit, save_visit_geologist); synced as a record
// of its own (kind "visit_geologist"), so the visits already on the office
// server stay as they were. A visit of an older project, or one nobody
// named, has none: every reader shows kGeologistNotRecorded, never "".
#include <cstddef>
#include <string>

namespace rockface::storage {

// A person's name, not a note.
inline constexpr std::size_t kGeologistMaxChars = 80;
// How every page, report and screen shows a visit without a geologist.
inline constexpr const char* kGeologistNotRecorded = "not recorded";

// The name as kept: trimmed of spaces; "" for none. InputError naming
// `field` for a name over kGeologistMaxChars characters (a UTF-8 letter
// counts once) or with a control character (a line break, a tab).
std::string checked_geologist(const std::string& name, const std::string& field);

}  // namespace rockface::storage

#pragma once
// A decision's changes applied to its class (issue 44): the pattern as
// decided for this round, which the check runs on beside the class as the
// designer wrote it, so that the effect of a change is seen before the
// round is drilled.
//
// A change names what it changes (WHAT, one of support_change_names(), in
// any case), what the class gives (FROM) and what it gives now (TO). A
// figure is a number with its unit: lengths in m, cm or mm, capacities in
// N, kN or MN, strengths in kPa or MPa; "none" where the class has none or
// the change takes it away. A whole bolt pattern ("bolts", "face bolts")
// is "LENGTH at SPACING[, CAPACITY]" ("4 m at 1.5 m, 150 kN"; the capacity
// may be left out where the class has bolts: theirs is kept). Text fields
// (mesh, steel sets, the face support's words) take any text.
//
// Refused by name (InputError naming `where`, the change's number and its
// WHAT): a WHAT the check cannot apply, a figure without its unit or with a
// unit of another quantity, a FROM that is not what the class gives (the
// record would say something the class does not: FROM matches within half
// the last digit typed, "1.5 m" for 1.45-1.55 m), a value outside the
// range the class file takes, and a bolt figure changed on a class without
// bolts (add the pattern with "bolts: none -> ...").
//
// Changes apply in order (a second change of one WHAT starts from the
// first's TO). What the wedge and block check does not use (the round
// length, mesh, steel sets, the face support's words; shotcrete without a
// shear strength) is applied to the pattern and said in the notes.
#include <string>
#include <vector>

#include "core/analysis/support_classes.h"
#include "core/analysis/support_decision.h"

namespace rockface::analysis {

// The class as changed, and what of the changes the check does not count.
struct ChangedPattern {
  SupportClass pattern;
  std::vector<std::string> notes;
};

ChangedPattern apply_support_changes(const SupportClass& c,
                                     const std::vector<SupportChange>& changes,
                                     const std::string& where);

// The WHATs a change may name, lower case ("bolt length", ...).
const std::vector<std::string>& support_change_names();

}  // namespace rockface::analysis

#pragma once
// The round's support for one visit (issue 44), shared by `rockface
// support`, the field report and the drive: the support the Q chart and
// Bieniawski's table call for with the visit's figures, the designer's
// class the visit meets, the check of the proposed and the chosen class on
// the visit's wedges and the face's moving blocks, and the decision stored
// with the visit.
#include <optional>
#include <string>
#include <vector>

#include "core/analysis/support_check.h"
#include "core/analysis/support_classes.h"
#include "core/analysis/support_decision.h"
#include "core/rockmass/q_support_chart.h"
#include "core/rockmass/rmr_support_guidelines.h"
#include "storage/project/project_store.h"

namespace rockface::app {

struct SupportRequest {
  std::string project;
  storage::RecordId visit = 0;
  std::optional<std::string> classes_file;  // read, refused by name, stored in the project
  std::optional<std::string> esr_use;       // a key of the ESR table; default: the form's ESR
  // A decision: the class chosen, by whom, why (required when it is not
  // the proposed class), and the changes made to the class for this round
  // (each with what, from, to and why: support_change_text.h).
  std::optional<std::string> decide, by, reason;
  std::vector<analysis::SupportChange> changes;
};

struct VisitSupport {
  storage::RecordId visit = 0;
  std::optional<double> chainage;
  analysis::VisitFigures figures;
  std::optional<double> span_m, esr;
  std::string esr_source;  // "form", "table: road_rail_major"
  std::optional<rockmass::QChartPoint> q_point;
  std::optional<rockmass::QSupport> q_support;
  std::string q_support_why;  // when none
  std::optional<rockmass::RmrSupport> rmr_support;
  std::string rmr_support_why;
  std::optional<analysis::SupportClasses> classes;
  std::optional<analysis::ClassProposal> proposal;
  std::vector<analysis::SupportCheck> checks;  // the proposed and the chosen class
  // The chosen class with the decision's changes applied
  // (core/analysis/support_changes.h), checked: its class_name is the
  // class's with " as changed", its notes say what of the changes the check
  // does not use. None when the decision changes nothing (the chosen
  // class's check in `checks` is the pattern as decided) or when a stored
  // decision's changes cannot be applied to the class (said in `notes`).
  std::optional<analysis::SupportCheck> decided_check;
  std::optional<analysis::SupportDecision> decision;
  std::vector<std::string> notes;
};

// Reads what the project holds for the visit (the classes stored for the
// tunnel unless the request gives a file); stores the classes and the
// decision when asked. InputError naming the option for a bad request
// (an unknown class, a decision without --by, a class other than the
// proposed one without --reason, a change without its reason or without
// --decide).
VisitSupport visit_support(const SupportRequest& request);

// The same on an open store, without storing anything (the field report,
// the drive, the tablet).
VisitSupport visit_support(storage::ProjectStore& store, storage::RecordId visit,
                           const std::optional<std::string>& esr_use = {});

// The checks in one line ("SC2: 1 of 6 wedges and 0 of 2 blocks below FoS 1.5 (W3)").
std::string checks_words(const analysis::SupportCheck& check);

// The check of the pattern as decided, in one line, with the class's
// unchanged check beside it when the decision changed the class ("SC2 as
// changed: 0 of 6 ...; the class unchanged: SC2: 1 of 6 ..."); "" without
// a decision or a check of its class.
std::string decision_checks_words(const VisitSupport& support);

}  // namespace rockface::app

#include "ui/blocks/support_view.h"

#include <cstddef>
#include <memory>
#include <optional>

#include <imgui.h>

#include "ui/app/app_state.h"
#include "ui/widgets/format.h"
#include "ui/widgets/toggle_button.h"
#include "ui/widgets/widgets_controls.h"
#include "ui/widgets/widgets_table.h"

namespace rockface::ui {

namespace {

// Reads the proposals, or with `decide` stores the decision first.
void load_support(AppState& app, std::optional<SupportChoice> decide) {
  SupportRunner* runner = app.services.support;
  const auto file = app.session->file();
  const auto visit = *app.session->visit();
  auto result = std::make_shared<SupportProposals>();
  const bool deciding = decide.has_value();
  app.task.start(
      deciding ? "Support decision" : "Support of this round",
      [runner, file, visit, decide, result](Progress& progress) {
        *result = runner->support(file, visit, decide, progress);
        return result->decision && decide ? "decided: class " + result->decision->class_name
                                          : std::string("proposals read");
      },
      [&app, result, deciding](const TaskOutcome& outcome) {
        SupportViewState& s = app.blocks.support;
        if (outcome.kind != TaskOutcome::Kind::done) {
          s.message = outcome.message;
          if (!deciding) s.proposals.reset();
          return;
        }
        s.message.clear();
        s.proposals = std::move(*result);
        if (deciding) {
          s.reason.clear();
          s.changes.clear();
        }
      });
}

void draw_proposals(AppState& app, const SupportProposals& p) {
  paragraph(p.figures);
  const ImGuiTableFlags flags =
      ImGuiTableFlags_Borders | ImGuiTableFlags_SizingStretchSame | ImGuiTableFlags_RowBg;
  if (ImGui::BeginTable("support proposals", 3, flags)) {
    ImGui::TableSetupColumn("From Q (NGI chart)");
    ImGui::TableSetupColumn("From RMR89 (Bieniawski)");
    ImGui::TableSetupColumn("The designer's classes");
    table_headers_row();
    ImGui::TableNextRow(0, app.targets.target_px());
    for (const auto* column : {&p.from_q, &p.from_rmr, &p.from_classes}) {
      ImGui::TableNextColumn();
      for (const auto& line : *column) paragraph(line);
    }
    ImGui::EndTable();
  }
  for (const auto& c : p.checks) paragraph("Check " + c);
  // The pattern as decided beside its class unchanged (above): the
  // effect of the changes.
  for (std::size_t i = 0; i < p.decided_check.size(); ++i)
    if (i == 0)
      paragraph("Check as decided, " + p.decided_check[i]);
    else
      note(p.decided_check[i]);
  for (const auto& n : p.notes) note(n);
}

// The changes to the chosen class for this round, each in four fields, and
// the buttons to add and remove one. What is missing from one, in words
// ("" when every change is complete).
std::string draw_changes(AppState& app, SupportViewState& s) {
  label("Changes to the class for this round");
  std::string missing;
  std::optional<std::size_t> remove;
  for (std::size_t i = 0; i < s.changes.size(); ++i) {
    analysis::SupportChange& c = s.changes[i];
    const std::string n = std::to_string(i + 1);
    label("Change " + n + ": what (e.g. bolt spacing), from, to (with units: 1.5 m), why");
    text_field(app.targets, "change " + n + " what", &c.what);
    text_field(app.targets, "change " + n + " from", &c.from);
    text_field(app.targets, "change " + n + " to", &c.to);
    text_field(app.targets, "change " + n + " why", &c.reason);
    if (app.targets.button("Remove change " + n)) remove = i;
    if (missing.empty() && (c.what.empty() || c.from.empty() || c.to.empty() || c.reason.empty()))
      missing = "Change " + n + ": say what was changed, from what, to what and why.";
  }
  if (remove) s.changes.erase(s.changes.begin() + static_cast<std::ptrdiff_t>(*remove));
  if (app.targets.button("Add a change")) s.changes.emplace_back();
  return missing;
}

void draw_decision(AppState& app, SupportViewState& s, const SupportProposals& p) {
  heading("The decision");
  if (p.decision) {
    const SupportDecided& d = *p.decision;
    paragraph("Class " + d.class_name + " decided by " + d.by + " on " + format::date_time(d.at) +
              (d.proposed.empty()           ? " (no class proposed)"
               : d.proposed == d.class_name ? " (the proposed class)"
                                            : " (proposed: " + d.proposed + ")") +
              ".");
    if (!d.reason.empty()) paragraph("Why: " + d.reason);
    for (const auto& c : d.changes)
      paragraph("Changed " + c.what + ": " + c.from + " -> " + c.to + " (" + c.reason + ")");
    if (!d.checks.empty()) paragraph("Checked: " + d.checks);
  } else {
    paragraph("No decision stored for this round.");
  }
  if (p.classes.empty()) {
    note("A class is chosen from the tunnel's support classes: none are stored.");
    return;
  }
  label("Class for this round:");
  for (const auto& c : p.classes) {
    same_line_if_fits(button_width(c, app.targets.target_px()));
    if (toggle_button(app.targets, c, s.chosen == c)) s.chosen = c;
  }
  label("Decided by");
  text_field(app.targets, "decided by", &s.by);
  const bool other = !s.chosen.empty() && s.chosen != p.proposed;
  label(other ? "Why not the proposed class (required)" : "Remarks");
  text_field(app.targets, "reason", &s.reason);
  const std::string incomplete = draw_changes(app, s);
  std::string why;
  if (s.chosen.empty())
    why = "Choose a class.";
  else if (s.by.empty())
    why = "Say who decides.";
  else if (other && s.reason.empty())
    why = "Class " + s.chosen + " is not the proposed " +
          (p.proposed.empty() ? std::string("(none)") : p.proposed) + ": say why.";
  else
    why = incomplete;
  if (!why.empty()) paragraph(why);
  const bool can = why.empty() && !app.task.running() && !app.session->read_only();
  if (app.targets.button("Decide", 0, can))
    load_support(app, SupportChoice{s.chosen, s.by, s.reason, s.changes});
}

}  // namespace

void draw_support_view(AppState& app) {
  SupportViewState& s = app.blocks.support;
  if (!app.session) return;
  if (s.file != app.session->file() || s.visit != app.session->visit()) {
    s.file = app.session->file();
    s.visit = app.session->visit();
    s.requested = false;
    s.proposals.reset();
    s.message.clear();
    s.chosen.clear();
    s.reason.clear();
    s.changes.clear();
  }
  heading("Support of this round");
  if (!app.services.support) {
    note("No support workflow in this build.");
    return;
  }
  if (!app.session->visit()) return;
  if (!s.requested && !app.task.running()) {
    s.requested = true;
    load_support(app, std::nullopt);
  }
  if (app.targets.button("Read again", 0, !app.task.running())) load_support(app, std::nullopt);
  if (!s.message.empty()) paragraph(s.message);
  if (!s.proposals) return;
  draw_proposals(app, *s.proposals);
  draw_decision(app, s, *s.proposals);
}

}  // namespace rockface::ui

#include "ui/blocks/wedges_view.h"

#include <memory>

#include <imgui.h>

#include "ui/app/app_state.h"
#include "ui/widgets/format.h"
#include "ui/widgets/toggle_button.h"
#include "ui/widgets/widgets_table.h"

namespace rockface::ui {

namespace {

void find_wedges(AppState& app) {
  WedgeRunner* runner = app.services.wedges;
  const auto file = app.session->file();
  const auto visit = *app.session->visit();
  const WedgeForm form = app.blocks.wedges.form.form();
  auto result = std::make_shared<WedgeTable>();
  app.task.start(
      "Wedges",
      [runner, file, visit, form, result](Progress& progress) {
        *result = runner->wedges(file, visit, form, progress);
        return std::to_string(result->rows.size()) + " wedges around the excavation";
      },
      [&app, result](const TaskOutcome& outcome) {
        WedgesState& w = app.blocks.wedges;
        if (outcome.kind != TaskOutcome::Kind::done) {
          w.table.reset();
          w.picture.clear();
          w.message = outcome.message;
          return;
        }
        w.message.clear();
        w.picture.set(result->bgr);
        result->bgr.release();
        w.table = std::move(*result);
      });
}

void draw_wedge_table(AppState& app, const WedgeTable& t) {
  const ImGuiTableFlags flags =
      ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchSame;
  if (!ImGui::BeginTable("wedges", static_cast<int>(t.columns.size()), flags)) return;
  for (const auto& c : t.columns) ImGui::TableSetupColumn(c.c_str());
  table_headers_row();
  const float row_height = app.targets.target_px();
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    ImGui::TableNextRow(0, row_height);
    if (i < t.marginal.size() && t.marginal[i])
      ImGui::TableSetBgColor(ImGuiTableBgTarget_RowBg0, IM_COL32(255, 200, 120, 255));
    for (std::size_t c = 0; c < t.rows[i].size(); ++c) {
      ImGui::TableNextColumn();
      label(t.rows[i][c]);
      if (c == 0)
        app.targets.record_area("wedge " + t.rows[i][0], ImGui::GetItemRectMin(),
                                ImGui::GetItemRectMax());
    }
  }
  ImGui::EndTable();
}

// One field of the form: its toggle (which field the keypad types into)
// and what is typed, with its unit.
void wedge_form_field(AppState& app, WedgeFormState& f, WedgeField which, const char* name,
                      const char* unit) {
  if (toggle_button(app.targets, name, f.typing == which)) {
    f.typing = which;
    f.field(which).clear();
  }
  ImGui::SameLine();
  const std::string& typed = f.field(which).text();
  label_in_row(typed.empty() ? std::string("not given") : typed + " " + unit);
}

void draw_wedge_form(AppState& app) {
  WedgeFormState& f = app.blocks.wedges.form;
  paragraph(
      "Friction of every joint (empty: each joint's own, else 30°) and the support the wedges "
      "are checked with, as rockface wedges --friction --bolts --shotcrete takes them.");
  wedge_form_field(app, f, WedgeField::friction, "Friction", "°");
  wedge_form_field(app, f, WedgeField::bolt_length, "Bolt length", "m");
  wedge_form_field(app, f, WedgeField::bolt_spacing, "Bolt spacing", "m");
  wedge_form_field(app, f, WedgeField::bolt_capacity, "Bolt capacity", "kN");
  wedge_form_field(app, f, WedgeField::shotcrete_thickness, "Shotcrete thickness", "mm");
  wedge_form_field(app, f, WedgeField::shotcrete_shear, "Shotcrete shear strength", "MPa");
  if (const auto k = draw_keypad(app.targets)) f.field(f.typing).key(*k);
  if (app.targets.button("Clear the form")) f.clear();
  note(
      "Not stored with the visit (the project has no place for it): kept while the tablet "
      "runs.");
}

}  // namespace

TypedNumber& WedgeFormState::field(WedgeField f) {
  switch (f) {
    case WedgeField::friction:
      return friction;
    case WedgeField::bolt_length:
      return bolt_length;
    case WedgeField::bolt_spacing:
      return bolt_spacing;
    case WedgeField::bolt_capacity:
      return bolt_capacity;
    case WedgeField::shotcrete_thickness:
      return shotcrete_thickness;
    case WedgeField::shotcrete_shear:
      return shotcrete_shear;
  }
  return friction;
}

WedgeForm WedgeFormState::form() const {
  WedgeForm out;
  if (!friction.text().empty()) out.friction_deg = friction.value();
  if (!bolt_length.text().empty() && !bolt_spacing.text().empty() && !bolt_capacity.text().empty())
    out.bolts = WedgeBoltsForm{bolt_length.value(), bolt_spacing.value(), bolt_capacity.value()};
  if (!shotcrete_thickness.text().empty() && !shotcrete_shear.text().empty())
    out.shotcrete = WedgeShotcreteForm{shotcrete_thickness.value(), shotcrete_shear.value()};
  return out;
}

std::string WedgeFormState::problem() const {
  const int bolts =
      !bolt_length.text().empty() + !bolt_spacing.text().empty() + !bolt_capacity.text().empty();
  if (bolts > 0 && bolts < 3) return "Bolts: type the length, the spacing and the capacity.";
  const int shotcrete = !shotcrete_thickness.text().empty() + !shotcrete_shear.text().empty();
  if (shotcrete == 1) return "Shotcrete: type the thickness and the shear strength.";
  return {};
}

void WedgeFormState::clear() {
  for (auto* t : {&friction, &bolt_length, &bolt_spacing, &bolt_capacity, &shotcrete_thickness,
                  &shotcrete_shear})
    t->clear();
  typing = WedgeField::friction;
}

void draw_wedges_view(AppState& app) {
  WedgesState& w = app.blocks.wedges;
  if (!app.session) return;
  if (w.file != app.session->file() || w.visit != app.session->visit()) {
    w.file = app.session->file();
    w.visit = app.session->visit();
    w.table.reset();
    w.message.clear();
    w.picture.clear();
  }
  const std::string problem = w.form.problem();
  const bool can =
      app.services.wedges && app.session->visit() && !app.task.running() && problem.empty();
  if (app.targets.button_in_row("Find wedges", can)) find_wedges(app);
  ImGui::SameLine();
  if (toggle_button(app.targets, "Friction and support", w.form.open)) w.form.open = !w.form.open;
  if (w.form.open) draw_wedge_form(app);
  if (!problem.empty()) paragraph(problem);
  paragraph(
      "Wedges that the visit's sets form around the tunnel's design section, "
      "each at its largest (joints of unlimited persistence).");
  if (!app.services.wedges) note("No wedge analysis in this build.");
  if (!w.message.empty()) paragraph(w.message);
  if (!w.table) return;
  const WedgeTable& t = *w.table;
  for (const auto& line : t.lines) paragraph(line);
  const SplitLayout layout = split_for_side_panel(0.4f * ImGui::GetContentRegionAvail().x);
  ImGui::BeginChild("wedge table", layout.main);
  if (t.rows.empty())
    paragraph("No removable wedge.");
  else
    draw_wedge_table(app, t);
  for (const auto& n : t.notes) paragraph(n);
  ImGui::EndChild();
  begin_side_panel("wedge picture", layout, true);
  w.picture.draw(ImGui::GetContentRegionAvail().x);
  ImGui::EndChild();
}

}  // namespace rockface::ui

// The Mapping screen's compass reading (issue 27): a geologist holds a Clar
// compass on the exposed joint where a trace runs and types the dip and dip
// direction read, on keys a gloved thumb hits (9 mm).
#include "ui/mapping/mapping_compass.h"

#include <algorithm>
#include <vector>

#include "ui/app/screens.h"
#include "ui/widgets/format.h"
#include "ui/widgets/keypad.h"
#include "ui/widgets/toggle_button.h"
#include "ui/widgets/widgets_controls.h"
#include "ui/widgets/widgets_text.h"

namespace rockface::ui {

namespace {

using Field = CompassEntry::Field;

std::vector<const storage::Measurement*> saved_traces(const ProjectSession& session) {
  std::vector<const storage::Measurement*> out;
  for (const auto& m : session.measurements())
    if (m.kind == storage::Measurement::Kind::trace) out.push_back(&m);
  return out;
}

std::string reading_words(const measure::CompassReading& r) {
  return format::dip_and_direction(r.dip_deg, r.dip_direction_deg);
}

// One field: its button (the keypad types into the field chosen) and its
// value with - / + steps of a degree.
void draw_field(AppState& app, const std::string& label, Field field) {
  CompassEntry& e = app.mapping.compass;
  // Tapped again, the field is typed afresh.
  if (toggle_button(app.targets, label, e.typing() == field)) e.choose(field);
  ImGui::SameLine();
  double* value = e.value(field);
  double stepped = *value;
  if (number_field(app.targets, "Compass " + label, &stepped, "%.1f°",
                   ImGui::GetContentRegionAvail().x, 1.0))
    e.set(field, stepped);
}

// Save reading / Clear reading of a saved trace: stored at once by the
// map's runner; each that replaces or drops a stored reading asks first.
void draw_saved_trace_actions(AppState& app, const storage::Measurement& trace) {
  CompassEntry& e = app.mapping.compass;
  const bool can = !app.task.running() && !app.session->read_only() && app.services.trace_map;
  const auto stored = compass_of(trace);
  const auto reading = e.reading();
  auto store = [&](std::optional<measure::CompassReading> r, const std::string& title) {
    MapEdit edit = map_edit(app);
    edit.compass_trace = trace.id;
    edit.compass = r;
    store_map_edit(app, std::move(edit), title, [](AppState& a) { a.mapping.compass.clear(); });
  };
  const bool save_enabled = can && reading.has_value();
  if (stored && reading) {
    if (app.targets.confirmed_button("Save reading",
                                     "Replace " + trace.label + "'s reading " +
                                         reading_words(*stored) + " with " +
                                         reading_words(*reading) + "?",
                                     save_enabled))
      store(reading, "Saving the compass reading of " + trace.label);
  } else if (app.targets.button("Save reading", 0, save_enabled)) {
    store(reading, "Saving the compass reading of " + trace.label);
  }
  same_line_if_fits(button_width("Clear reading", app.targets.target_px()));
  if (app.targets.confirmed_button("Clear reading",
                                   "Clear " + trace.label + "'s compass reading? Its joint then " +
                                       "comes from the trace alone, or goes.",
                                   can && stored.has_value()))
    store(std::nullopt, "Clearing the compass reading of " + trace.label);
  if (stored && !trace.note.empty()) paragraph(trace.label + ": " + trace.note);
}

}  // namespace

void draw_compass_button(AppState& app) {
  same_line_if_fits(button_width("Compass", app.targets.target_px()));
  if (app.targets.button("Compass")) {
    CompassEntry& e = app.mapping.compass;
    e.open = true;
    if (e.typing() == Field::none) e.choose(Field::dip);
  }
}

bool draw_compass_panel(AppState& app) {
  CompassEntry& e = app.mapping.compass;
  if (!e.open || app.mapping.outlining) return false;
  const bool marking = !app.mapping.marker.taps().empty();
  const storage::Measurement* trace = nullptr;
  if (marking) {
    // The trace being marked takes the reading: one for a saved trace goes.
    if (e.trace) {
      e.clear();
      e.trace.reset();
      e.choose(Field::dip);
    }
    paragraph("Compass reading of the trace being marked, saved with it:");
  } else {
    const auto traces = saved_traces(*app.session);
    if (traces.empty() || !app.services.trace_map) {
      paragraph(
          "Mark a trace, or save one, to give it the dip and dip direction read with a "
          "compass on its joint.");
      if (app.targets.button("Done")) e.open = false;
      return true;
    }
    auto found = std::find_if(traces.begin(), traces.end(),
                              [&](const auto* m) { return e.trace && m->id == *e.trace; });
    if (found == traces.end()) {  // the newest saved trace, at first
      found = traces.end() - 1;
      e.clear();
      e.trace = (*found)->id;
    }
    std::vector<std::string> items;
    for (const auto* m : traces) items.push_back("Trace " + m->label);
    const auto at = static_cast<std::size_t>(found - traces.begin());
    if (const auto chosen = choice(app.targets, "Compass trace", items[at], items, at);
        chosen && *chosen != at) {
      e.clear();
      e.trace = traces[*chosen]->id;
      found = traces.begin() + static_cast<std::ptrdiff_t>(*chosen);
    }
    trace = *found;
    // Until the geologist types, the fields show the trace's stored reading.
    if (!e.given()) {
      const auto id = e.trace;
      const auto field = e.typing();
      if (const auto r = compass_of(*trace))
        e.show(*r);
      else
        e.clear();
      e.trace = id;
      e.choose(field == Field::none ? Field::dip : field);
    }
  }
  draw_field(app, "Dip", Field::dip);
  draw_field(app, "Dip direction", Field::dip_direction);
  if (e.given() && !e.problem().empty()) paragraph(e.problem(), warning_colour());
  if (trace) {
    draw_saved_trace_actions(app, *trace);
  } else {
    const bool can_save = !app.task.running() && app.mapping.marker.points().size() >= 2 &&
                          app.session->visit() && !app.session->read_only();
    if (app.targets.button("Save trace", 0, can_save)) save_trace(app);
    same_line_if_fits(button_width("Clear reading", app.targets.target_px()));
    if (app.targets.button("Clear reading", 0, e.given())) {
      e.clear();
      e.choose(Field::dip);
    }
  }
  same_line_if_fits(button_width("Done", app.targets.target_px()));
  if (app.targets.button("Done")) e.open = false;
  if (const auto k = draw_keypad(app.targets)) app.mapping.compass.key(*k);
  return true;
}

bool attach_compass_reading(AppState& app, storage::Measurement& m) {
  const CompassEntry& e = app.mapping.compass;
  if (e.trace || !e.given()) return true;
  if (!e.problem().empty()) {
    app.fail(e.problem());
    return false;
  }
  m.compass_dip_deg = e.dip();
  m.compass_dipdir_deg = e.dip_direction() == 360 ? 0.0 : e.dip_direction();  // both north
  return true;
}

}  // namespace rockface::ui

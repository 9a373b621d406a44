#pragma once
// The Mapping screen's compass reading (issue 27): dip and dip direction
// typed on a keypad of thumb-sized keys (the tablet has no keyboard, and a
// gloved hand does not hit a phone keyboard's keys), for the trace being
// marked or a saved trace. What is typed, and whether it is a reading a
// compass gives; the screen draws it (ui/mapping/mapping_compass.h).
#include <optional>
#include <string>

#include "core/measure/compass_reading.h"
#include "storage/project/project_records.h"
#include "ui/widgets/keypad.h"

namespace rockface::ui {

class CompassEntry {
 public:
  enum class Field { none, dip, dip_direction };

  // The field the keypad types into; choosing one starts it afresh (the
  // first key replaces the value shown, as on a calculator).
  void choose(Field field);
  Field typing() const { return typing_; }
  // A key of the keypad: '0'..'9', '.', or '\b' (take the last one back).
  void key(char c);
  // A value set by the field's - / + steps.
  void set(Field field, double value);
  double dip() const { return dip_; }
  double dip_direction() const { return dip_direction_; }
  double* value(Field field) { return field == Field::dip ? &dip_ : &dip_direction_; }
  // A reading was typed (or stepped) since the entry was cleared.
  bool given() const { return given_; }
  // Why the values are no compass reading ("Dip 95.0° is outside 0–90°"),
  // empty when they are one.
  std::string problem() const;
  // The reading, when given and a reading.
  std::optional<measure::CompassReading> reading() const;
  // The values of a saved reading (shown to be edited), not yet given again.
  void show(const measure::CompassReading& r);
  void clear();

  // The saved trace the reading is for; none: the trace being marked.
  std::optional<storage::RecordId> trace;
  // The Mapping screen shows the compass panel.
  bool open = false;

 private:
  double dip_ = 0, dip_direction_ = 0;
  Field typing_ = Field::none;
  TypedNumber typed_{5};  // digits a reading needs: "359.9" (and a dip "90.0")
  bool given_ = false;
};

// A stored trace's reading, when it has one.
std::optional<measure::CompassReading> compass_of(const storage::Measurement& m);

}  // namespace rockface::ui

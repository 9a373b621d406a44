#include "ui/mapping/compass_entry.h"

#include <cmath>

#include "ui/widgets/format.h"

namespace rockface::ui {

void CompassEntry::choose(Field field) {
  typing_ = field;
  typed_.clear();
}

void CompassEntry::key(char c) {
  if (typing_ == Field::none || !typed_.key(c)) return;
  *value(typing_) = typed_.value();
  given_ = true;
}

void CompassEntry::set(Field field, double v) {
  *value(field) = v;
  typed_.clear();
  given_ = true;
}

std::string CompassEntry::problem() const {
  if (!(dip_ >= 0 && dip_ <= 90))
    return "Dip " + format::text(format::Angle{dip_}) + " is outside 0–90°: type it again.";
  if (!(dip_direction_ >= 0 && dip_direction_ <= 360))
    return "Dip direction " + format::text(format::Angle{dip_direction_}) +
           " is outside 0–360°: type it again.";
  return {};
}

std::optional<measure::CompassReading> CompassEntry::reading() const {
  if (!given_ || !problem().empty()) return std::nullopt;
  return measure::CompassReading{dip_, dip_direction_};
}

void CompassEntry::show(const measure::CompassReading& r) {
  dip_ = r.dip_deg;
  dip_direction_ = r.dip_direction_deg;
  typing_ = Field::none;
  typed_.clear();
  given_ = false;
}

void CompassEntry::clear() {
  dip_ = dip_direction_ = 0;
  typing_ = Field::none;
  typed_.clear();
  given_ = false;
}

std::optional<measure::CompassReading> compass_of(const storage::Measurement& m) {
  if (!m.compass_dip_deg || !m.compass_dipdir_deg) return std::nullopt;
  return measure::CompassReading{*m.compass_dip_deg, *m.compass_dipdir_deg};
}

}  // namespace rockface::ui

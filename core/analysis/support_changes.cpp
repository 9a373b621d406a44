#include "core/analysis/support_changes.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <optional>

#include "core/common/error.h"
#include "core/common/number_format.h"

namespace rockface::analysis {

namespace {

enum class ChangeQuantity { length, force, stress };

struct ChangeUnit {
  const char* name;
  double scale;  // to SI
};

const std::vector<ChangeUnit>& change_units_of(ChangeQuantity q) {
  static const std::vector<ChangeUnit> length{{"m", 1.0}, {"cm", 0.01}, {"mm", 0.001}};
  static const std::vector<ChangeUnit> force{{"N", 1.0}, {"kN", 1e3}, {"MN", 1e6}};
  static const std::vector<ChangeUnit> stress{{"Pa", 1.0}, {"kPa", 1e3}, {"MPa", 1e6}};
  switch (q) {
    case ChangeQuantity::length:
      return length;
    case ChangeQuantity::force:
      return force;
    case ChangeQuantity::stress:
      return stress;
  }
  return length;
}

const char* change_quantity_words(ChangeQuantity q) {
  switch (q) {
    case ChangeQuantity::length:
      return "a length (m, cm or mm)";
    case ChangeQuantity::force:
      return "a force (N, kN or MN)";
    case ChangeQuantity::stress:
      return "a strength (Pa, kPa or MPa)";
  }
  return "";
}

std::string lower_case(std::string s) {
  for (char& ch : s) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return s;
}

std::string trim_typed(const std::string& s) {
  const auto a = s.find_first_not_of(" \t");
  if (a == std::string::npos) return "";
  return s.substr(a, s.find_last_not_of(" \t") - a + 1);
}

// "bolt  Length" -> "bolt length".
std::string normalised_change_name(const std::string& s) {
  std::string out;
  for (char ch : lower_case(trim_typed(s))) {
    if (ch == '\t') ch = ' ';
    if (ch == ' ' && !out.empty() && out.back() == ' ') continue;
    out += ch;
  }
  return out;
}

bool typed_none(const std::string& s) {
  return lower_case(trim_typed(s)) == "none";
}

// A figure as typed: its value in SI units, half its last typed digit
// (what "as typed" can be off by when it is the class's value rounded),
// and the unit it was typed in (to say the class's value in it).
struct TypedFigure {
  double value = 0;
  double tolerance = 0;
  ChangeUnit unit{"", 1.0};
};

// Refusals of one change, with its number and WHAT.
struct RefuseChange {
  std::string where, change;
  [[noreturn]] void operator()(const std::string& why) const {
    throw InputError(where, change + ": " + why);
  }
};

TypedFigure parse_typed_figure(const std::string& typed, ChangeQuantity q,
                               const RefuseChange& refuse) {
  const std::string text = trim_typed(typed);
  std::size_t end = 0;
  while (end < text.size() &&
         (std::isdigit(static_cast<unsigned char>(text[end])) || text[end] == '.' ||
          text[end] == ',' || (end == 0 && (text[end] == '+' || text[end] == '-'))))
    ++end;
  std::string number = text.substr(0, end);
  std::replace(number.begin(), number.end(), ',', '.');  // a decimal comma
  TypedFigure f;
  const auto [ptr, ec] = std::from_chars(number.data(), number.data() + number.size(), f.value);
  if (number.empty() || ec != std::errc() || ptr != number.data() + number.size() ||
      !std::isfinite(f.value))
    refuse("\"" + text + "\" is not a figure: write it as a number and its unit (" +
           change_quantity_words(q) + ")");
  const std::string unit = trim_typed(text.substr(end));
  if (unit.empty())
    refuse("\"" + text + "\" has no unit: " + change_quantity_words(q) + " is expected");
  const auto& units = change_units_of(q);
  const auto found = std::find_if(units.begin(), units.end(), [&](const ChangeUnit& u) {
    return lower_case(u.name) == lower_case(unit);
  });
  if (found == units.end()) {
    for (ChangeQuantity other :
         {ChangeQuantity::length, ChangeQuantity::force, ChangeQuantity::stress})
      for (const ChangeUnit& u : change_units_of(other))
        if (lower_case(u.name) == lower_case(unit))
          refuse("\"" + text + "\" is " + change_quantity_words(other) + ", not " +
                 change_quantity_words(q));
    refuse("\"" + unit + "\" is not a unit of " + change_quantity_words(q));
  }
  const auto point = number.find('.');
  const int decimals = point == std::string::npos ? 0 : static_cast<int>(number.size() - point - 1);
  f.unit = *found;
  f.value *= found->scale;
  f.tolerance = 0.5 * std::pow(10.0, -decimals) * found->scale;
  return f;
}

std::string figure_in_unit(double si, const ChangeUnit& u) {
  return format_significant(si / u.scale, 4, std::string(" ") + u.name);
}

// FROM against what the pattern gives (none: the pattern has none).
void require_class_gives(const std::string& from, ChangeQuantity q,
                         const std::optional<double>& given, const RefuseChange& refuse) {
  if (typed_none(from)) {
    if (given)
      refuse("the class gives " + figure_in_unit(*given, change_units_of(q).front()) +
             ", not none");
    return;
  }
  const TypedFigure f = parse_typed_figure(from, q, refuse);
  if (!given) refuse("the class gives none, not " + trim_typed(from));
  // A relative 1e-9 for what a class file's number holds after its unit's scaling.
  if (std::abs(f.value - *given) > f.tolerance + 1e-9 * std::abs(*given))
    refuse("the class gives " + figure_in_unit(*given, f.unit) + ", not " + trim_typed(from));
}

double require_in_range(double v, const tunnel::SupportRange& range, const char* what,
                        const RefuseChange& refuse) {
  if (!range.contains(v)) refuse(tunnel::outside_range_text(v, range, what));
  return v;
}

// "4 m at 1.5 m, 150 kN"; the capacity kept from `kept` when left out.
BoltPattern parse_bolt_pattern(const std::string& typed, const std::optional<BoltPattern>& kept,
                               const RefuseChange& refuse) {
  const std::string text = trim_typed(typed);
  const std::string form =
      "write the pattern as \"LENGTH at SPACING, CAPACITY\" (4 m at 1.5 m, "
      "150 kN)";
  const auto at = lower_case(text).find(" at ");
  if (at == std::string::npos) refuse("\"" + text + "\" gives no spacing: " + form);
  std::string rest = text.substr(at + 4);
  std::string capacity;
  for (const char* sep : {", ", ";"}) {
    const auto s = rest.find(sep);
    if (s != std::string::npos) {
      capacity = rest.substr(s + std::string(sep).size());
      rest = rest.substr(0, s);
      break;
    }
  }
  BoltPattern b;
  if (kept) b = *kept;
  b.length_m =
      require_in_range(parse_typed_figure(text.substr(0, at), ChangeQuantity::length, refuse).value,
                       tunnel::kBoltLengthRange, "a bolt's length", refuse);
  b.spacing_m = require_in_range(parse_typed_figure(rest, ChangeQuantity::length, refuse).value,
                                 tunnel::kBoltSpacingRange, "a bolt pattern's spacing", refuse);
  if (!trim_typed(capacity).empty())
    b.capacity_n =
        require_in_range(parse_typed_figure(capacity, ChangeQuantity::force, refuse).value,
                         tunnel::kBoltCapacityRange, "a bolt's capacity", refuse);
  else if (!kept)
    refuse("\"" + text +
           "\" gives no capacity and the class has no bolts to keep it from: " + form);
  return b;
}

void require_class_pattern(const std::string& from, const std::optional<BoltPattern>& given,
                           const RefuseChange& refuse) {
  if (typed_none(from) || !given) {
    require_class_gives(from, ChangeQuantity::length,
                        given ? std::optional<double>(given->length_m) : std::nullopt, refuse);
    return;
  }
  const std::string text = trim_typed(from);
  const auto at = lower_case(text).find(" at ");
  if (at == std::string::npos)
    refuse("\"" + text + "\" gives no spacing: write the class's pattern as \"LENGTH at SPACING\"");
  std::string rest = text.substr(at + 4), capacity;
  for (const char* sep : {", ", ";"}) {
    const auto s = rest.find(sep);
    if (s != std::string::npos) {
      capacity = rest.substr(s + std::string(sep).size());
      rest = rest.substr(0, s);
      break;
    }
  }
  require_class_gives(text.substr(0, at), ChangeQuantity::length, given->length_m, refuse);
  require_class_gives(rest, ChangeQuantity::length, given->spacing_m, refuse);
  if (!trim_typed(capacity).empty())
    require_class_gives(capacity, ChangeQuantity::force, given->capacity_n, refuse);
}

// A text field: FROM as the class words it (any case), "none" for empty.
void change_text_field(std::string& field, const SupportChange& ch, const RefuseChange& refuse) {
  const std::string from = typed_none(ch.from) ? "" : lower_case(trim_typed(ch.from));
  if (from != lower_case(trim_typed(field)))
    refuse("the class gives \"" + (field.empty() ? std::string("none") : field) + "\", not \"" +
           trim_typed(ch.from) + "\"");
  field = typed_none(ch.to) ? "" : trim_typed(ch.to);
}

std::optional<double> figure_if_given(double v) {
  return v > 0 ? std::optional<double>(v) : std::nullopt;
}

struct BoltFigure {
  double* value;
  ChangeQuantity quantity;
  tunnel::SupportRange range;
  const char* range_words;
};

// The bolt figure a WHAT names on one pattern (bolts or face bolts).
void change_bolt_figure(std::optional<BoltPattern>& bolts, const std::string& figure,
                        const std::string& pattern_name, const SupportChange& ch,
                        const RefuseChange& refuse) {
  if (!bolts)
    refuse("the class has no " + pattern_name + ": add them with \"" + pattern_name +
           ": none -> LENGTH at SPACING, CAPACITY\"");
  BoltFigure f{&bolts->length_m, ChangeQuantity::length, tunnel::kBoltLengthRange,
               "a bolt's length"};
  if (figure == "spacing")
    f = {&bolts->spacing_m, ChangeQuantity::length, tunnel::kBoltSpacingRange,
         "a bolt pattern's spacing"};
  if (figure == "capacity")
    f = {&bolts->capacity_n, ChangeQuantity::force, tunnel::kBoltCapacityRange,
         "a bolt's capacity"};
  require_class_gives(ch.from, f.quantity, *f.value, refuse);
  if (typed_none(ch.to))
    refuse("a pattern's " + figure + " cannot be none: change \"" + pattern_name +
           ": ... -> none\" to take the bolts away");
  *f.value = require_in_range(parse_typed_figure(ch.to, f.quantity, refuse).value, f.range,
                              f.range_words, refuse);
}

void change_thickness(double& thickness, const SupportChange& ch, const RefuseChange& refuse) {
  require_class_gives(ch.from, ChangeQuantity::length, figure_if_given(thickness), refuse);
  thickness =
      typed_none(ch.to)
          ? 0.0
          : require_in_range(parse_typed_figure(ch.to, ChangeQuantity::length, refuse).value,
                             kShotcreteThicknessRange, "shotcrete's thickness", refuse);
}

void apply_change(SupportClass& c, const SupportChange& ch, const std::string& name,
                  const RefuseChange& refuse, std::vector<std::string>& notes) {
  const auto not_checked = [&](const std::string& what) {
    notes.push_back(what + " changed to " + trim_typed(ch.to) +
                    ": applied to the pattern; the wedge and block check does not use it");
  };
  if (name == "round length") {
    require_class_gives(ch.from, ChangeQuantity::length, c.round_length_m, refuse);
    if (typed_none(ch.to)) refuse("a round has a length");
    c.round_length_m =
        require_in_range(parse_typed_figure(ch.to, ChangeQuantity::length, refuse).value,
                         kRoundLengthRange, "a round's length", refuse);
    not_checked("the round length");
  } else if (name == "bolts" || name == "face bolts") {
    std::optional<BoltPattern>& bolts = name == "bolts" ? c.bolts : c.face.bolts;
    require_class_pattern(ch.from, bolts, refuse);
    if (typed_none(ch.to))
      bolts.reset();
    else
      bolts = parse_bolt_pattern(ch.to, bolts, refuse);
  } else if (name == "bolt length" || name == "bolt spacing" || name == "bolt capacity") {
    change_bolt_figure(c.bolts, name.substr(5), "bolts", ch, refuse);
  } else if (name == "face bolt length" || name == "face bolt spacing" ||
             name == "face bolt capacity") {
    change_bolt_figure(c.face.bolts, name.substr(10), "face bolts", ch, refuse);
  } else if (name == "shotcrete" || name == "shotcrete thickness") {
    change_thickness(c.shotcrete_m, ch, refuse);
  } else if (name == "face shotcrete" || name == "face shotcrete thickness") {
    change_thickness(c.face.shotcrete_m, ch, refuse);
  } else if (name == "shotcrete shear strength") {
    require_class_gives(ch.from, ChangeQuantity::stress, c.shotcrete_shear_pa, refuse);
    if (typed_none(ch.to))
      c.shotcrete_shear_pa.reset();
    else
      c.shotcrete_shear_pa =
          require_in_range(parse_typed_figure(ch.to, ChangeQuantity::stress, refuse).value,
                           kShotcreteShearRange, "shotcrete's shear strength", refuse);
  } else if (name == "mesh") {
    change_text_field(c.mesh, ch, refuse);
    not_checked("the mesh");
  } else if (name == "steel sets") {
    change_text_field(c.steel_sets, ch, refuse);
    not_checked("the steel sets");
  } else if (name == "face support") {
    change_text_field(c.face.words, ch, refuse);
    not_checked("the face support's words");
  } else {
    std::string names;
    for (const auto& n : support_change_names()) names += (names.empty() ? "" : ", ") + n;
    refuse("not a change the check can apply; changes name one of: " + names);
  }
}

}  // namespace

const std::vector<std::string>& support_change_names() {
  static const std::vector<std::string> names = {"round length",
                                                 "bolts",
                                                 "bolt length",
                                                 "bolt spacing",
                                                 "bolt capacity",
                                                 "shotcrete",
                                                 "shotcrete thickness",
                                                 "shotcrete shear strength",
                                                 "mesh",
                                                 "steel sets",
                                                 "face bolts",
                                                 "face bolt length",
                                                 "face bolt spacing",
                                                 "face bolt capacity",
                                                 "face shotcrete",
                                                 "face shotcrete thickness",
                                                 "face support"};
  return names;
}

ChangedPattern apply_support_changes(const SupportClass& c,
                                     const std::vector<SupportChange>& changes,
                                     const std::string& where) {
  ChangedPattern out;
  out.pattern = c;
  for (std::size_t i = 0; i < changes.size(); ++i) {
    const RefuseChange refuse{where,
                              "change " + std::to_string(i + 1) + " (\"" + changes[i].what + "\")"};
    apply_change(out.pattern, changes[i], normalised_change_name(changes[i].what), refuse,
                 out.notes);
  }
  const SupportClass& p = out.pattern;
  if ((p.shotcrete_m > 0 || p.face.shotcrete_m > 0) && !p.shotcrete_shear_pa)
    out.notes.push_back(
        "shotcrete is not counted on the wedges: the pattern gives no shear strength (change "
        "\"shotcrete shear strength: none -> 1 MPa\")");
  return out;
}

}  // namespace rockface::analysis

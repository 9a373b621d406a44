#pragma once
// One line of a classification sheet: the parameter, the value it was rated
// on, its rating, where the value came from and which table rated it.
#include <optional>
#include <string>
#include <vector>

namespace rockface::rockmass {

enum class Source {
  measured,     // from the visit's traces, sets and blocks
  entered,      // typed on the form (or the scene's rockmass section)
  mixed,        // parts measured, parts entered (RMR89's joint condition)
  not_entered,  // neither: the line is open and the total incomplete
};
const char* words(Source s);  // "measured", "entered", "measured + entered", "not entered"

struct Rating {
  std::string parameter;         // "RQD", "Jn", "strength of intact rock", ...
  std::optional<double> value;   // the value rated, in `unit`
  std::string unit;              // "%", "m", "MPa", "" (a number of the table)
  std::string value_words;       // what was rated in words ("3 sets + random", "damp")
  std::optional<double> rating;  // nullopt when not entered
  Source source = Source::not_entered;
  std::string table;  // "Bieniawski 1989, Table A.2", ...
  std::string note;   // e.g. the entered value beside a measured one
};

// A classification's sum: complete only when every line is rated. When
// lines are open, `partial` sums the rated ones and [lowest, highest] is
// what the open lines could still make of it (so that no total pretends to
// be complete).
struct Total {
  std::optional<double> value;
  double partial = 0, lowest = 0, highest = 0;
  std::vector<std::string> missing;  // the open lines' parameters
};

}  // namespace rockface::rockmass

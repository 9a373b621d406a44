#include "core/measure/pair_photo.h"

namespace rockface::measure {

std::string pair_photo(int pair, const std::string& side) {
  return pair == 1 ? side : "pair " + std::to_string(pair) + " " + side;
}

int pair_of_photo(const std::string& photo) {
  if (photo.rfind("pair ", 0) != 0) return 1;
  return std::stoi(photo.substr(5));
}

Picks picks_by_pair_photo(Picks picks) {
  for (auto& t : picks.traces)
    if (!t.photo.empty()) t.photo = pair_photo(t.pair, t.photo);
  for (auto& a : picks.areas) a.photo = pair_photo(a.pair, a.photo);
  for (auto& p : picks.points) p.photo = pair_photo(p.pair, p.photo);
  return picks;
}

}  // namespace rockface::measure

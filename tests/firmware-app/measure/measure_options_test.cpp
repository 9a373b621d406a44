// `rockface measure`'s options read into its request (measure_options.h):
// --sets as a count or "auto", --add-to-visit as the visit measured on, and
// each refusal naming the option at fault before any pick is read
// (--point-sigma and --friction are refused through the verb in
// tests/integration/cli_measure).
#include "firmware-app/measure/measure_options.h"

#include <string>

#include <gtest/gtest.h>

#include "core/common/error.h"

namespace rockface::app {
namespace {

// The option a refusal names; "(no refusal)" when none.
std::string refusal_of(const MeasureOptions& o) {
  try {
    measure_request(o);
  } catch (const InputError& e) {
    return e.where();
  }
  return "(no refusal)";
}

MeasureOptions on_a_project() {
  MeasureOptions o;
  o.request.on.source = "site.rockface";
  o.request.picks = "picks.json";
  o.request.out = "measures.json";
  return o;
}

TEST(MeasureOptions, SetsAreACountOrAuto) {
  MeasureOptions o = on_a_project();
  MeasureRequest r = measure_request(o);
  EXPECT_FALSE(r.sets) << "none given: the picks' own";
  EXPECT_FALSE(r.automatic_sets);

  o.sets = "auto";
  r = measure_request(o);
  EXPECT_FALSE(r.sets);
  EXPECT_TRUE(r.automatic_sets);

  for (const int count : {1, 3, 12}) {
    o.sets = std::to_string(count);
    r = measure_request(o);
    EXPECT_EQ(r.sets, count);
    EXPECT_FALSE(r.automatic_sets);
  }
  for (const char* bad : {"0", "13", "-1", "3x", "three", "2.5", "Auto"}) {
    o.sets = bad;
    EXPECT_EQ(refusal_of(o), "--sets") << bad;
  }
}

TEST(MeasureOptions, AddToVisitIsTheVisitMeasuredOnAndStandsAlone) {
  MeasureOptions o = on_a_project();
  o.add_to_visit = 4;
  const MeasureRequest r = measure_request(o);
  EXPECT_EQ(r.on.visit, storage::RecordId{4});
  EXPECT_TRUE(r.add_to_visit);
  EXPECT_EQ(r.picks, "picks.json");

  o.request.on.visit = 3;
  EXPECT_EQ(refusal_of(o), "--add-to-visit") << "with --visit";
  o.request.on.visit.reset();
  o.request.on.model = 9;
  EXPECT_EQ(refusal_of(o), "--add-to-visit") << "with --model";

  o = on_a_project();
  o.request.on.visit = 3;
  EXPECT_FALSE(measure_request(o).add_to_visit) << "--visit alone stores a new visit";
}

// Issue 46: --geologist names the new visit's geologist, trimmed; a name
// the store would refuse, or one given with --add-to-visit (an existing
// visit's is named with `place --geologist`), is refused naming it.
TEST(MeasureOptions, GeologistNamesTheNewVisitsAndIsCheckedFirst) {
  MeasureOptions o = on_a_project();
  o.request.geologist = " O'Brien <b> ";
  EXPECT_EQ(measure_request(o).geologist, "O'Brien <b>");
  o.request.geologist = "Anna\nBerger";
  EXPECT_EQ(refusal_of(o), "--geologist") << "two lines";
  o.request.geologist = "Anna Berger";
  o.add_to_visit = 4;
  EXPECT_EQ(refusal_of(o), "--geologist") << "with --add-to-visit";
}

}  // namespace
}  // namespace rockface::app

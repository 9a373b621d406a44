// `rockface import`'s options read into its request (import_options.h): the
// points given as text, and each refusal naming the option at fault before
// any file is read.
#include "firmware-app/import/import_options.h"

#include <functional>
#include <string>

#include <gtest/gtest.h>

#include "core/common/error.h"

namespace rockface::app {
namespace {

// The option a refusal names, and its reason; "(no refusal)" when none.
std::string refusal_of(const ImportOptions& o, std::string* reason = nullptr) {
  try {
    import_request(o);
  } catch (const InputError& e) {
    if (reason) *reason = e.reason();
    return e.where();
  }
  return "(no refusal)";
}

ImportOptions cloud() {
  ImportOptions o;
  o.project = "site.rockface";
  o.file = "face.ply";
  return o;
}

TEST(ImportOptions, PointsAreReadAsTyped) {
  ImportOptions o = cloud();
  o.offset = "2600000.5,1200000.25,431";
  o.view_from = "-3, 4.5, 1e1";
  o.pole = "0,0,0,0.1,0.2,2";
  o.range_pole = 2.0;
  o.azimuth = 123.5;
  o.reference_line = "1,2,3,4,5,6";
  o.declination = -2.5;
  o.visit = 7;
  const ImportRequest r = import_request(o);
  EXPECT_EQ(r.file.string(), "face.ply");
  // The numbers as typed: a parsed decimal of at most 9 significant digits
  // is the double nearest it, so they compare exactly.
  ASSERT_TRUE(r.file_options.offset);
  EXPECT_EQ(*r.file_options.offset, Eigen::Vector3d(2600000.5, 1200000.25, 431));
  ASSERT_TRUE(r.view_from);
  EXPECT_EQ(*r.view_from, Eigen::Vector3d(-3, 4.5, 10));
  ASSERT_TRUE(r.pole);
  EXPECT_EQ(r.pole->lower, Eigen::Vector3d(0, 0, 0));
  EXPECT_EQ(r.pole->upper, Eigen::Vector3d(0.1, 0.2, 2));
  EXPECT_FALSE(r.find_pole);
  EXPECT_EQ(r.pole_length_m, 2.0);
  ASSERT_TRUE(r.north);
  EXPECT_EQ(r.north->from, Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(r.north->to, Eigen::Vector3d(4, 5, 6));
  EXPECT_EQ(r.north->azimuth_deg, 123.5);
  EXPECT_EQ(r.north->declination_deg, -2.5);
  EXPECT_EQ(r.visit, storage::RecordId{7});
}

TEST(ImportOptions, NothingGivenAsksNothingOfTheWorkflow) {
  const ImportRequest r = import_request(cloud());
  EXPECT_FALSE(r.file_options.offset);
  EXPECT_FALSE(r.view_from);
  EXPECT_FALSE(r.pole);
  EXPECT_FALSE(r.find_pole);
  EXPECT_FALSE(r.north);
  EXPECT_FALSE(r.visit) << "visit 0 is a new visit";
}

TEST(ImportOptions, PoleAutoIsFoundInTheCloud) {
  ImportOptions o = cloud();
  o.pole = "auto";
  const ImportRequest r = import_request(o);
  EXPECT_TRUE(r.find_pole);
  EXPECT_FALSE(r.pole);
}

TEST(ImportOptions, APointThatIsNotItsCountOfFiniteNumbersIsRefusedByName) {
  for (const char* bad :
       {"1,2", "1,2,3,4", "1,2,3,", "1,,3", "1,x,3", "1,2,3m", "1,nan,3", "1,inf,3", ""}) {
    ImportOptions o = cloud();
    o.view_from = bad;
    std::string reason;
    // An empty text is no option given.
    if (std::string(bad).empty()) {
      EXPECT_EQ(refusal_of(o), "(no refusal)");
      continue;
    }
    EXPECT_EQ(refusal_of(o, &reason), "--view-from") << bad;
    EXPECT_EQ(reason, "'" + std::string(bad) + "' is not three numbers E,N,Z");
  }
  ImportOptions o = cloud();
  o.pole = "0,0,0,0,0";
  std::string reason;
  EXPECT_EQ(refusal_of(o, &reason), "--pole");
  EXPECT_EQ(reason, "'0,0,0,0,0' is not six numbers X1,Y1,Z1,X2,Y2,Z2");
  o = cloud();
  o.offset = "1;2;3";
  EXPECT_EQ(refusal_of(o), "--offset");
}

TEST(ImportOptions, OptionsThatGoTogetherAreRefusedAlone) {
  ImportOptions o = cloud();
  o.range_pole = 2.0;
  EXPECT_EQ(refusal_of(o), "--range-pole") << "a length with no pole";

  o = cloud();
  o.pole = "0,0,0,0,0,2";
  o.azimuth = 90;
  EXPECT_EQ(refusal_of(o), "--reference-line") << "a bearing with no line";

  o = cloud();
  o.pole = "0,0,0,0,0,2";
  o.reference_line = "0,0,0,1,0,0";
  EXPECT_EQ(refusal_of(o), "--azimuth") << "a line with no bearing";

  o = cloud();
  o.pole = "0,0,0,0,0,2";
  o.declination = 2;
  EXPECT_EQ(refusal_of(o), "--declination") << "a declination with no bearing";
}

// Issue 46: --geologist names the new visit's geologist, trimmed; a name
// the store would refuse, or one given with --visit (an existing visit's
// is named with `place --geologist`), is refused naming it.
TEST(ImportOptions, GeologistNamesTheNewVisitsAndIsCheckedFirst) {
  ImportOptions o = cloud();
  o.geologist = " O'Brien <b> ";
  EXPECT_EQ(import_request(o).geologist, "O'Brien <b>");
  o.geologist = std::string(81, 'x');
  std::string reason;
  EXPECT_EQ(refusal_of(o, &reason), "--geologist") << "81 characters";
  EXPECT_NE(reason.find("at most 80"), std::string::npos) << reason;
  o.geologist = "Anna Berger";
  o.visit = 7;
  EXPECT_EQ(refusal_of(o), "--geologist") << "with --visit";
}

}  // namespace
}  // namespace rockface::app

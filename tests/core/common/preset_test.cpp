// The one decoder of preset names: the three names, and every other name
// (the empty one too) refused with the field named and the valid names listed.
#include "core/common/preset.h"

#include <gtest/gtest.h>

#include "core/common/error.h"

namespace rockface {
namespace {

TEST(Preset, TheThreeNamesRoundTrip) {
  for (const Preset p : {Preset::fast, Preset::standard, Preset::precise})
    EXPECT_EQ(parse_preset(preset_name(p), "where"), p) << preset_name(p);
  EXPECT_EQ(parse_preset("fast", "where"), Preset::fast);
  EXPECT_EQ(parse_preset("standard", "where"), Preset::standard);
  EXPECT_EQ(parse_preset("precise", "where"), Preset::precise);
}

// The message every boundary prints for a bad name.
std::string refusal(std::string_view name, const std::string& where) {
  try {
    parse_preset(name, where);
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), where);
    return e.what();
  }
  ADD_FAILURE() << "'" << name << "' was accepted";
  return {};
}

TEST(Preset, AnUnknownNameIsRefusedNamingTheFieldAndTheValidNames) {
  EXPECT_EQ(refusal("best", "analysis.preset"),
            "analysis.preset: unknown preset 'best' (fast | standard | precise)");
  // Names are exact: no case folding, no trimming.
  EXPECT_NE(refusal("Fast", "--preset").find("unknown preset 'Fast'"), std::string::npos);
  EXPECT_NE(refusal(" standard", "--preset").find("(fast | standard | precise)"),
            std::string::npos);
}

TEST(Preset, TheEmptyNameIsRefusedNotDefaulted) {
  EXPECT_EQ(refusal("", "--preset"), "--preset: no preset given (fast | standard | precise)");
}

}  // namespace
}  // namespace rockface

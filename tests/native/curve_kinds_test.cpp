// The table of curve kinds (curve_kinds.hpp): one entry per kind of curveParams.ts CurveKind, each
// with its constraints, and a tail exactly for the kinds that gather hair (ponytail, braid, bun).
#include "curve_kinds.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>

// Each test file is a namespace of its own: the build compiles several files as one (unity).
namespace curve_kinds_test {

using namespace hairsketch;

TEST(CurveKinds, EachKindCodeHasItsOwnEntryAndUnknownCodesNone) {
  // curveParams.ts CurveKind, written out here as the reference
  const struct {
    uint8_t code;
    const char* name;
    bool tail, reach, parting;
  } expected[] = {{0, "stream", false, true, false},
                  {1, "dividing", false, false, true},
                  {2, "ponytail", true, true, false},
                  {3, "braid", true, true, false},
                  {4, "bun", true, false, false}};
  std::set<const CurveKindDef*> seen;
  for (const auto& e : expected) {
    const CurveKindDef* k = curveKind(e.code);
    ASSERT_NE(k, nullptr) << e.name;
    EXPECT_EQ(uint8_t(k->code), e.code);
    EXPECT_EQ(std::string(k->name), e.name);
    EXPECT_NE(k->constraints, nullptr) << e.name;
    EXPECT_EQ(k->tail != nullptr, e.tail) << e.name;
    EXPECT_EQ(k->reach, e.reach) << e.name;
    EXPECT_EQ(k->parting, e.parting) << e.name;
    seen.insert(k);
  }
  EXPECT_EQ(seen.size(), 5u);
  EXPECT_EQ(curveKind(5), nullptr);
  EXPECT_EQ(curveKind(255), nullptr);
}

}  // namespace curve_kinds_test

// HairEngine::setSettings: the session's settings as one array (engine_settings.hpp). A wrong
// count or a non-finite value is refused and changes nothing; the fall entry sets natural fall.
#include <gtest/gtest.h>

#include <cmath>

#include "hair_engine.hpp"

// Each test file is a namespace of its own: the build compiles several files as one (unity).
namespace engine_settings_test {

using namespace hairsketch;

TEST(EngineSettings, FallFollowsItsEntryAndBadArraysChangeNothing) {
  HairEngine e;
  double v[kEngineSettingCount] = {};
  v[kSettingFall] = 1;
  ASSERT_TRUE(e.setSettings(v, kEngineSettingCount).ok());
  EXPECT_TRUE(e.fall());
  v[kSettingFall] = 0;
  EXPECT_EQ(e.setSettings(v, kEngineSettingCount - 1).code, StatusCode::InvalidInput);
  EXPECT_TRUE(e.fall());
  v[kSettingAvoidScalp] = std::nan("");
  EXPECT_EQ(e.setSettings(v, kEngineSettingCount).code, StatusCode::NonFinite);
  EXPECT_TRUE(e.fall());
  v[kSettingAvoidScalp] = 1;
  ASSERT_TRUE(e.setSettings(v, kEngineSettingCount).ok());
  EXPECT_FALSE(e.fall());
}

TEST(EngineSettings, EachFlagFollowsItsOwnEntry) {
  struct Flag {
    EngineSetting at;
    bool (HairEngine::*read)() const;
  };
  const Flag flags[] = {{kSettingSections, &HairEngine::sections},
                        {kSettingTies, &HairEngine::ties},
                        {kSettingHairline, &HairEngine::hairline},
                        {kSettingCurlVolume, &HairEngine::curlVolume},
                        {kSettingCoilVolume, &HairEngine::coilVolume}};
  for (const Flag& f : flags) {
    HairEngine e;
    double v[kEngineSettingCount] = {};
    v[f.at] = 1;
    ASSERT_TRUE(e.setSettings(v, kEngineSettingCount).ok());
    for (const Flag& g : flags) EXPECT_EQ((e.*g.read)(), g.at == f.at) << f.at << " " << g.at;
  }
}

}  // namespace engine_settings_test

// The run-time tuning (cfg/ShotPredictor.cfg) against the node's own declaration and validation: every tuning name
// is a parameter's name with '/' as '_', every range is the parameter's own, and a change round-trips.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "tuning.hpp"

namespace bsp = billiard_shot_planner;

namespace
{
using Config = bsp::ShotPredictorConfig;

/// The member of a double tuning value by its name.
double Config::*numberField(const std::string& name)
{
  for (const auto& description : Config::__getParamDescriptions__())
    if (description->name == name)
      if (auto number = boost::dynamic_pointer_cast<const Config::ParamDescription<double>>(description))
        return number->field;
  return nullptr;
}

/// Whether the node accepts `value` for the tuning number `name`, every other value at the default.
bool accepts(double Config::*field, double value)
{
  Config tuning = bsp::toTuning(bsp::ShotConfiguration{});
  tuning.*field = value;
  return bsp::applyTuning(bsp::ShotConfiguration{}, tuning).ok();
}
}  // namespace

TEST(Tuning, RoundTripAndRejection)
{
  bsp::ShotConfiguration c;
  c.cue_contact.friction = 0.55;
  c.motion.rolling_model = bsp::RollingModel::Pooltool;
  auto tuning = bsp::toTuning(c);
  EXPECT_EQ(tuning.cue_contact_friction, 0.55);
  EXPECT_EQ(tuning.motion_rolling_model, "pooltool");
  tuning.table_cloth_eta2 = 4.0;
  const auto tuned = bsp::applyTuning(c, tuning).value();
  EXPECT_EQ(tuned.table.cloth.eta2, 4.0);
  EXPECT_EQ(tuned.cue_contact.friction, 0.55);
  tuning.ball_radius = 0.05;  // the cushion nose (0.0363 m) would be below the ball's centre... still valid
  EXPECT_TRUE(bsp::applyTuning(c, tuning).ok());
  tuning.ball_radius = 0.015;  // nose above the ball: rejected
  EXPECT_EQ(bsp::applyTuning(c, tuning).error().field, "table/cushion_height");
}

// One rule names them all: the default configuration round-trips through the tuning whole, and a few tuned values
// land where their parameters' names say (written out here, not derived by the rule).
TEST(Tuning, EveryTuningNameIsAParametersNameWithUnderscoresForSlashes)
{
  EXPECT_EQ(bsp::tuningName("table/cloth/restitution"), "table_cloth_restitution");
  const bsp::ShotConfiguration defaults;
  Config tuning = bsp::toTuning(defaults);
  const auto same = bsp::applyTuning(defaults, tuning);
  ASSERT_TRUE(same.ok()) << same.error().describe();
  tuning.table_cushion_friction = 0.31;
  tuning.ball_ball_eta2 = 2.5;
  tuning.motion_spinning_friction = 0.02;
  tuning.motion_planar = true;
  const auto tuned = bsp::applyTuning(defaults, tuning).value();
  EXPECT_EQ(tuned.table.cushion.friction, 0.31);
  EXPECT_EQ(tuned.ball_contact.ball_ball.eta2, 2.5);
  EXPECT_EQ(tuned.motion.spinning_friction, 0.02);
  EXPECT_TRUE(tuned.motion.planar);
  EXPECT_EQ(tuned.table.cloth.friction, defaults.table.cloth.friction);
}

// Each finite bound of a tuning number is the parameter's: a step beyond it is refused, a step inside (towards the
// default, a thousandth of the way) accepted. The ball's radius is bounded by the cushion's height besides (its
// description says so), so only its refusals are checked.
TEST(Tuning, EachRangeIsTheParametersOwn)
{
  const Config minimum = Config::__getMin__(), maximum = Config::__getMax__(), defaults = Config::__getDefault__();
  int bounds = 0;
  for (const auto& description : Config::__getParamDescriptions__())
  {
    double Config::*field = numberField(description->name);
    if (field == nullptr)
      continue;
    const bool cross_checked = description->name == "ball_radius";
    for (const double bound : {minimum.*field, maximum.*field})
    {
      if (!std::isfinite(bound))
        continue;
      ++bounds;
      const double outward = bound == minimum.*field ? -1.0 : 1.0;
      const double beyond = bound + outward * 1e-9 * std::max(1.0, std::abs(bound));
      EXPECT_FALSE(accepts(field, beyond)) << description->name << " = " << beyond;
      if (!cross_checked)
      {
        EXPECT_TRUE(accepts(field, bound + 1e-3 * (defaults.*field - bound))) << description->name << " near " << bound;
      }
    }
  }
  EXPECT_EQ(bounds, 26);  // the 21 numbers their lower bounds; the four restitutions and stiffness_ratio their upper
}

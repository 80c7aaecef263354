// Core prediction → ShotPrediction message: every field carries the core's value.
#include <gtest/gtest.h>

#include <set>

#include "parameter_names.hpp"
#include "prediction_message.hpp"
#include "request_fields.hpp"
#include "shot_fixtures.hpp"

namespace bsp = billiard_shot_planner;

TEST(PredictionMessage, CarriesTheCoreResult)
{
  const auto outcome = bsp::predictShot(shot_fixtures::masse(), bsp::ShotConfiguration{}).value();
  const auto m = bsp::toMessage(outcome, "table", 0.01);
  EXPECT_EQ(m.header.frame_id, "table");
  EXPECT_EQ(m.ball_velocity.x, outcome.strike.velocity.x());
  EXPECT_EQ(m.ball_angular_velocity.z, outcome.strike.angular_velocity.z());
  EXPECT_EQ(m.hit_point.z, outcome.hit_point.z());
  EXPECT_EQ(m.cue_speed_after, outcome.strike.cue_velocity);
  EXPECT_EQ(m.impulse_table.z, outcome.strike.impulse_table.z());
  EXPECT_EQ(m.states, outcome.strike.states);
  EXPECT_EQ(m.contact_events.size(), outcome.strike.impact.events.size());
  EXPECT_EQ(m.trajectory_events.size(), outcome.trajectory.events.size());
  EXPECT_EQ(m.outcome, bsp::toString(outcome.trajectory.outcome));
  EXPECT_EQ(m.final_position.x, outcome.trajectory.finalState().position.x());
  EXPECT_EQ(m.trajectory.size(), outcome.trajectory.sample(0.01).size());
  EXPECT_EQ(m.trajectory.front().phase, billiard_shot_planner::PathSample::AIRBORNE);
}

TEST(ShotPrediction, OverridesAreValidatedByName)
{
  bsp::ShotConfiguration c;
  EXPECT_TRUE(bsp::applyOverride(c, "cue_contact.friction", 0.5).ok());
  EXPECT_EQ(c.cue_contact.friction, 0.5);
  EXPECT_EQ(bsp::applyOverride(c, "cue_contact.friction", -1).error().field, "cue_contact.friction");
  EXPECT_EQ(c.cue_contact.friction, 0.5);  // a rejected value leaves the configuration as it was
  EXPECT_EQ(bsp::applyOverride(c, "warp_drive", 1).error().field, "warp_drive");
  bsp::ShotConfiguration d;
  d.table.cloth.eta2 = 0;
  EXPECT_EQ(bsp::validate(d).error().field, "table.cloth.eta2");
  EXPECT_EQ(bsp::applyOverride(c, "solver.relative_tolerance", 1e-20).error().field, "solver.relative_tolerance");
  bsp::ShotConfiguration e;
  e.solver.max_steps = 0;  // not a parameter, but the configuration checks every solver option
  EXPECT_EQ(bsp::validate(e).error().field, "solver.max_steps");
}

TEST(ParameterNames, TheNodeNamesConfigurationPathsWithSlashes)
{
  EXPECT_EQ(bsp::parameterName("table.cloth.friction"), "table/cloth/friction");
  EXPECT_EQ(bsp::configurationPath("table/cloth/friction"), "table.cloth.friction");
  bsp::ShotConfiguration d;
  d.table.cloth.eta2 = 0;
  EXPECT_EQ(bsp::namedAsParameter(bsp::validate(d)).error().field, "table/cloth/eta2");
  EXPECT_TRUE(bsp::namedAsParameter(bsp::validate(bsp::ShotConfiguration{})).ok());
}

// The core names a prediction's input by its place in the call; the node names it by the request's fields, with the
// balls at their places in the request's table (the cue ball among them or given as ball_position).
TEST(ParameterNames, TheCoresFieldsInTheRequestsNames)
{
  const bsp::BallOrigins cue_in_table{{0, 2}, 1};
  const bsp::BallOrigins cue_given{{0, 1}, std::nullopt};
  auto named = [](const std::string& field, const bsp::BallOrigins& origins) {
    return bsp::inRequestTerms(bsp::Error{bsp::ErrorKind::InvalidArgument, field, ""}, origins).field;
  };
  EXPECT_EQ(named("cue.tip", cue_given), "cue_pose.position");
  EXPECT_EQ(named("cue.direction", cue_given), "cue_pose.orientation");
  EXPECT_EQ(named("cue.speed", cue_given), "cue_speed");
  EXPECT_EQ(named("cue", cue_given), "cue_pose");
  EXPECT_EQ(named("cue.ball", cue_given), "ball_position");
  EXPECT_EQ(named("cue.ball", cue_in_table), "table.balls[1].position");
  EXPECT_EQ(named("others[1].position", cue_in_table), "table.balls[2].position");
  EXPECT_EQ(named("others[1].position", cue_given), "table.balls[1].position");
  EXPECT_EQ(named("table.cloth.friction", cue_given), "table/cloth/friction");
  EXPECT_EQ(named("strike.other_balls", cue_given), "strike.other_balls");
}

// A cue ball frozen to a ball: the message lists every contact of the strike by name with its impulse, the ball the
// strike moved with its velocity, and the contact events name their contact (an index past the lone strike's two).
TEST(PredictionMessage, CarriesAFrozenStrikesContactsAndMovedBalls)
{
  const bsp::ShotConfiguration configuration;
  const bsp::ShotOutcome outcome = shot_fixtures::frozenFollow(configuration);
  ASSERT_FALSE(outcome.strike.other_balls.empty());
  const auto m = bsp::toMessage(outcome, "table", 0.01);
  ASSERT_EQ(m.strike_contacts.size(), outcome.strike.contacts.size());
  EXPECT_EQ(m.strike_contacts[1].name, "cue-one");
  EXPECT_EQ(m.strike_contacts[1].impulse.x, outcome.strike.contacts[1].impulse.x());
  ASSERT_EQ(m.struck_balls.size(), 1u);
  EXPECT_EQ(m.struck_balls[0].id, "one");
  EXPECT_EQ(m.struck_balls[0].velocity.x, outcome.strike.other_balls[0].velocity.x());
  std::set<std::string> names;
  for (const auto& contact : m.strike_contacts)
    names.insert(contact.name);
  for (const auto& event : m.contact_events)
    EXPECT_EQ(names.count(event.contact), 1u) << event.contact;
  EXPECT_EQ(m.first_contact, "one");
}

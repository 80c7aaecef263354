// The recorder that turns a camera's stream of sightings into observed shots: each sighting lands in the track of
// the shot whose window holds it, with its time counted from that strike; shots may be recorded after they were
// struck; the next strike closes the window before it; late sightings take their place, repeated and foreign ones are
// dropped; the limits hold. And a fit from recorded sightings finds the constant that drew them.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "billiard_shot_planner/calibration/shot_recorder.hpp"
#include "billiard_shot_planner/planning/stroke.hpp"

namespace bsp = billiard_shot_planner;

namespace
{
constexpr double R = 0.0286;

bsp::ObservedShot shotWith(std::vector<std::string> others)
{
  bsp::ObservedShot shot;
  for (const std::string& id : others)
    shot.others.push_back({id, {}});
  return shot;
}

bsp::TableSighting sighting(double time, double x)
{
  return {time, {{bsp::CUE_BALL_ID, {x, 0.0}}, {"one", {x, 0.5}}}};
}

std::size_t trackLength(const bsp::ObservedShot& shot, const std::string& id)
{
  const auto found = shot.tracks.find(id);
  return found == shot.tracks.end() ? 0 : found->second.size();
}
}  // namespace

TEST(ShotRecorder, SightingsWithinTheWindowBecomeTrackPointsTimedFromTheStrike)
{
  bsp::RecorderLimits limits;
  limits.track_duration = 1.0;
  bsp::ShotRecorder recorder(limits);
  ASSERT_TRUE(recorder.record(shotWith({"one"}), 100.0).ok());
  for (double t : {99.5, 100.25, 100.5, 101.0, 101.5})  // before, within (twice), at the end, after
    recorder.observe(sighting(t, t - 100.0));
  const auto& track = recorder.shots()[0].tracks.at(bsp::CUE_BALL_ID);
  ASSERT_EQ(track.size(), 3u);
  EXPECT_DOUBLE_EQ(track[0].t, 0.25);
  EXPECT_DOUBLE_EQ(track[2].t, 1.0);
  EXPECT_DOUBLE_EQ(track[1].position.x(), 0.5);
  EXPECT_EQ(trackLength(recorder.shots()[0], "one"), 3u);
  EXPECT_EQ(recorder.points(), 6u);
}

TEST(ShotRecorder, AShotRecordedAfterItWasStruckTakesTheSightingsAlreadySeen)
{
  bsp::ShotRecorder recorder;
  for (double t : {9.9, 10.1, 10.2, 10.3})
    recorder.observe(sighting(t, t));
  const bsp::TableSighting* before = recorder.sightingAtOrBefore(10.0);
  ASSERT_NE(before, nullptr);
  EXPECT_DOUBLE_EQ(before->time, 9.9);
  ASSERT_TRUE(recorder.record(shotWith({"one"}), 10.0).ok());
  EXPECT_EQ(trackLength(recorder.shots()[0], bsp::CUE_BALL_ID), 3u);
  EXPECT_NEAR(recorder.shots()[0].tracks.at(bsp::CUE_BALL_ID)[0].t, 0.1, 1e-12);
}

TEST(ShotRecorder, TheNextStrikeEndsTheWindowOfTheShotBeforeIt)
{
  bsp::ShotRecorder recorder;
  ASSERT_TRUE(recorder.record(shotWith({}), 0.0).ok());
  recorder.observe(sighting(1.0, 1.0));
  recorder.observe(sighting(2.5, 2.5));
  // Recorded late: the sighting at 2.5 s moves to the second shot.
  ASSERT_TRUE(recorder.record(shotWith({}), 2.0).ok());
  recorder.observe(sighting(3.0, 3.0));
  EXPECT_EQ(trackLength(recorder.shots()[0], bsp::CUE_BALL_ID), 1u);
  EXPECT_EQ(trackLength(recorder.shots()[1], bsp::CUE_BALL_ID), 2u);
  EXPECT_EQ(recorder.points(), 3u);
  EXPECT_NEAR(recorder.shots()[1].tracks.at(bsp::CUE_BALL_ID)[0].t, 0.5, 1e-12);
}

TEST(ShotRecorder, LateSightingsTakeTheirPlaceAndRepeatedForeignAndNonFiniteOnesAreDropped)
{
  bsp::ShotRecorder recorder;
  ASSERT_TRUE(recorder.record(shotWith({"one"}), 0.0).ok());
  recorder.observe(sighting(0.2, 0.2));
  recorder.observe(sighting(0.1, 0.1));              // out of order: both balls' points go before the first
  recorder.observe(sighting(0.2, 0.2));              // repeated: both dropped
  recorder.observe({0.3, {{"ghost", {0.0, 0.0}}}});  // not on the table at the strike: ignored
  recorder.observe({0.4, {{bsp::CUE_BALL_ID, {NAN, 0.0}}}});
  recorder.observe({NAN, {{bsp::CUE_BALL_ID, {0.0, 0.0}}}});
  const auto& track = recorder.shots()[0].tracks.at(bsp::CUE_BALL_ID);
  ASSERT_EQ(track.size(), 2u);
  EXPECT_NEAR(track[0].t, 0.1, 1e-12);
  EXPECT_NEAR(track[1].t, 0.2, 1e-12);
  EXPECT_EQ(recorder.shots()[0].tracks.count("ghost"), 0u);
  EXPECT_EQ(recorder.droppedPoints(), 3u);
}

TEST(ShotRecorder, ItsLimitsHoldAndBadStrikesAreRefusedByName)
{
  bsp::RecorderLimits limits;
  limits.max_shots = 2;
  limits.max_points = 3;
  limits.history = 4;
  bsp::ShotRecorder recorder(limits);
  ASSERT_TRUE(recorder.record(shotWith({"one"}), 1.0).ok());
  for (int i = 1; i <= 10; ++i)
    recorder.observe(sighting(1.0 + 0.1 * i, 0.0));
  EXPECT_EQ(recorder.points(), 3u);
  EXPECT_EQ(recorder.droppedPoints(), 17u);
  EXPECT_EQ(recorder.record(shotWith({}), 0.5).error().field, "strike_time");
  EXPECT_EQ(recorder.record(shotWith({}), INFINITY).error().field, "strike_time");
  ASSERT_TRUE(recorder.record(shotWith({}), 5.0).ok());
  EXPECT_EQ(recorder.record(shotWith({}), 6.0).error().field, "shots");
  // The history keeps its last four sightings only.
  EXPECT_EQ(recorder.sightingAtOrBefore(1.55), nullptr);
  recorder.clear();
  EXPECT_TRUE(recorder.shots().empty());
  EXPECT_EQ(recorder.points(), 0u);
  EXPECT_TRUE(recorder.record(shotWith({}), 0.0).ok());
}

// Two shots streamed as a 30 Hz camera with 2 mm noise would see them, with a rolling friction of 0.015: the
// recorded tracks fit it back within 3σ, starting from 0.01.
TEST(ShotRecorder, AFitOfRecordedSightingsFindsTheConstantThatDrewThem)
{
  bsp::ShotConfiguration truth;
  truth.motion.rolling_friction = 0.015;
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 0.002);
  bsp::ShotRecorder recorder;
  double clock = 50.0;
  for (double phi_deg : {10.0, 100.0})
  {
    const auto cue = bsp::placeStroke({phi_deg * M_PI / 180.0, 0.0, 1.5, 0.0, 0.2}, {0.0, 0.0}, R);
    ASSERT_TRUE(cue.ok());
    const auto outcome = bsp::predictShot(cue.value(), truth);
    ASSERT_TRUE(outcome.ok()) << outcome.error().describe();
    bsp::ObservedShot shot;
    shot.cue = cue.value();
    ASSERT_TRUE(recorder.record(shot, clock).ok());
    for (double t = 0.0; t < std::min(4.0, outcome->trajectory.duration()); t += 1.0 / 30.0)
      recorder.observe({clock + t,
                        {{bsp::CUE_BALL_ID,
                          outcome->trajectory.at(t).position.head<2>() + Eigen::Vector2d{noise(rng), noise(rng)}}}});
    clock += 20.0;
  }
  const auto fitted = bsp::fitTracks(bsp::ShotConfiguration{}, {{"motion.rolling_friction", 0.01, 0.001, 0.2}},
                                     recorder.shots(), 0.002);
  ASSERT_TRUE(fitted.ok()) << fitted.error().describe();
  const bsp::FittedParameter& mu = fitted->fit.parameters[0];
  ASSERT_TRUE(mu.identifiable);
  EXPECT_NEAR(mu.value, 0.015, 3.0 * mu.sigma);
  EXPECT_LT(mu.sigma, 0.001);
}

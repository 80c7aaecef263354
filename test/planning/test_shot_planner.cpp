// The shot planner: what it plans must pot when replayed independently, its pot probability must agree with a fresh
// measurement, the cue must clear the balls and the rails, and bad requests are refused naming the field.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "billiard_shot_planner/planning/shot_planner.hpp"

namespace bsp = billiard_shot_planner;

namespace
{
const double R = bsp::ShotConfiguration{}.ball_radius;
const std::string TOP_RIGHT = "top_right";  // the (+x, +y) corner pocket
constexpr std::size_t TOP_RIGHT_INDEX = 3;  // its place in the default table's pockets

bsp::TableBall ballAt(const std::string& id, double x, double y)
{
  bsp::BallState state;
  state.position = {x, y, R};
  state.velocity.setZero();
  state.angular_velocity.setZero();
  return {id, state};
}

/// The object ball "one" `distance` m from the top-right corner pocket on the diagonal towards the table's centre,
/// the cue ball `behind` m further along a line at `cut` to it.
bsp::PlanRequest cutShot(double distance, double behind, double cut_deg)
{
  const bsp::Table table;
  const Eigen::Vector2d pocket = table.pockets[TOP_RIGHT_INDEX].centre;
  const Eigen::Vector2d line = -pocket.normalized();  // from the pocket towards the centre
  const Eigen::Vector2d object = pocket + distance * line;
  const Eigen::Vector2d ghost = object + 2.0 * R * line;
  const double cut = cut_deg * M_PI / 180.0;
  const Eigen::Vector2d back(std::cos(cut) * line.x() - std::sin(cut) * line.y(),
                             std::sin(cut) * line.x() + std::cos(cut) * line.y());
  const Eigen::Vector2d cue = ghost + behind * back;
  bsp::PlanRequest request;
  request.balls = {ballAt("cue", cue.x(), cue.y()), ballAt("one", object.x(), object.y())};
  request.target = "one";
  // A plan ends once its rollouts are confirmed (a fraction of a second here); the budget is for the sanitized build,
  // which runs twenty times slower.
  request.budget = 60.0;
  return request;
}

bsp::ShotPlan planned(const bsp::PlanRequest& request, const bsp::ShotConfiguration& configuration = {})
{
  auto plan = bsp::planShot(request, configuration);
  EXPECT_TRUE(plan.ok()) << plan.error().describe();
  return plan.ok() ? std::move(plan).value() : bsp::ShotPlan{};
}

/// Replays a cue placement with predictShot at the configuration's own tolerance: whether ball `target` drops in
/// `pocket` and the cue ball stays on the table.
bool replayPots(const bsp::CuePlacement& cue, const bsp::PlanRequest& request, const std::string& target,
                const std::string& pocket, const bsp::ShotConfiguration& configuration = {})
{
  std::vector<bsp::TableBall> others(request.balls.begin() + 1, request.balls.end());
  const auto outcome = bsp::predictShot(cue, configuration, others);
  if (!outcome)
    return false;
  const bsp::TableTrajectory& run = outcome.value().table;
  if (run.balls[0].outcome == bsp::MotionOutcome::Pocketed)
    return false;
  for (std::size_t i = 1; i < run.ids.size(); ++i)
    if (run.ids[i] == target)
      for (const bsp::MotionEvent& e : run.balls[i].events)
        if (e.type == bsp::MotionEventType::Pocketed)
          return pocket.empty() || e.pocket == pocket;
  return false;
}
}  // namespace

// Wilson's interval at the extremes: all n rollouts pot (or none) and the interval still holds the estimate, ending
// at 1 (or 0) on that side; its other end is the closed form's, n/(n + z²) (z²/(n + z²)).
TEST(ShotPlanner, TheIntervalHoldsTheEstimateAtItsExtremes)
{
  bsp::PlanRequest request = cutShot(0.4, 0.5, 0.0);
  request.noise = {0.0, 0.0, 0.0, 0.0, 0.0};  // no noise: every rollout is the nominal shot, which pots
  request.rollouts = 30;
  const bsp::ShotPlan plan = planned(request);
  ASSERT_TRUE(plan.found) << plan.explanation;
  const double z2 = 1.959963984540054 * 1.959963984540054, n = plan.best.rollouts;
  EXPECT_EQ(plan.best.success_probability, 1.0);
  EXPECT_EQ(plan.best.confidence_high, 1.0);
  EXPECT_NEAR(plan.best.confidence_low, n / (n + z2), 1e-12);
}

// A straight-in shot: the plan pots when replayed independently, aims within the noise of the line of centres
// (a head-on hit has no throw, a centre hit no squirt), and the rollouts find it nearly certain.
TEST(ShotPlanner, AStraightInShotIsPlannedAlongTheLineOfCentres)
{
  const bsp::PlanRequest request = cutShot(0.4, 0.5, 0.0);
  const bsp::ShotPlan plan = planned(request);
  ASSERT_TRUE(plan.found) << plan.explanation;
  EXPECT_EQ(plan.best.target, "one");
  EXPECT_EQ(plan.best.pocket, TOP_RIGHT);
  EXPECT_TRUE(replayPots(plan.best.cue, request, "one", TOP_RIGHT));
  const Eigen::Vector2d line = request.balls[1].state.position.head<2>() - request.balls[0].state.position.head<2>();
  EXPECT_NEAR(std::remainder(plan.best.stroke.phi - std::atan2(line.y(), line.x()), 2 * M_PI), 0.0, 0.5 * M_PI / 180.0);
  EXPECT_GT(plan.best.success_probability, 0.9);
  EXPECT_LE(plan.best.confidence_low, plan.best.success_probability);
  EXPECT_GE(plan.best.confidence_high, plan.best.success_probability);
  // Ranked on the request's rollouts, confirmed (when another shot was ranked) on up to four times as many.
  EXPECT_GE(plan.best.rollouts, request.rollouts);
  EXPECT_LE(plan.best.rollouts, 4 * request.rollouts);
}

// On the jaws' table the planner aims through the mouth: the straight-in shot into the corner (18° off its axis) pots
// when replayed on the jaws, and its margin is its clearance from the jaws up to the mouth: no more than the mouth's
// half-width that clears both jaw points, half the WPA's 4.5625 in mouth less the cushion's reach R cos θ,
// sin θ = (h − R)/R, and no less than half of that, where the refinement stops as good enough.
TEST(ShotPlanner, OnTheJawsItAimsThroughTheMouth)
{
  bsp::ShotConfiguration jaws;
  jaws.table.pocket_model = bsp::PocketModel::Jaws;
  bsp::PlanRequest request = cutShot(0.4, 0.5, 0.0);
  request.pocket = TOP_RIGHT;
  const bsp::ShotPlan plan = planned(request, jaws);
  ASSERT_TRUE(plan.found) << plan.explanation;
  EXPECT_EQ(plan.best.pocket, TOP_RIGHT);
  EXPECT_TRUE(replayPots(plan.best.cue, request, "one", TOP_RIGHT, jaws));
  const double sin_theta = (jaws.table.cushion_height - R) / R;
  const double half_width = 0.5 * 4.5625 * 0.0254 - R * std::sqrt(1.0 - sin_theta * sin_theta);
  EXPECT_LE(plan.best.margin, half_width + 1e-12);
  EXPECT_GE(plan.best.margin, 0.5 * half_width);
  EXPECT_GT(plan.best.success_probability, 0.8);
}

// The planner's pot probability of a 40° cut against 1 000 fresh noisy rollouts drawn here, with another generator,
// and replayed at the default tolerance (the planner runs at PLANNING_TOLERANCE; a stroke whose cue touches a ball or a
// rail is a miss in both): the two binomial estimates agree within three standard deviations of their difference.
TEST(ShotPlanner, ItsPotProbabilityAgreesWithAFreshMeasurement)
{
  bsp::PlanRequest request = cutShot(0.5, 0.6, 40.0);
  request.rollouts = 1000;
  request.noise.phi *= 4.0;  // a noisier robot: the probability is away from 0 and 1, where the check is sharpest
  const bsp::ShotPlan plan = planned(request);
  ASSERT_TRUE(plan.found) << plan.explanation;
  std::mt19937 rng(12345);
  std::normal_distribution<double> gauss(0.0, 1.0);
  const int fresh = 1000;
  int pots = 0;
  for (int k = 0; k < fresh; ++k)
  {
    bsp::Stroke stroke = plan.best.stroke;
    stroke.phi += request.noise.phi * gauss(rng);
    stroke.theta += request.noise.theta * gauss(rng);
    stroke.speed += request.noise.speed * gauss(rng);
    stroke.a += request.noise.a / R * gauss(rng);
    stroke.b += request.noise.b / R * gauss(rng);
    const auto cue = bsp::placeStroke(stroke, request.balls[0].state.position.head<2>(), R);
    const std::vector<bsp::TableBall> others(request.balls.begin() + 1, request.balls.end());
    pots += cue.ok() && bsp::cueClears(cue.value(), others, bsp::Table{}, request.limits, R) &&
            replayPots(cue.value(), request, "one", "");
  }
  const double p_fresh = static_cast<double>(pots) / fresh, p_plan = plan.best.success_probability;
  const double p = 0.5 * (p_fresh + p_plan);
  const double sigma = std::sqrt(std::max(p * (1 - p), 0.01) * (1.0 / fresh + 1.0 / plan.best.rollouts));
  std::printf("40° cut, σ_φ = 0.5°: planner %.3f [%.3f, %.3f] over %d rollouts, fresh %.3f over %d\n", p_plan,
              plan.best.confidence_low, plan.best.confidence_high, plan.best.rollouts, p_fresh, fresh);
  EXPECT_NEAR(p_plan, p_fresh, 3.0 * sigma);
  EXPECT_GT(p_fresh, 0.2);  // the case is the one meant: neither hopeless nor certain
  EXPECT_LT(p_fresh, 0.95);
}

// Within its budget (40 rollouts a shot: a few seconds even under the sanitizers) a plan is a function of the request
// and its seed, whatever the threads' timing.
TEST(ShotPlanner, TheSameSeedGivesTheSamePlan)
{
  bsp::PlanRequest request = cutShot(0.5, 0.6, 30.0);
  request.rollouts = 40;
  const bsp::ShotPlan a = planned(request), b = planned(request);
  ASSERT_TRUE(a.found && b.found);
  EXPECT_EQ(a.best.stroke.phi, b.best.stroke.phi);
  EXPECT_EQ(a.best.stroke.speed, b.best.stroke.speed);
  EXPECT_EQ(a.best.success_probability, b.best.success_probability);
}

// A cue ball 15 cm from the −x rail shooting towards +x, a ball 6 cm behind it: a level cue would pass through both,
// so the plan raises it until it clears the ball and its underside clears the rail's top where it crosses the rail
// line (both checked here from the placement's geometry).
TEST(ShotPlanner, TheCueClearsTheRailsAndTheBalls)
{
  const bsp::Table table;
  const bsp::RobotLimits limits;
  bsp::PlanRequest request;
  const double x0 = -0.5 * table.length + 3 * R + 0.12;
  request.balls = {ballAt("cue", x0, 0.2), ballAt("one", 0.0, 0.2), ballAt("blocker", x0 - 2 * R - 0.06, 0.2)};
  request.target = "one";
  request.budget = 3.0;
  request.rollouts = 20;
  const bsp::ShotPlan plan = planned(request);
  ASSERT_FALSE(plan.best.target.empty()) << plan.explanation;
  const Eigen::Vector3d back = -plan.best.cue.direction.normalized();
  ASSERT_LT(back.x(), 0.0);  // the cue points at +x, its butt towards the −x rail
  EXPECT_GT(plan.best.stroke.theta, 0.0);
  const double to_rail = (-0.5 * table.length - plan.best.cue.tip.x()) / back.x();
  ASSERT_LE(to_rail, limits.cue_length);
  EXPECT_GE(plan.best.cue.tip.z() + to_rail * back.z() - limits.cue_radius, limits.rail_height);
  const Eigen::Vector3d blocker = request.balls[2].state.position;
  const double along = std::clamp((blocker - plan.best.cue.tip).dot(back), 0.0, limits.cue_length);
  EXPECT_GE((plan.best.cue.tip + along * back - blocker).norm(), R + limits.cue_radius);
}

// A ball on the line from the target to the only pocket allowed: no direct shot, and the plan says why.
TEST(ShotPlanner, ABlockedPocketGivesNoPlanAndSaysWhy)
{
  bsp::PlanRequest request = cutShot(0.4, 0.5, 0.0);
  const Eigen::Vector2d object = request.balls[1].state.position.head<2>();
  const Eigen::Vector2d pocket = bsp::Table{}.pockets[TOP_RIGHT_INDEX].centre;
  const Eigen::Vector2d middle = 0.5 * (object + pocket);
  request.balls.push_back(ballAt("blocker", middle.x(), middle.y()));
  request.pocket = TOP_RIGHT;
  request.budget = 1.0;
  const bsp::ShotPlan plan = planned(request);
  EXPECT_FALSE(plan.found);
  EXPECT_NE(plan.explanation.find("1 with a ball in the way"), std::string::npos) << plan.explanation;
}

// The target 0.3 m from the −y rail with the cue ball behind it on the line to its bounce point: no straight route to
// the (+x, +y) corner (its cut would be near 90°), one off the −y cushion by the pocket's mirror image. The plan
// banks there, and pots when replayed independently.
TEST(ShotPlanner, ABankIsPlannedWhenNoStraightRouteIsPlayable)
{
  bsp::PlanRequest request;
  request.balls = {ballAt("cue", 0.035, 0.125), ballAt("one", 0.3, -0.3)};
  request.target = "one";
  request.pocket = TOP_RIGHT;
  request.budget = 3.0;
  const bsp::ShotPlan plan = planned(request);
  ASSERT_TRUE(plan.found) << plan.explanation;
  EXPECT_EQ(plan.best.bank_cushion, "rail.bottom");  // the −y rail
  EXPECT_TRUE(replayPots(plan.best.cue, request, "one", TOP_RIGHT));
  EXPECT_GT(plan.best.success_probability, 0.0);
}

// The target 0.15 m from the (+x, +y) corner, the cue ball 0.8 m behind its ghost ball at a 10° cut, and a third
// ball on that line, 0.45 of the way, 0.3 R to its side: the straight shot hits it (a combination may still pot).
// With the cue allowed up to 60°, the planner also goes around it: off a cushion (the kick) and over it (the jump).
// Every detour pots when replayed independently, the cue ball's first contact is the target, and the ball in the
// way ends where it stood (to 1e-9 m: nothing touched it).
// A jump is checked to have gone over: its cue ball's centre passes within 2R of the obstacle's on the cloth plane
// (so it cannot have passed beside it) and its flight is what carries it (its highest centre is above 2R over the
// cloth, as far as a ball leaving at v_z climbs: v_z²/2g).
TEST(ShotPlanner, AroundABallInTheWayItPlansAKickAndAJump)
{
  bsp::PlanRequest request = cutShot(0.15, 0.8, 10.0);
  const Eigen::Vector2d cue = request.balls[0].state.position.head<2>();
  const Eigen::Vector2d object = request.balls[1].state.position.head<2>();
  const Eigen::Vector2d ghost = object + 2.0 * R * (object - bsp::Table{}.pockets[TOP_RIGHT_INDEX].centre).normalized();
  const Eigen::Vector2d along = (ghost - cue).normalized();
  const Eigen::Vector2d obstacle = cue + 0.45 * (ghost - cue) + 0.3 * R * Eigen::Vector2d(-along.y(), along.x());
  request.balls.push_back(ballAt("two", obstacle.x(), obstacle.y()));
  request.pocket = TOP_RIGHT;
  request.limits.max_theta = 60.0 * M_PI / 180.0;
  request.budget =
      60.0;  // the largest: never reached (the plan ends when its rollouts are done), so the plan is the seed's alone
  const bsp::ShotPlan plan = planned(request);
  ASSERT_TRUE(plan.found) << plan.explanation;
  std::vector<bsp::PlannedShot> shots{plan.best};
  shots.insert(shots.end(), plan.alternatives.begin(), plan.alternatives.end());
  std::vector<bsp::CueBallPath> kinds;
  for (const bsp::PlannedShot& shot : shots)
  {
    SCOPED_TRACE(bsp::toString(shot.cue_ball_path));
    kinds.push_back(shot.cue_ball_path);
    EXPECT_TRUE(replayPots(shot.cue, request, "one", TOP_RIGHT));
    if (shot.cue_ball_path == bsp::CueBallPath::Straight)
      continue;
    const auto outcome = bsp::predictShot(shot.cue, {}, {request.balls[1], request.balls[2]});
    ASSERT_TRUE(outcome.ok());
    const bsp::TableTrajectory& run = outcome.value().table;
    EXPECT_EQ(bsp::firstContact(run, 0), "one");
    EXPECT_NEAR((run.balls[2].finalState().position.head<2>() - obstacle).norm(), 0.0, 1e-9);
    if (shot.cue_ball_path == bsp::CueBallPath::Masse)
    {
      EXPECT_GT(std::abs(shot.stroke.a), 0.1);  // a hit off the centre with a raised cue
    }
    if (shot.cue_ball_path != bsp::CueBallPath::Jump)
      continue;
    double nearest = INFINITY, highest = 0.0;
    for (const bsp::TrajectorySample& sample : run.balls[0].sample(1e-3))
    {
      if (sample.time < run.ball_impacts.front().time)
        nearest = std::min(nearest, (sample.state.position.head<2>() - obstacle).norm());
      highest = std::max(highest, sample.state.position.z());
    }
    const double v_z = outcome.value().strike.velocity.z();
    EXPECT_LT(nearest, 2.0 * R);
    EXPECT_GT(highest - R, 2.0 * R * std::sqrt(1.0 - std::pow(nearest / (2.0 * R), 2)));
    EXPECT_LE(highest - R, v_z * v_z / (2.0 * bsp::MotionParameters{}.gravity) + 1e-6);
  }
  for (bsp::CueBallPath kind : {bsp::CueBallPath::Kick, bsp::CueBallPath::Jump})
    EXPECT_NE(std::find(kinds.begin(), kinds.end(), kind), kinds.end()) << bsp::toString(kind);
}

TEST(ShotPlanner, BadRequestsAreRefusedNamingTheField)
{
  const bsp::PlanRequest good = cutShot(0.4, 0.5, 0.0);
  const auto field = [](const bsp::PlanRequest& request)
  {
    auto plan = bsp::planShot(request, bsp::ShotConfiguration{});
    return plan.ok() ? std::string("(none)") : plan.error().field;
  };
  bsp::PlanRequest r = good;
  r.target = "seven";
  EXPECT_EQ(field(r), "target");
  r = good;
  r.target = "cue";
  EXPECT_EQ(field(r), "target");
  r = good;
  r.cue_ball = "white";
  EXPECT_EQ(field(r), "cue_ball");
  r = good;
  r.pocket = "pocket6";
  EXPECT_EQ(field(r), "pocket");
  // Under the jaws the pockets are the outline's: a capture circle's id names none of them.
  bsp::ShotConfiguration jaws;
  jaws.table.pocket_model = bsp::PocketModel::Jaws;
  jaws.table.pockets = {{{1.27, 0.635}, 0.06, "corner"}};
  r = good;
  r.pocket = "corner";
  const auto on_jaws = bsp::planShot(r, jaws);
  ASSERT_FALSE(on_jaws.ok());
  EXPECT_EQ(on_jaws.error().field, "pocket");
  r = good;
  r.limits.min_speed = 3.0;
  r.limits.max_speed = 2.0;
  EXPECT_EQ(field(r), "limits.speed");
  r = good;
  r.noise.phi = -1.0;
  EXPECT_EQ(field(r), "noise.phi");
  r = good;
  r.budget = 0.0;
  EXPECT_EQ(field(r), "budget");
  r = good;
  r.balls[1].state.position.x() = NAN;
  EXPECT_EQ(field(r).rfind("balls", 0), 0u) << field(r);
  r = good;
  r.balls[0].state.position.head<2>() = bsp::Table{}.pockets[0].centre;
  EXPECT_EQ(field(r).rfind("balls", 0), 0u) << field(r);
  r = good;
  r.balls.resize(1);
  EXPECT_EQ(field(r), "balls");
  r = good;
  r.cue_region = bsp::CueRegion{{0.0, 0.0}, -0.1};
  EXPECT_EQ(field(r), "cue_region.radius");
  r = good;
  r.balls[1].state.velocity.x() = 1e-3;  // a plan starts from a table at rest: a moving ball has its own kind
  const auto moving = bsp::planShot(r, bsp::ShotConfiguration{});
  ASSERT_FALSE(moving.ok());
  EXPECT_EQ(moving.error().code, bsp::ErrorKind::BallsMoving);
  EXPECT_EQ(moving.error().field, "balls");
}

// A cue ball frozen to the target, their line of centres 3° off the line to the corner pocket: whatever the cue's
// aim, the target leaves along the line of centres turned by the throw (at most atan μ ≈ 6.7°), so a pot exists only
// through the combined strike. The planner finds it, it pots when replayed, and the strike moves the target at once.
TEST(ShotPlanner, AFrozenTargetLinedUpWithAPocketIsPotted)
{
  const bsp::Table table;
  const Eigen::Vector2d pocket = table.pockets[TOP_RIGHT_INDEX].centre;
  const Eigen::Vector2d line = -pocket.normalized();
  const Eigen::Vector2d object = pocket + 0.6 * line;
  const double turn = 3.0 * M_PI / 180.0;
  const Eigen::Vector2d back(std::cos(turn) * line.x() - std::sin(turn) * line.y(),
                             std::sin(turn) * line.x() + std::cos(turn) * line.y());
  const Eigen::Vector2d cue = object + 2.0 * R * back;
  bsp::PlanRequest request;
  request.balls = {ballAt("cue", cue.x(), cue.y()), ballAt("one", object.x(), object.y())};
  request.target = "one";
  request.budget = 60.0;  // as cutShot's: the sanitized build's
  const bsp::ShotPlan plan = planned(request);
  ASSERT_TRUE(plan.found) << plan.explanation;
  EXPECT_EQ(plan.best.pocket, TOP_RIGHT);
  EXPECT_TRUE(replayPots(plan.best.cue, request, "one", TOP_RIGHT));
  ASSERT_EQ(plan.outcome.strike.other_balls.size(), 1u);
  EXPECT_GT(plan.best.success_probability, 0.5);
}

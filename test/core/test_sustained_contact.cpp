// Balls that stay in contact while they move (docs/engine.md, Sustained contact between balls): a ball pressed into
// another is one linked pair, the limit of the sequence of ever smaller collisions, until the pair's own
// accelerations part it.
//
// The pair's law, derived here once for the tests below. Two balls of mass m and radius R touch; F ≥ 0 is the
// contact force through both centres (no torque about either), on the front ball along the line of centres n, on
// the rear ball against it. On the cloth (μ_s sliding, d_r = (5/7) μ_r g the rolling deceleration of the paper's
// model):
//   sliding ball:  a = −μ_s g û + F n/m, ω̇ = (5 μ_s g / 2R) ẑ × û, so the slip u = v + R ẑ × ω changes at
//                  u̇ = −(7/2) μ_s g û + F n/m (û the slip's direction);
//   rolling ball:  the cloth's static friction takes 2F/7 of the push (I = (2/5) m R², a = R ω̇), so
//                  a = −d_r v̂ + (5/7) F n/m while 2F/7 ≤ μ_s m g.
// The gap stays closed while (a_front − a_rear)·n = 0 (a pair on one line), which fixes F; F ≤ 0 lets it go.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include "billiard_shot_planner/motion/ball_motion.hpp"
#include "billiard_shot_planner/motion/table_simulation.hpp"
#include "billiard_shot_planner/scenarios/cue_stroke.hpp"
#include "billiard_shot_planner/shot/shot_prediction.hpp"
#include "table_helpers.hpp"

namespace bsp = billiard_shot_planner;
using table_helpers::strokeAt;
using Type = bsp::MotionEventType;

namespace
{
const bsp::BallProperties BALL;
const double R = BALL.radius;

bsp::BallState at(double x, double y, const Eigen::Vector3d& v = Eigen::Vector3d::Zero(),
                  const Eigen::Vector3d& w = Eigen::Vector3d::Zero())
{
  return table_helpers::stateOnCloth(R, x, y, v, w);
}

/// Kinetic energy and the potential energy of a ball above the cloth (a hop after an impact).
double energy(const bsp::BallState& s, const bsp::BallProperties& ball)
{
  const double m = ball.mass, r = ball.radius;
  return 0.5 * m * s.velocity.squaredNorm() + 0.2 * m * r * r * s.angular_velocity.squaredNorm() +
         m * bsp::MotionParameters{}.gravity * (s.position.z() - r);
}

double tableEnergy(const bsp::TableTrajectory& run, double t, const bsp::BallProperties& ball)
{
  double sum = 0.0;
  for (const bsp::BallTrajectory& b : run.balls)
    if (b.outcome != bsp::MotionOutcome::Pocketed || t < b.duration())
      sum += energy(b.at(t), ball);
  return sum;
}

double gap(const bsp::TableTrajectory& run, int i, int j, double t, double radius = R)
{
  return (run.balls[i].at(t).position - run.balls[j].at(t).position).norm() - 2.0 * radius;
}

std::size_t eventCount(const bsp::TableTrajectory& run)
{
  std::size_t n = 0;
  for (const bsp::BallTrajectory& b : run.balls)
    n += b.events.size();
  return n;
}

void expectEnergyNeverRises(const bsp::TableTrajectory& run, double spacing, const bsp::BallProperties& ball = BALL)
{
  double before = tableEnergy(run, 0.0, ball);
  for (double t = spacing; t <= run.duration(); t += spacing)
  {
    const double now = tableEnergy(run, t, ball);
    EXPECT_LE(now, before + 1e-9 * (1.0 + before)) << "t " << t;
    before = now;
  }
}

/// The balls run on `table` until every one rests (expected: none pocketed or stopped by a limit); nothing where
/// the run fails.
std::optional<bsp::TableTrajectory> runToRest(const std::vector<bsp::TableBall>& balls, const bsp::Table& table,
                                              const bsp::MotionParameters& p)
{
  auto run = bsp::simulateTable(balls, BALL, table, p);
  EXPECT_TRUE(run.ok()) << run.error().describe();
  if (!run.ok())
    return std::nullopt;
  for (const bsp::BallTrajectory& b : run.value().balls)
    EXPECT_EQ(b.outcome, bsp::MotionOutcome::Rest);
  return std::move(run.value());
}

const bsp::MotionEvent* firstEvent(const bsp::BallTrajectory& b, Type type)
{
  for (const bsp::MotionEvent& e : b.events)
    if (e.type == type)
      return &e;
  return nullptr;
}

/// impact_solve's table_shot example: its cue, its cue tip and cloth contacts, R = 0.028575 m.
bsp::ShotConfiguration jammedRowConfiguration()
{
  bsp::ShotConfiguration c;
  c.ball_radius = 0.028575;
  c.cue_mass = 0.54;
  c.cue_contact = {0.75, 0.7, 1.2};
  c.table.cloth = {0.5, 0.2, 10.0};
  c.stiffness_ratio = 0.8;
  return c;
}
}  // namespace

// (1) A rolling ball pushes a sliding one. The rear ball rolls at V, the front one touches it and slides at V
// without spin: the front decelerates at μ_s g, the rear at d_r only, so they press together at once. Linked:
//   front  −μ_s g + F/m = rear  −d_r − (5/7) F/m   ⇒   F/m = (7/12)(μ_s g − d_r)
// (the rear stays rolling: 2F/7 = m (μ_s g − d_r)/6 ≤ μ_s m g), and the pair decelerates at
//   a_A = μ_s g − F/m = (5/12) μ_s g + (7/12) d_r.
// The front's slip V shrinks at (7/2) μ_s g − F/m = (35/12) μ_s g + (7/12) d_r, so it rolls at
//   τ₁ = V / ((35/12) μ_s g + (7/12) d_r),   the pair's speed then V₁ = V − a_A τ₁.
// From then both roll: equal decelerations d_r, F = 0, and the pair rolls on touching until both stop at
//   τ₂ = τ₁ + V₁/d_r,   the rear at x₀ + V τ₁ − a_A τ₁²/2 + V₁²/(2 d_r), the front 2R ahead.
TEST(SustainedContact, ARollingBallPushesASlidingOneAsOnePair)
{
  const bsp::Table table;
  const bsp::MotionParameters p;
  const double V = 0.5, x0 = -0.8;
  const double mu_g = p.sliding_friction * p.gravity, d_r = 5.0 / 7.0 * p.rolling_friction * p.gravity;
  const double a_A = 5.0 / 12.0 * mu_g + 7.0 / 12.0 * d_r;
  const double tau1 = V / (35.0 / 12.0 * mu_g + 7.0 / 12.0 * d_r);
  const double V1 = V - a_A * tau1;
  const double tau2 = tau1 + V1 / d_r;
  const double rear_stop = x0 + V * tau1 - 0.5 * a_A * tau1 * tau1 + V1 * V1 / (2.0 * d_r);

  const std::vector<bsp::TableBall> balls{{"rear", at(x0, 0.0, {V, 0, 0}, {0, V / R, 0})},
                                          {"front", at(x0 + 2.0 * R, 0.0, {V, 0, 0})}};
  const auto run = runToRest(balls, table, p);
  ASSERT_TRUE(run);
  const bsp::TableTrajectory& r = *run;
  EXPECT_LT(eventCount(r), 50u);
  EXPECT_EQ(r.ball_impacts.size(), 1u);  // the sequence's limit, at t = 0: no sequence of collisions

  const bsp::MotionEvent* rolls = firstEvent(r.balls[1], Type::SlideToRoll);
  ASSERT_NE(rolls, nullptr);
  EXPECT_NEAR(rolls->time, tau1, 1e-9);
  EXPECT_NEAR(rolls->state.velocity.x(), V1, 1e-9);
  EXPECT_NEAR(r.balls[0].at(0.5 * tau1).velocity.x(), V - a_A * 0.5 * tau1, 1e-9);  // one deceleration for both
  EXPECT_NEAR(r.balls[1].at(0.5 * tau1).velocity.x(), V - a_A * 0.5 * tau1, 1e-9);
  EXPECT_NEAR(r.balls[0].duration(), tau2, 1e-6);
  EXPECT_NEAR(r.balls[1].duration(), tau2, 1e-6);
  EXPECT_NEAR(r.balls[0].finalState().position.x(), rear_stop, 1e-7);
  EXPECT_NEAR(r.balls[1].finalState().position.x(), rear_stop + 2.0 * R, 1e-7);
  for (double t = 0.0; t <= tau2; t += 1e-3)
    EXPECT_NEAR(gap(r, 0, 1, t), 0.0, 1e-9) << "t " << t;
  expectEnergyNeverRises(r, 1e-3);
}

// (2) The break, the rack with 1e-7 m between its balls, the cue ball at (−0.635, 0.01) sliding at 8 m/s 3° off
// the rack's axis. Balls pressed together after the break (without the sustained contact: pairs meeting ~950 times
// in a few milliseconds until max_events cut a ball's path mid-table) end with every ball at rest, pocketed or off
// the table; energy never rises; no two balls overlap.
TEST(SustainedContact, TheBreakEndsWithNoBallOnABoundOfEvents)
{
  const bsp::Table table;
  const double d = 2.0 * R + 1e-7, heading = 3.0 * M_PI / 180.0;
  std::vector<bsp::TableBall> balls{
      {"cue", at(-0.25 * table.length, 0.01, {8.0 * std::cos(heading), 8.0 * std::sin(heading), 0})}};
  for (int row = 0; row < 5; ++row)
    for (int k = 0; k <= row; ++k)
      balls.push_back({std::to_string(balls.size()),
                       at(0.25 * table.length + row * std::sqrt(3.0) / 2.0 * d, (k - 0.5 * row) * d)});
  bsp::MotionParameters p;
  p.impact.max_seconds = 60.0;
  const auto run = bsp::simulateTable(balls, BALL, table, p);
  ASSERT_TRUE(run.ok()) << run.error().describe();
  for (const bsp::BallTrajectory& b : run.value().balls)
  {
    EXPECT_NE(b.outcome, bsp::MotionOutcome::TimeLimit);
    EXPECT_NE(b.outcome, bsp::MotionOutcome::AgainstCushion);
    EXPECT_LT(b.events.size(), 200u);
  }
  expectEnergyNeverRises(run.value(), 1e-3);
  for (double t = 0.0; t <= run.value().duration(); t += 5e-4)
    for (std::size_t i = 0; i < balls.size(); ++i)
      for (std::size_t j = i + 1; j < balls.size(); ++j)
      {
        if (run.value().balls[i].outcome != bsp::MotionOutcome::Pocketed &&
            run.value().balls[j].outcome != bsp::MotionOutcome::Pocketed)
        {
          EXPECT_GT(gap(run.value(), i, j, t), -1e-9) << i << " " << j << " t " << t;
        }
      }
}

// (3) The pair parts where the front ball's deceleration falls below the rear's. The rear ball slides at V along
// the line of centres with a slip turned 60° from it (spin about x): its friction decelerates it along the line at
// only μ_s g cos 60°, the stunned front ball at μ_s g, so they press together. The front's slip shrinks at about
// (7/2) μ_s g − F/m with F/m ≈ μ_s g/4; the rear's, twice as long, at about (7/2) μ_s g: the front rolls first.
// From then its deceleration along the line is d_r, below the rear's: F would pull, the pair lets go and the gap
// opens as (μ_s g cos ψ − d_r) t²/2. The instant the front rolls is checked against an independent integration of
// the pressed pair's law above (explicit steps of 1e-6 s, the rear's slip turning as it goes).
double pressedPairRollTime(double V, double slip_angle, const bsp::MotionParameters& p)
{
  const double mu_g = p.sliding_friction * p.gravity, dt = 1e-6;
  Eigen::Vector2d d(2.0 * R, 0.0), v_rear(V, 0.0), u_rear(V, V * std::tan(slip_angle)), v_front(V, 0.0);
  double u_front = V, t = 0.0;  // the front's slip stays along the line: the force and its friction are along it
  while (u_front > 0.0)
  {
    const Eigen::Vector2d n = d.normalized(), w = v_front - v_rear;
    const Eigen::Vector2d free_rear = -mu_g * u_rear.normalized(), free_front(-mu_g, 0.0);
    const double wt2 = w.squaredNorm() - std::pow(w.dot(n), 2);
    const double force = -((free_front - free_rear).dot(n) + wt2 / d.norm()) / 2.0;  // per unit mass
    EXPECT_GT(force, 0.0) << "t " << t;
    const Eigen::Vector2d a_rear = free_rear - force * n, a_front = free_front + force * n;
    u_rear += (a_rear + 2.5 * free_rear) * dt;
    u_front += (a_front.x() + 2.5 * free_front.x()) * dt;
    v_rear += a_rear * dt;
    v_front += a_front * dt;
    d += w * dt;
    t += dt;
  }
  return t;
}

TEST(SustainedContact, ThePairPartsWhereTheFrontBallDeceleratesLess)
{
  const bsp::Table table;
  const bsp::MotionParameters p;
  const double V = 0.6, psi = 60.0 * M_PI / 180.0;
  const std::vector<bsp::TableBall> balls{{"rear", at(-0.5, 0.0, {V, 0, 0}, {V * std::tan(psi) / R, 0, 0})},
                                          {"front", at(-0.5 + 2.0 * R, 0.0, {V, 0, 0})}};
  const auto run = runToRest(balls, table, p);
  ASSERT_TRUE(run);
  const bsp::TableTrajectory& r = *run;
  EXPECT_LT(eventCount(r), 50u);
  // The linked steps end with the gap closed but leave a normal velocity of their round-off and step error (below
  // 1e-6 m/s): where the pair lets go it may be met as one ordinary, vanishing impact.
  EXPECT_LE(r.ball_impacts.size(), 2u);

  const bsp::MotionEvent* rolls = firstEvent(r.balls[1], Type::SlideToRoll);
  ASSERT_NE(rolls, nullptr);
  const double parting = pressedPairRollTime(V, psi, p);
  EXPECT_NEAR(rolls->time, parting, 1e-3 * parting);
  const bsp::MotionEvent* rear_rolls = firstEvent(r.balls[0], Type::SlideToRoll);
  ASSERT_NE(rear_rolls, nullptr);
  EXPECT_GT(rear_rolls->time, rolls->time);  // the rear still slides when the front rolls
  for (double t = 0.0; t <= rolls->time; t += 1e-3)
    EXPECT_NEAR(gap(r, 0, 1, t), 0.0, 1e-9) << "t " << t;
  // Apart: the gap grows after the front rolls, as the rear decelerates more along the line.
  const double later = 0.5 * (rolls->time + rear_rolls->time);
  EXPECT_GT(gap(r, 0, 1, later), 1e-6);
  EXPECT_GT(gap(r, 0, 1, rear_rolls->time), gap(r, 0, 1, later));
  expectEnergyNeverRises(r, 1e-3);
}

// (4) A link met at a graze. The rear ball rolls at V into a front one 5e-10 m ahead (a gap within the touching
// tolerance, 1e-9 m) that slides with a slip of 5e-5 m/s, gone within some 1e-5 s. They meet at once at zero
// approach, pressed together: the sequence's limit. The link's first step, cut short by the front's roll, could not
// close the gap (the contact force does not pull): the balls ended it approaching at 1.3e-5 m/s, the next step's
// constant force closed the gap only at its end, overlapping by 3e-8 m on the way, and the pair then drifted apart
// while linked. The link starts with the gap closed: the pair rolls on touching, as in (1).
TEST(SustainedContact, ALinkMetAtAGrazeStartsClosed)
{
  const bsp::Table table;
  const bsp::MotionParameters p;
  const double V = 0.5, x0 = -0.8, slip = 5e-5;
  const std::vector<bsp::TableBall> balls{{"rear", at(x0, 0.0, {V, 0, 0}, {0, V / R, 0})},
                                          {"front", at(x0 + 2.0 * R + 5e-10, 0.0, {V, 0, 0}, {0, (V - slip) / R, 0})}};
  const auto run = runToRest(balls, table, p);
  ASSERT_TRUE(run);
  const bsp::TableTrajectory& r = *run;
  EXPECT_EQ(r.ball_impacts.size(), 1u);
  const double both_rest = std::min(r.balls[0].duration(), r.balls[1].duration());
  for (double t = 0.0; t <= both_rest; t += t < 0.02 ? 1e-5 : 1e-3)
    EXPECT_NEAR(gap(r, 0, 1, t), 0.0, 1e-9) << "t " << t;
  expectEnergyNeverRises(r, 1e-3);
}

// (5) The strike of a jammed row (the configuration of impact_solve's table_shot example with R = 0.028575 m): the
// cue ball frozen to "one", frozen to "two", frozen to the +y rail, struck towards the rail (90°, 5° up, b = 0.3) as
// one multiple impact. All three leave in −y; the cue ball comes back from the −y rail rolling and presses into
// "one", which slides. The sequence's limit, the plastic impact, lifts the cue ball: the rubbing of the balls'
// spins at their contact (the rolling ball's contact point runs down past the other's) pushes it up at 7e-5 m/s, a
// hop of 2e-10 m. The link refused a ball off the cloth, the two met again at one instant as airborne balls at
// zero approach, and "one" ran into the bound of events there (some 950 impacts). A hop within LINK_EXCURSION is taken
// onto the cloth.
TEST(SustainedContact, AJammedRowStruckIntoTheRailEndsWithNoBallOnABoundOfEvents)
{
  const bsp::ShotConfiguration c = jammedRowConfiguration();
  const double r = c.ball_radius, above = c.table.cushion_height - r;
  const double y = 0.5 * c.table.width - std::sqrt(r * r - above * above);  // "two" touches the +y nose
  std::vector<bsp::TableBall> others{{"one", {}}, {"two", {}}};
  others[0].state.position = {-0.5, y - 2.0 * r, r};
  others[1].state.position = {-0.5, y, r};
  const bsp::CuePlacement cue = strokeAt({-0.5, y - 4.0 * r}, r, {M_PI / 2.0, 5.0 * M_PI / 180.0, 0.0, 0.3}, 4.0);
  const auto outcome = bsp::predictShot(cue, c, others);
  ASSERT_TRUE(outcome.ok()) << outcome.error().describe();
  const bsp::TableTrajectory& run = outcome.value().table;
  ASSERT_EQ(run.balls.size(), 3u);
  for (const bsp::BallTrajectory& b : run.balls)
  {
    EXPECT_NE(b.outcome, bsp::MotionOutcome::TimeLimit);
    EXPECT_LT(b.events.size(), 200u);
  }
  EXPECT_LT(run.ball_impacts.size(), 100u);
  expectEnergyNeverRises(run, 1e-3, {c.ball_mass, r});
  for (double t = 0.0; t <= run.duration(); t += 1e-4)
    for (int i = 0; i < 3; ++i)
      for (int j = i + 1; j < 3; ++j)
        EXPECT_GT(gap(run, i, j, t, r), -1e-9) << i << " " << j << " t " << t;
}

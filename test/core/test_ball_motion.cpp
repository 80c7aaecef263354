// Ball motion after the shot (docs/impact_model.md, Motion on the table): closed-form phases against independent
// formulas and the reference numbers of docs/validation.md, Motion after the massé shot; physical invariants,
// landings, cushions and pockets.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "../fixtures/rail_ids.hpp"
#include "billiard_shot_planner/motion/ball_motion.hpp"
#include "billiard_shot_planner/scenarios/ball_table_impact.hpp"
#include "billiard_shot_planner/scenarios/cushion_impact.hpp"

namespace bsp = billiard_shot_planner;
using Type = bsp::MotionEventType;

namespace
{
const double G = 9.81, MU_S = 0.152479, MU_R = 0.0209727;

bsp::Table openTable()
{
  bsp::Table table;
  table.length = table.width = 20.0;
  table.pockets.clear();
  return table;
}

bsp::BallState stateOf(Eigen::Vector3d v, Eigen::Vector3d w, Eigen::Vector2d xy = Eigen::Vector2d::Zero())
{
  bsp::BallState s;
  s.position << xy, 0.0286;
  s.velocity = v;
  s.angular_velocity = w;
  return s;
}

bsp::BallTrajectory predicted(const bsp::BallState& start, const bsp::Table& table, bsp::MotionParameters p = {},
                              double radius = 0.0286)
{
  auto result = bsp::predictTrajectory(start, bsp::BallProperties{0.17, radius}, table, p);
  EXPECT_TRUE(result.ok()) << (result.ok() ? "" : result.error().describe());
  return result.value();
}

const bsp::MotionEvent* firstEvent(const bsp::BallTrajectory& t, Type type)
{
  for (const auto& e : t.events)
    if (e.type == type)
      return &e;
  return nullptr;
}

double energy(const bsp::BallState& s, double m = 0.17, double r = 0.0286)
{
  return 0.5 * m * s.velocity.squaredNorm() + 0.2 * m * r * r * s.angular_velocity.squaredNorm() +
         m * G * (s.position.z() - r);
}

/// Largest distance (m) by which the ball's centre, on the cloth, comes closer to a cushion nose than touching it.
double deepestPenetration(const bsp::BallTrajectory& t, const bsp::Table& table, double radius = 0.0286)
{
  const double reach = std::sqrt(radius * radius - std::pow(table.cushion_height - radius, 2));
  double deepest = -1.0;
  for (const auto& s : t.sample(0.0005))
    if (s.state.position.z() <= radius * (1.0 + 1e-9))
      deepest = std::max({deepest, std::abs(s.state.position.x()) - (0.5 * table.length - reach),
                          std::abs(s.state.position.y()) - (0.5 * table.width - reach)});
  return deepest;
}

/// Speeds (m/s) at which the ball leaves cushion `rail` at its hits, horizontally, in order.
std::vector<double> reboundSpeeds(const bsp::BallTrajectory& t, int rail)
{
  std::vector<double> speeds;
  for (const auto& e : t.events)
    if (e.type == Type::CushionHit && test_fixtures::railOf(e.cushion) == rail)
      speeds.push_back(std::abs(e.state.velocity(rail / 2)));
  return speeds;
}
}  // namespace

TEST(BallMotion, ClosedFormsOfSpecSection75)
{
  struct Case
  {
    Eigen::Vector3d v, w;
    double radius;
    double t_s;
    Eigen::Vector2d x_s, v_roll;
    double t_roll;
    Eigen::Vector2d rest;
  };
  const Case cases[] = {
      {{-1.67629, -0.075349, 0.637937},
       {40.3064, 83.6145, -15.4927},
       0.0286,
       0.80375,
       {-0.88026, -0.18427},
       {-0.51410, -0.38318},
       4.36308,
       {-2.00179, -1.02020}},
      {{-1.67063, -0.274431, 0},
       {28.4584, 79.1561, 0},
       0.0286,
       0.75855,
       {-0.84090, -0.26663},
       {-0.54649, -0.42857},
       4.72577,
       {-2.13219, -1.27929}},
      {{-1.67629, -0.075349, 0.637937},
       {40.3064, 83.6145, -15.4927},
       0.0305,
       0.83685,
       {-0.89753, -0.20102},
       {-0.46871, -0.40506},
       4.21538,
       {-1.88542, -1.05476}},
  };
  bsp::MotionParameters p;
  p.planar = true;
  for (const Case& c : cases)
  {
    const auto t = predicted(stateOf(c.v, c.w), openTable(), p, c.radius);
    // Independent closed forms (docs/impact_model.md, Motion on the table).
    const Eigen::Vector2d v0 = c.v.head<2>();
    const Eigen::Vector2d u0(c.v.x() - c.radius * c.w.y(), c.v.y() + c.radius * c.w.x());
    const double t_s = 2.0 * u0.norm() / (7.0 * MU_S * G);
    const Eigen::Vector2d x_s = v0 * t_s - 0.5 * MU_S * G * t_s * t_s * u0.normalized();
    const Eigen::Vector2d v_roll = v0 - 2.0 / 7.0 * u0;
    const double a_r = 5.0 / 7.0 * MU_R * G;
    const double t_roll = v_roll.norm() / a_r;
    const Eigen::Vector2d rest = x_s + v_roll.squaredNorm() / (2.0 * a_r) * v_roll.normalized();

    const auto* slide_end = firstEvent(t, Type::SlideToRoll);
    const auto* roll_end = firstEvent(t, Type::RollToSpin);
    ASSERT_TRUE(slide_end && roll_end);
    EXPECT_NEAR(slide_end->time, t_s, 1e-9);
    EXPECT_LT((slide_end->state.position.head<2>() - x_s).norm(), 1e-9);
    EXPECT_LT((slide_end->state.velocity.head<2>() - v_roll).norm(), 1e-9);
    EXPECT_NEAR(roll_end->time - slide_end->time, t_roll, 1e-9);
    EXPECT_LT((t.finalState().position.head<2>() - rest).norm(), 1e-9);
    EXPECT_EQ(t.outcome, bsp::MotionOutcome::Rest);
    // The reference values of docs/validation.md, Motion after the massé shot (5 digits).
    EXPECT_NEAR(t_s, c.t_s, 1e-5);
    EXPECT_LT((x_s - c.x_s).norm(), 2e-5);
    EXPECT_LT((v_roll - c.v_roll).norm(), 2e-5);
    EXPECT_NEAR(t_roll, c.t_roll, 1e-5);
    EXPECT_LT((rest - c.rest).norm(), 2e-5);
  }
}

TEST(BallMotion, StunShotAcquiresTopspinAndRollingKeepsTheRollingCondition)
{
  const auto t = predicted(stateOf({1.0, 0.5, 0}, {0, 0, 0}), openTable());
  const auto* roll = firstEvent(t, Type::SlideToRoll);
  ASSERT_TRUE(roll);
  // Topspin for motion along v: ω = ẑ × v / R, i.e. ω_y = v_x/R > 0 and ω_x = −v_y/R.
  EXPECT_GT(roll->state.angular_velocity.y(), 0.0);
  EXPECT_NEAR(roll->state.angular_velocity.y(), roll->state.velocity.x() / 0.0286, 1e-9);
  for (const auto& s : t.sample(0.05))
  {
    if (s.phase != bsp::MotionPhase::Rolling)
      continue;
    const Eigen::Vector3d expected = Eigen::Vector3d::UnitZ().cross(s.state.velocity) / 0.0286;
    EXPECT_LT((s.state.angular_velocity.head<2>() - expected.head<2>()).norm(), 1e-9);
  }
  // Stun: the velocity direction does not change (the slip is along v).
  EXPECT_NEAR(roll->state.velocity.y() / roll->state.velocity.x(), 0.5, 1e-12);
}

TEST(BallMotion, RollingModels)
{
  bsp::MotionParameters paper, pooltool;
  pooltool.rolling_model = bsp::RollingModel::Pooltool;
  pooltool.rolling_friction = paper.rolling_friction * 5.0 / 7.0;  // μ_r(paper) = (7/5) μ_r(pooltool)
  const auto start = stateOf({1.0, 0, 0}, {0, 1.0 / 0.0286, 0});   // rolling from the start
  const auto a = predicted(start, openTable(), paper), b = predicted(start, openTable(), pooltool);
  EXPECT_NEAR(a.finalState().position.x(), b.finalState().position.x(), 1e-9);
  EXPECT_NEAR(a.finalState().position.x(), 1.0 / (2.0 * 5.0 / 7.0 * MU_R * G), 1e-9);
}

TEST(BallMotion, EnergyNeverIncreasesAlongAHoppingShotWithCushions)
{
  bsp::Table table;
  const auto t = predicted(stateOf({-2.0733, 0.2413, 0.4673}, {11.637, 25.280, -6.150}, {0.3, 0.2}), table);
  double previous = energy(t.events.front().state);
  for (const auto& s : t.sample(0.002))
  {
    const double e = energy(s.state);
    EXPECT_LE(e, previous + 1e-9) << "t = " << s.time;
    previous = std::min(previous, e);
  }
  EXPECT_TRUE(firstEvent(t, Type::Landing));
  EXPECT_TRUE(firstEvent(t, Type::CushionHit));
}

TEST(Landing, FrictionlessBounceIsExactlyRestitution)
{
  bsp::BallTableImpact impact;
  impact.mass = 0.17;
  impact.radius = 0.0286;
  impact.velocity = {0.8, -0.3, -1.2};
  impact.angular_velocity = {5, -7, 3};
  impact.table = {0.51625, 0.0, 10.0};
  const auto r = bsp::solve(impact).value();
  EXPECT_NEAR(r.velocity.z(), 0.51625 * 1.2, 1e-12);
  EXPECT_NEAR((r.velocity.head<2>() - impact.velocity.head<2>()).norm(), 0.0, 1e-12);
  // In a trajectory: each landing multiplies v_z by −e.
  bsp::Table table = openTable();
  table.cloth.friction = 0.0;
  const auto t = predicted(stateOf({0.5, 0, 1.0}, {0, 0, 0}), table);
  double v_z = 1.0;
  int landings = 0;
  for (const auto& e : t.events)
  {
    if (e.type != Type::Landing)
      continue;
    v_z *= 0.51625;
    ++landings;
    if (v_z >= bsp::MotionParameters{}.min_bounce_speed)
      EXPECT_NEAR(e.state.velocity.z(), v_z, 1e-12);
    else
      EXPECT_EQ(e.state.velocity.z(), 0.0);
  }
  EXPECT_EQ(landings, 6);  // 1 · 0.51625^k drops below 0.02 m/s at k = 6
}

TEST(Landing, NumberOfBouncesIsFinite)
{
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int k = 0; k < 50; ++k)
  {
    bsp::Table table = openTable();
    table.cloth = {0.3 + 0.69 * unit(rng), 0.5 * unit(rng), 1 + 9 * unit(rng)};
    bsp::MotionParameters p;
    p.min_bounce_speed = 1e-3 * unit(rng);
    const auto t = predicted(stateOf({unit(rng), unit(rng), 3 * unit(rng)}, {20 * unit(rng), 0, 0}), table, p);
    EXPECT_EQ(t.outcome, bsp::MotionOutcome::Rest) << k;
  }
}

TEST(Cushion, StraightInRebondsStraightBackSlower)
{
  bsp::Table table;
  table.pockets.clear();
  const auto t = predicted(stateOf({2.0, 0, 0}, {0, 2.0 / 0.0286, 0}), table);  // rolling along +x
  const auto* hit = firstEvent(t, Type::CushionHit);
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->cushion, "rail.right");
  EXPECT_LT(hit->state.velocity.x(), 0.0);
  const double before = t.at(hit->time - 1e-9).velocity.x();
  EXPECT_LT(-hit->state.velocity.x(), before);
  EXPECT_NEAR(hit->state.velocity.y(), 0.0, 1e-12);
  EXPECT_NEAR(t.finalState().position.y(), 0.0, 1e-12);
  EXPECT_LE(energy(hit->state), energy(t.at(hit->time - 1e-9)) + 1e-12);
}

TEST(Cushion, MirroredIncidenceGivesMirroredOutcomes)
{
  bsp::Table table;
  table.pockets.clear();
  for (double angle : {0.2, 0.6, 1.0})
  {
    const Eigen::Vector3d v(2 * std::cos(angle), 2 * std::sin(angle), 0);
    const Eigen::Vector3d mirrored(v.x(), -v.y(), 0);
    const auto a = predicted(stateOf(v, Eigen::Vector3d::UnitZ().cross(v) / 0.0286), table);
    const auto b = predicted(stateOf(mirrored, Eigen::Vector3d::UnitZ().cross(mirrored) / 0.0286), table);
    EXPECT_NEAR(a.finalState().position.x(), b.finalState().position.x(), 1e-9);
    EXPECT_NEAR(a.finalState().position.y(), -b.finalState().position.y(), 1e-9);
    EXPECT_EQ(a.events.size(), b.events.size());
  }
}

TEST(Cushion, SweepNeverPenetratesOrHangs)
{
  bsp::Table table;
  table.pockets.clear();
  const double reach = std::sqrt(0.0286 * 0.0286 - std::pow(table.cushion_height - 0.0286, 2));
  int hits = 0;
  for (int k = 0; k < 50; ++k)
    for (double speed : {0.5, 2.0, 6.0})
    {
      const double angle = 2 * M_PI * k / 50.0;
      const Eigen::Vector3d v(speed * std::cos(angle), speed * std::sin(angle), 0);
      const auto t = predicted(stateOf(v, Eigen::Vector3d::UnitZ().cross(v) / 0.0286, {0.2, -0.1}), table);
      EXPECT_NE(t.outcome, bsp::MotionOutcome::TimeLimit);
      for (const auto& s : t.sample(0.001))
      {
        EXPECT_LE(std::abs(s.state.position.x()), 0.5 * table.length - reach + 1e-9);
        EXPECT_LE(std::abs(s.state.position.y()), 0.5 * table.width - reach + 1e-9);
      }
      for (const auto& e : t.events)
        hits += e.type == Type::CushionHit;
    }
  EXPECT_GT(hits, 150);
}

TEST(Cushion, AtTheHeightOfTheCentreTheClothNeverLoads)
{
  // Cushion nose at the height of the ball's centre: its normal is horizontal. Without spin about the cushion's
  // direction nothing pushes the ball into the cloth: the cloth contact, touching at rest, never takes part (no
  // derivative of its normal velocity is pressing), changes nothing, and the impact ends; a cloth left touching
  // without force from start to end would keep the impact going to the step limit.
  const bsp::Table table;
  const Eigen::Vector3d spins[] = {Eigen::Vector3d::Zero(), {0, 0, 5.0}, {0, 0, -40.0}};
  for (const Eigen::Vector3d& spin : spins)
  {
    bsp::CushionImpact hit;
    hit.velocity = {1.5, 0.8, 0.0};
    hit.angular_velocity = spin;
    hit.cushion_normal = -Eigen::Vector3d::UnitX();
    hit.cushion = table.cushion;
    hit.cloth = table.cloth;
    hit.on_cloth = false;
    const auto alone = bsp::solve(hit);
    hit.on_cloth = true;
    const auto with_cloth = bsp::solve(hit);
    ASSERT_TRUE(alone.ok()) << alone.error().describe();
    ASSERT_TRUE(with_cloth.ok()) << with_cloth.error().describe();
    EXPECT_LT((with_cloth.value().velocity - alone.value().velocity).cwiseAbs().maxCoeff(), 1e-12) << spin.z();
    EXPECT_LT((with_cloth.value().angular_velocity - alone.value().angular_velocity).cwiseAbs().maxCoeff(), 1e-9);
    EXPECT_LT(with_cloth.value().velocity.x(), 0.0);
    const bsp::ImpactResult& impact = with_cloth.value().impact;
    EXPECT_EQ(impact.impulses[1].normal, 0.0);
    EXPECT_EQ(impact.states.front().active, std::vector<std::size_t>{0});
    for (const bsp::ContactEvent& event : impact.events)
      EXPECT_EQ(event.contact, 0u);
  }
}

TEST(Cushion, AContactReactivatedAtItsThresholdLoadsInsteadOfBeingLetGo)
{
  // A ball whose spin curls it back into a soft cushion (e 0.19) meets it at 5e-12 m/s: a contact that can separate
  // and reactivate at its guard's root, approaching at exactly the threshold of reactivation. The rule that lets go
  // of a contact touching without force must not take that approach for none, or the contact is let go and
  // reactivated at the same instant until the event bound. Any reactivation must load the contact (an end of
  // compression follows).
  bsp::CushionImpact hit;
  hit.velocity = {0.84223154723387328, -5.3852930112494759e-12, 0.0};
  hit.angular_velocity = {0.0040839865442658975, 39.310115375068428, 25.463927966066368};
  hit.cushion_normal = {0.0, 0.7196455183388788, -0.69434165072733944};
  hit.on_cloth = true;
  hit.radius = 0.0214249249257841;
  hit.cloth = {0.080154259562920341, 0.22004573157468907, 1.6326594446956579};
  hit.cushion = {0.1948320499701551, 0.17072985525299081, 7.4442029288128175};
  hit.stiffness_ratio = 4.5272282433105282;
  const auto result = bsp::solve(hit);
  ASSERT_TRUE(result.ok()) << result.error().describe();
  const bsp::ImpactResult& impact = result.value().impact;
  EXPECT_LT(impact.events.size(), 20u);
  int reactivations = 0;
  for (std::size_t k = 0; k + 1 < impact.events.size(); ++k)
  {
    if (impact.events[k].type != bsp::ContactEventType::Reactivation)
      continue;
    ++reactivations;
    EXPECT_EQ(impact.events[k + 1].type, bsp::ContactEventType::EndOfCompression);
    EXPECT_EQ(impact.events[k + 1].contact, impact.events[k].contact);
  }
  EXPECT_LE(reactivations, 1);
  EXPECT_LE(impact.final_kinetic_energy, impact.initial_kinetic_energy * (1.0 + 1e-12));
}

TEST(Cushion, TheClothUnderANoseBelowTheCentreNeverTakesPart)
{
  // A nose at 0.57 radii, so the cushion lifts the ball off the cloth. The cloth contact starts at v_n = 0 and is
  // pulled apart from the first instant; if it stayed in compression (its end of compression missed on an
  // interpolant's round-off above zero), the solve would run into the step bound. A resting contact that the impact
  // does not press never takes part: no event, no impulse.
  bsp::CushionImpact hit;
  hit.velocity = {3.9542302919004766, -0.79789615085793442, 0.0};
  hit.angular_velocity = {28.678041277547241, 58.882103295385363, 16.601380833434163};
  hit.cushion_normal = {-0.90267315436936291, 0.0, 0.43032682507701547};
  hit.on_cloth = true;
  hit.radius = 0.025130732387656125;
  hit.cloth = {0.087060216654894856, 0.25002244031638138, 7.3360581092441777};
  hit.cushion = {0.07198785802784545, 0.44155015878236953, 5.5626097297058834};
  hit.stiffness_ratio = 0.63422044185609516;
  const auto result = bsp::solve(hit);
  ASSERT_TRUE(result.ok()) << result.error().describe();
  const bsp::ImpactResult& impact = result.value().impact;
  EXPECT_LT(impact.events.size(), 10u);
  EXPECT_EQ(impact.states.front().active, std::vector<std::size_t>{0});
  for (const bsp::ContactEvent& event : impact.events)
    EXPECT_EQ(event.contact, 0u);
  EXPECT_EQ(impact.impulses[1].normal, 0.0);
  EXPECT_GT(result.value().velocity.z(), 0.0);  // lifted by the nose
  EXPECT_LE(impact.final_kinetic_energy, impact.initial_kinetic_energy * (1.0 + 1e-12));
}

TEST(Cushion, AGrazingHitWhoseContactsBarelyLoadEnds)
{
  // Spin curls the ball back into a soft cushion (e 0.08), which it meets at 5e-8 m/s. Both contacts then slide with
  // friction cones of length 1e-8 (dimensionless), and the cloth's direction, integrated, would turn at |v_t|/ρ, a
  // stiff equation that runs the integrator to the step bound. A sliding contact whose cone is that short follows
  // its slip quasi-steadily.
  bsp::CushionImpact hit;
  hit.velocity = {-4.7415650383525699e-08, 1.1704347889257103, 0.0};
  hit.angular_velocity = {-33.308179561275331, -16.07797448399953, 50.915517919966952};
  hit.cushion_normal = {0.78446997328822621, 0.0, -0.62016680095694388};
  hit.on_cloth = true;
  hit.radius = 0.033871492077414245;
  hit.cloth = {0.091595829160741549, 0.33505336153968185, 13.924299933076691};
  hit.cushion = {0.0762088460132294, 0.2134698409515208, 1.7641201985977455};
  hit.stiffness_ratio = 7.811801976851882;
  const auto result = bsp::solve(hit);
  ASSERT_TRUE(result.ok()) << result.error().describe();
  const bsp::ImpactResult& impact = result.value().impact;
  EXPECT_LT(impact.events.size(), 30u);
  EXPECT_LE(impact.final_kinetic_energy, impact.initial_kinetic_energy * (1.0 + 1e-12));
  // A graze: the velocity along the rail and the spin barely change.
  EXPECT_NEAR(result.value().velocity.y(), hit.velocity.y(), 1e-6);
  EXPECT_LT((result.value().angular_velocity - hit.angular_velocity).norm(), 1e-4);
  EXPECT_LE(result.value().velocity.dot(hit.cushion_normal), 1e-12);  // not into the cushion any more
}

TEST(Cushion, ABallCurlingIntoASoftCushionIsPredicted)
{
  // The whole path of the table above: a Zeno sequence of ever-smaller cushion hits (2e-3, 6e-5, 1e-6, 4e-8 m/s).
  // Its last hits barely load their contacts, and hits slower still can be missed, letting the ball into the
  // cushion. It must end, against the cushion, where the sequence has converged.
  bsp::Table table;
  table.cushion_height = 0.054877466962702667;
  table.cloth = {0.091595829160741549, 0.33505336153968185, 13.924299933076691};
  table.cushion = {0.0762088460132294, 0.2134698409515208, 1.7641201985977455};
  table.cushion_stiffness_ratio = 7.811801976851882;
  bsp::MotionParameters p;
  p.sliding_friction = 0.11261994609757389;
  p.rolling_friction = 0.043706731396202146;
  p.spinning_friction = 0.010781506537503247;
  p.rolling_model = bsp::RollingModel::Pooltool;
  bsp::BallState start;
  start.position << 0.49933085954083634, -0.34519807284493736, 0.033871492077414245;
  start.velocity << -4.6846204838423384, 1.6686265572513594, 0.39360068737174386;
  start.angular_velocity << -30.343797850137598, -130.77481513384362, 39.227599195920668;
  const auto t = predicted(start, table, p, 0.033871492077414245);
  EXPECT_EQ(t.outcome, bsp::MotionOutcome::AgainstCushion);
  int hits = 0;
  for (const auto& e : t.events)
    hits += e.type == Type::CushionHit ? 1 : 0;
  EXPECT_GE(hits, 4);
  EXPECT_LE(deepestPenetration(t, table, 0.033871492077414245), 1e-9);
}

TEST(Cushion, ATipThatSlipsOnAShortConeFollowsItsSlipOnceRelaxed)
{
  // A hopping ball grazes a nearly plastic cushion (e 3e-4) over a cloth of small friction (0.024). The cushion
  // contact slips from a loaded spring, then becomes a rigid link, with a relaxation time ρ/|v_t| of 1e-6 of the
  // collision's: its integrated direction relaxes onto the slip within a few of those, and integrated on it is a
  // stiff equation. A slip that has relaxed is followed quasi-steadily from the end of the step where it has: the
  // path must end with every impact far inside a step bound of 20 000.
  bsp::Table table;
  table.cloth = {0.27778586242616549, 0.023531720218351863, 3.0322937484677674};
  table.cushion = {0.00030755272638528466, 0.28191673980882598, 7.2193506293204495};
  table.cushion_stiffness_ratio = 1.388670656839039;
  table.cushion_height = 0.044280580569913311;
  bsp::MotionParameters p;
  p.sliding_friction = 0.25059821633465446;
  p.rolling_friction = 0.011891543789761634;
  p.spinning_friction = 0.021637359477288533;
  p.impact.max_steps = 20000;
  bsp::BallState start;
  start.position << 0.507107726960627, 0.20915727107963333, 0.0286;
  start.velocity << 0.31691211311725698, -1.4075822481269467, 0.99481430086045541;
  start.angular_velocity << 156.78669830639049, 75.536983479265402, -28.786878151479055;
  const auto t = predicted(start, table, p);
  EXPECT_EQ(t.outcome, bsp::MotionOutcome::AgainstCushion);
  EXPECT_LE(deepestPenetration(t, table, 0.0286), 1e-9);
}

TEST(Cushion, RandomShotsAlongARailNeverEnterTheCushion)
{
  // Shots within 4 cm of the +y rail with any spin: many curl back into it. Every path stays on the table side of
  // the noses; a path that ends against a cushion has converged there (k = 333 is one, which would otherwise go
  // through the rail).
  const bsp::Table table;
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int against = 0;
  for (int k = 0; k < 400; ++k)
  {
    bsp::BallState start;
    start.position << 0.9 * u(rng), 0.635 - 0.0286 - 0.02 * (1.0 + u(rng)), 0.0286;
    start.velocity << 1.5 * u(rng), 0.3 * u(rng), 0.0;
    start.angular_velocity << 100 * u(rng), 100 * u(rng), 50 * u(rng);
    auto t = bsp::predictTrajectory(start, bsp::BallProperties{}, table);
    if (!t.ok())
    {
      EXPECT_EQ(t.error().field, "position") << k;  // a start inside the side pocket's capture region
      continue;
    }
    EXPECT_LE(deepestPenetration(t.value(), table), 1e-9) << k;
    if (t.value().outcome != bsp::MotionOutcome::AgainstCushion)
      continue;
    ++against;
    EXPECT_EQ(t.value().events.back().type, Type::CushionContact) << k;
    const std::vector<double> rebounds =
        reboundSpeeds(t.value(), test_fixtures::railOf(t.value().events.back().cushion));
    ASSERT_FALSE(rebounds.empty()) << k;
    EXPECT_LT(rebounds.back(), 1e-6) << k;
  }
  EXPECT_GE(against, 1);
}

TEST(Cushion, RandomHitsAndLandingsEndAndLoseEnergy)
{
  // Any incidence, spin and cushion height (nose below, at or above the ball's centre), on the cloth or in the
  // air; landings at any slant and spin. Every impact must end, and none may gain energy.
  const bsp::Table table;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int k = 0; k < 200; ++k)
  {
    bsp::CushionImpact hit;
    const double tilt = k % 10 == 0 ? 0.0 : 0.6 * u(rng);
    hit.cushion_normal = {-std::cos(tilt), 0.0, -std::sin(tilt)};
    const double heading = 1.4 * u(rng), speed = 3.05 + 3.0 * u(rng);
    hit.velocity = speed * Eigen::Vector3d(std::cos(heading), std::sin(heading), 0.0);
    hit.angular_velocity = k % 3 == 0 ? Eigen::Vector3d(Eigen::Vector3d::UnitZ().cross(hit.velocity) / 0.0286)
                                      : Eigen::Vector3d(200 * u(rng), 200 * u(rng), 150 * u(rng));
    hit.on_cloth = k % 5 != 0;
    hit.cushion = table.cushion;
    hit.cloth = table.cloth;
    hit.stiffness_ratio = table.cushion_stiffness_ratio;
    const auto result = bsp::solve(hit);
    ASSERT_TRUE(result.ok()) << k << ": " << result.error().describe();
    const bsp::ImpactResult& impact = result.value().impact;
    EXPECT_LE(impact.final_kinetic_energy, impact.initial_kinetic_energy * (1 + 1e-9)) << k;
  }
  for (int k = 0; k < 200; ++k)
  {
    const bsp::BallTableImpact landing{0.17,
                                       0.0286,
                                       {4 * u(rng), 4 * u(rng), -1.51 + 1.49 * u(rng)},
                                       {100 * u(rng), 100 * u(rng), 100 * u(rng)},
                                       table.cloth};
    const auto result = bsp::solve(landing);
    ASSERT_TRUE(result.ok()) << k << ": " << result.error().describe();
    const bsp::ImpactResult& impact = result.value().impact;
    EXPECT_LE(impact.final_kinetic_energy, impact.initial_kinetic_energy * (1 + 1e-9)) << k;
  }
}

TEST(Cushion, ABallPressedIntoTheRailByItsSpinEndsAgainstIt)
{
  // Side spin (ω_x < 0) drives the slip into the +y rail: the ball comes back after every hit, slower each time, a
  // Zeno sequence. Followed to its last hits, approaching at 1e-12 m/s and less, a hit would be missed and the ball
  // would go through the cushion. The path ends where the sequence has converged, against the cushion.
  const bsp::Table table;
  // The sequence's physics is under test, not the default 10 s budget, of which its hits take 6-10 s under the
  // sanitizers on a busy two-core host.
  bsp::MotionParameters p;
  p.impact.max_seconds = 60.0;
  const auto t = predicted(stateOf({0.3, 0.0, 0.0}, {-100.0, 0.0, 0.0}, {-0.8, 0.635 - 0.0286 - 0.002}), table, p);
  EXPECT_EQ(t.outcome, bsp::MotionOutcome::AgainstCushion);
  ASSERT_EQ(t.events.back().type, Type::CushionContact);
  EXPECT_EQ(t.events.back().cushion, "rail.top");
  // A Zeno sequence: every rebound from the rail slower than the one before, the last one below the 1e-6 m/s that
  // makes the contact sustained.
  const std::vector<double> rebounds = reboundSpeeds(t, 3);
  ASSERT_GE(rebounds.size(), 2u);
  for (std::size_t k = 1; k < rebounds.size(); ++k)
    EXPECT_LT(rebounds[k], rebounds[k - 1]) << k;
  EXPECT_LT(rebounds.back(), 1e-6);
  EXPECT_LT(std::abs(t.events.back().state.velocity.y()), 1e-6);  // converged: no approach left
  EXPECT_GT(t.events.back().state.velocity.x(), 0.05);            // still moving along the rail
  EXPECT_LE(deepestPenetration(t, table), 1e-9);
}

TEST(Cushion, ABallCurlingBackToTheRailFasterStillRebounds)
{
  // The same spin with more speed into the rail and along it: the spin brings the ball back after its first hit,
  // slower each time but far above 1e-6 m/s, and the run along the rail ends in the corner pocket ahead. Slow
  // returns to a rail are hits, not sustained contact.
  const bsp::Table table;
  const auto t = predicted(stateOf({2.0, 0.05, 0.0}, {-50.0, 0.0, 0.0}, {-0.8, 0.635 - 0.0286 - 0.002}), table);
  EXPECT_EQ(t.outcome, bsp::MotionOutcome::Pocketed);
  const std::vector<double> rebounds = reboundSpeeds(t, 3);
  ASSERT_GE(rebounds.size(), 2u);
  EXPECT_GT(rebounds.back(), 1e-6);
  EXPECT_LE(deepestPenetration(t, table), 1e-9);
}

TEST(Cushion, ARollingBallsHitDoesNotDependOnRoundOffInItsClothContact)
{
  // The ball rolls into the −y rail. Its cloth contact has a slip of round-off (1e-16) at the hit, and the first
  // stick/slip decisions must not depend on that noise: velocities below round-off are zero, and the hit must be
  // the same by every route (default, integrated from the start at 1e-13), to 1e-8.
  bsp::BallState start;
  start.position << 1.019103830667047, -0.11099287062386398, 0.0286;
  start.velocity << -1.3167934302843094, -0.28434362218257281, 0.0;
  start.angular_velocity << 39.354559241073709, -141.48746768861722, -14.736403711242696;
  const bsp::Table table;
  bsp::MotionParameters integrated;
  integrated.impact.quasi_steady_slip = false;
  integrated.impact.relative_tolerance = 1e-13;
  integrated.impact.absolute_tolerance = 1e-15;
  const auto by_default = predicted(start, table);
  const auto reference = predicted(start, table, integrated);
  ASSERT_GE(by_default.events.size(), 3u);
  ASSERT_GE(reference.events.size(), 3u);
  const bsp::MotionEvent& hit = by_default.events[2];
  ASSERT_EQ(hit.type, Type::CushionHit);
  ASSERT_EQ(reference.events[2].type, Type::CushionHit);
  EXPECT_EQ(by_default.events[1].type, Type::SlideToRoll);  // rolling into the rail
  EXPECT_LE((hit.state.velocity - reference.events[2].state.velocity).norm(), 1e-8);
  EXPECT_LE((hit.state.angular_velocity - reference.events[2].state.angular_velocity).norm(), 1e-8);
}
TEST(Cushion, AirborneBallsTouchTheNoseAtOneRadiusOrPassOverIt)
{
  // Hops towards the rails with any spin, for noses below, at and above the ball's centre height. In the air the
  // ball must meet the nose where its centre is one radius from the nose line (taken to hit it at the on-cloth
  // reach, where it may not touch it yet, it could have no approach left and the prediction would fail), or pass
  // over it and leave the table with its bottom above the nose.
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double r = 0.0286;
  int airborne_hits = 0, over = 0;
  for (int k = 0; k < 300; ++k)
  {
    bsp::Table table;
    table.pockets.clear();
    table.cushion_height = (k % 3 == 0 ? 1.27 : k % 3 == 1 ? 1.0 : 0.9) * r;
    const Eigen::Vector3d v(3.0 * u(rng), 1.5 * u(rng), 1.35 + 1.15 * u(rng));
    const auto t = predicted(stateOf(v, {60 * u(rng), 60 * u(rng), 40 * u(rng)}, {1.0 * u(rng), 0.5 * u(rng)}), table);
    for (const auto& e : t.events)
    {
      if (e.type != Type::CushionHit)
        continue;
      const int axis = test_fixtures::railOf(e.cushion) / 2;
      const double edge = 0.5 * (axis == 0 ? table.length : table.width);
      const double inside = edge - std::abs(e.state.position(axis));
      const double above = e.state.position.z() - table.cushion_height;
      if (&e == &t.events.back() && t.outcome == bsp::MotionOutcome::OffTable)
      {
        EXPECT_NEAR(inside, 0.0, 1e-9) << k;
        EXPECT_GT(above, r) << k;
        ++over;
        continue;
      }
      EXPECT_NEAR(std::hypot(inside, above), r, 1e-9) << k << " at t = " << e.time;
      airborne_hits += e.state.position.z() > r * (1 + 1e-9);
    }
  }
  EXPECT_GT(airborne_hits, 20);
  EXPECT_GT(over, 20);
}

namespace
{
struct RandomTable
{
  double radius, cushion_height;
  bsp::SurfaceContact cloth, cushion;
  double ratio;
  Eigen::Vector2d position;
  Eigen::Vector3d velocity, spin;
  double sliding, rolling, spinning;
};

bsp::BallTrajectory predictedOn(const RandomTable& c)
{
  bsp::Table table;
  table.cushion_height = c.cushion_height;
  table.cloth = c.cloth;
  table.cushion = c.cushion;
  table.cushion_stiffness_ratio = c.ratio;
  bsp::MotionParameters p;
  p.sliding_friction = c.sliding;
  p.rolling_friction = c.rolling;
  p.spinning_friction = c.spinning;
  p.rolling_model = bsp::RollingModel::Pooltool;
  return predicted(stateOf(c.velocity, c.spin, c.position), table, p, c.radius);
}
}  // namespace

TEST(Cushion, HopsOfNothing)
{
  // Cushion hits that leave the ball a hop of about 1e-14 s. Over the first, the search for an airborne cushion
  // contact must not hand TOMS 748 bounds out of order; the second comes down at v_z = +5e-16, which the landing
  // must not refuse for having no approach. Both must simply go on.
  const RandomTable tables[] = {
      {0.026892482682571821,
       0.03566483138945329,
       {0.11530287887407221, 0.40559454927167438, 5.3766107618993759},
       {0.86563711273110966, 0.029394118214602413, 10.653185795157576},
       0.30187670855751941,
       {-0.32783169370675491, -0.32039563071398003},
       {-2.527272371064893, 2.0465671545387156, 0},
       {-39.321945248476332, 6.1526420839000835, 73.539974187355313},
       0.40033697353835063,
       0.017584699723765747,
       0.015635775746731924},
      {0.020396282913948766,
       0.032130016616502131,
       {0.0018332732791070171, 0.23924326211609928, 8.5057544820374247},
       {0.85759256074212753, 0.37764563968023784, 2.2337714791081762},
       0.24218399024800819,
       {0.84270574897956729, 0.41728131623202624},
       {-2.8560519362639947, -0.74273020860031669, 0},
       {64.997444491501554, 44.766055355430346, -19.631515092058283},
       0.32086812449774171,
       0.039342547153758477,
       0.024852889379475902},
  };
  for (const RandomTable& c : tables)
  {
    const bsp::BallTrajectory t = predictedOn(c);  // fails the test if the prediction returns an error
    EXPECT_NE(t.outcome, bsp::MotionOutcome::TimeLimit);
    double previous = energy(t.events.front().state, 0.17, c.radius);
    for (const auto& e : t.events)
    {
      EXPECT_LE(energy(e.state, 0.17, c.radius), previous + 1e-9) << e.time;
      previous = std::min(previous, energy(e.state, 0.17, c.radius));
    }
  }
}

TEST(Pocket, StraightAtACornerIsPocketedBesideItIsNot)
{
  bsp::Table table;
  const Eigen::Vector2d corner(0.5 * table.length, 0.5 * table.width);
  const Eigen::Vector2d start(0.0, 0.0);
  const Eigen::Vector2d aim = (corner - start).normalized();
  const Eigen::Vector3d v(3 * aim.x(), 3 * aim.y(), 0);
  const auto in = predicted(stateOf(v, Eigen::Vector3d::UnitZ().cross(v) / 0.0286, start), table);
  EXPECT_EQ(in.outcome, bsp::MotionOutcome::Pocketed);
  EXPECT_EQ(in.events.back().pocket, "top_right");
  // Aimed at a point on the long cushion 0.25 m before the corner.
  const Eigen::Vector2d beside = (Eigen::Vector2d(corner.x() - 0.25, corner.y()) - start).normalized();
  const Eigen::Vector3d w(1.0 * beside.x(), 1.0 * beside.y(), 0);
  const auto out = predicted(stateOf(w, Eigen::Vector3d::UnitZ().cross(w) / 0.0286, start), table);
  EXPECT_NE(out.events[1].type, Type::Pocketed);
  EXPECT_TRUE(firstEvent(out, Type::CushionHit));
}

TEST(BallMotionBadInput, NamedErrors)
{
  bsp::Table table;
  const bsp::BallProperties ball;
  auto error = [&](const bsp::BallState& s, const bsp::MotionParameters& p = {})
  { return bsp::predictTrajectory(s, ball, table, p).error(); };
  EXPECT_EQ(error(stateOf({1, 0, 0}, {0, 0, 0}, {2.0, 0.0})).field, "position");   // off the table
  EXPECT_EQ(error(stateOf({1, 0, 0}, {0, 0, 0}, {1.26, 0.0})).field, "position");  // overlaps a cushion
  EXPECT_EQ(error(stateOf({1, 0, 0}, {0, 0, 0}, {1.25, 0.6})).field, "position");  // in a pocket region
  EXPECT_EQ(error(stateOf({NAN, 0, 0}, {0, 0, 0})).field, "v");
  bsp::MotionParameters p;
  p.sliding_friction = -0.1;
  EXPECT_EQ(error(stateOf({1, 0, 0}, {0, 0, 0}), p).field, "sliding_friction");
  p = {};
  p.rolling_friction = 0.0;
  EXPECT_EQ(error(stateOf({1, 0, 0}, {0, 0, 0}), p).field, "rolling_friction");
  table.cushion.friction = -1;
  EXPECT_EQ(error(stateOf({1, 0, 0}, {0, 0, 0})).field, "table.cushion.friction");
}

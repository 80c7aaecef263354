// The integrated cue strike (paper §8): the massé shot of §9.2 against the converged reference of
// docs/validation.md, The massé shot; the invariants of docs/impact_model.md, The cue strike, on random shots; and
// invalid shots.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "../fixtures/paper_masse.hpp"
#include "billiard_shot_planner/scenarios/ball_ball_table.hpp"
#include "billiard_shot_planner/scenarios/cue_strike.hpp"
#include "same_solution.hpp"

namespace bsp = billiard_shot_planner;

namespace
{
/// The paper's massé inputs with the corrections of docs/validation.md, The massé shot: m = 0.17 kg, r = 0.0286 m.
bsp::CueStrike masse(const Eigen::Vector3d& cue_direction, double cue_eta2 = 7.0)
{
  bsp::CueStrike s = fixtures::paperMasseStrike(cue_direction);
  s.cue_contact.eta2 = cue_eta2;
  return s;
}

bsp::CueStrikeResult solved(const bsp::CueStrike& strike)
{
  auto result = bsp::solve(strike);
  EXPECT_TRUE(result.ok()) << (result.ok() ? "" : result.error().describe());
  return result.value();
}

void expectRelative(const Eigen::Vector3d& actual, const Eigen::Vector3d& expected, double tolerance, const char* what)
{
  EXPECT_LE((actual - expected).norm(), tolerance * expected.norm())
      << what << ": " << actual.transpose() << " vs " << expected.transpose();
}

/// A strike of the random sweeps: the paper's massé strike with another hit point, cue, tip and stiffness ratio.
bsp::CueStrike sweptStrike(const Eigen::Vector3d& hit_normal, const Eigen::Vector3d& cue_direction, double cue_speed,
                           const bsp::SurfaceContact& cue_contact, double stiffness_ratio)
{
  bsp::CueStrike s = fixtures::paperMasseStrike();
  s.hit_normal = hit_normal;
  s.cue_direction = cue_direction;
  s.cue_speed = cue_speed;
  s.cue_contact = cue_contact;
  s.stiffness_ratio = stiffness_ratio;
  return s;
}

/// Relative tolerance as given, absolute a hundredth of it (the defaults' ratio): the benchmarks' settings.
using bench::withTolerance;

/// +1 when the sliding ball's path curves left (counter-clockwise seen from above), −1 when right. The sliding
/// friction opposes the contact slip u = v + R ẑ × ω (docs/impact_model.md, Motion on the table).
int turn(const bsp::CueStrikeResult& r, double radius)
{
  const Eigen::Vector2d v = r.velocity.head<2>();
  const Eigen::Vector2d u(v.x() - radius * r.angular_velocity.y(), v.y() + radius * r.angular_velocity.x());
  const double cross = v.x() * (-u.y()) - v.y() * (-u.x());
  return cross > 0 ? 1 : -1;
}

double kineticEnergy(const bsp::CueStrike& s, const bsp::CueStrikeResult& r)
{
  const Eigen::Vector3d c = s.cue_direction.normalized();
  const Eigen::Vector3d tip_across = r.tip_velocity - r.tip_velocity.dot(c) * c;
  const double across = std::isinf(s.cue_end_mass) ? 0.0 : 0.5 * s.cue_end_mass * tip_across.squaredNorm();
  return 0.5 * s.cue_mass * r.cue_velocity * r.cue_velocity + across + 0.5 * s.ball_mass * r.velocity.squaredNorm() +
         0.2 * s.ball_mass * s.ball_radius * s.ball_radius * r.angular_velocity.squaredNorm();
}
}  // namespace

TEST(MasseShot, MatchesTheSpecConvergedTableForAllFourCueDirections)
{
  struct Row
  {
    Eigen::Vector3d c;
    std::vector<std::string> states;
    Eigen::Vector3d v, w;
    double cue_velocity, cue_normal, cue_tangential, table_normal, table_tangential;
  };
  const Row rows[] = {
      {{0.2761, -0.1388, -0.9511},
       {"S1", "S3", "S4"},
       {-1.42587, 0.24610, 0.45511},
       {17.0970, 83.8724, -1.1087},
       0.24554,
       1.67022,
       0.39596,
       1.72678,
       0.22954},
      {{-0.2761, -0.1388, -0.9511},
       {"S1", "S2", "S4"},
       {-2.07330, 0.24128, 0.46729},
       {11.6367, 25.2785, -6.1496},
       0.34248,
       1.39491,
       0.20696,
       1.39551,
       0.15300},
      {{-0.2761, 0.1388, -0.9511},
       {"S1", "S2", "S4"},
       {-2.09568, 0.52433, 0.43209},
       {2.2641, 21.0055, 2.2622},
       0.33885,
       1.37476,
       0.18669,
       1.36262,
       0.14565},
      {{0.2761, 0.1388, -0.9511},
       {"S1", "S3", "S4"},
       {-1.44503, 0.48462, 0.51161},
       {15.8893, 75.4765, 3.9977},
       0.27812,
       1.62908,
       0.37044,
       1.68785,
       0.22049},
  };
  // The reference gives 5–6 digits from fixed-step RK4 (Δt = 2e-4 … 5e-5): 1e-4 relative, vectors by their norm.
  const double tol = 1e-4;
  for (const Row& row : rows)
  {
    SCOPED_TRACE(testing::Message() << "c = " << row.c.transpose());
    const auto r = solved(masse(row.c));
    EXPECT_EQ(r.states, row.states);
    expectRelative(r.velocity, row.v, tol, "v");
    expectRelative(r.angular_velocity, row.w, tol, "omega");
    EXPECT_NEAR(r.cue_velocity, row.cue_velocity, tol * row.cue_velocity);
    const Eigen::Vector3d n = r.hit_normal;
    const double cue_normal = r.impulse_cue.dot(n);
    EXPECT_NEAR(cue_normal, row.cue_normal, tol * row.cue_normal);
    EXPECT_NEAR((r.impulse_cue - cue_normal * n).norm(), row.cue_tangential, tol * row.cue_normal);
    EXPECT_NEAR(r.impulse_table.z(), row.table_normal, tol * row.table_normal);
    EXPECT_NEAR(r.impulse_table.head<2>().norm(), row.table_tangential, tol * row.table_normal);
    EXPECT_FALSE(r.miscue);
  }
}

TEST(MasseShot, PaperPredictionQualitatively)
{
  // docs/validation.md, The massé shot: with the literal cue direction the paper's (57) is a plausibility target:
  // sequence <S1, S2, S4>, a left-turning path, v_x ≈ −1.7 … −2.1, ω_y > 0, ω_x > 0, ω_z < 0.
  const auto r = solved(masse({-0.2761, -0.1388, -0.9511}));
  EXPECT_EQ(r.states, (std::vector<std::string>{"S1", "S2", "S4"}));
  EXPECT_EQ(turn(r, 0.0286), 1);
  EXPECT_LT(r.velocity.x(), -1.5);
  EXPECT_GT(r.velocity.x(), -2.2);
  EXPECT_GT(r.angular_velocity.y(), 0.0);
  EXPECT_GT(r.angular_velocity.x(), 0.0);
  EXPECT_LT(r.angular_velocity.z(), 0.0);
  EXPECT_GT(r.velocity.z(), 0.0);  // the ball leaves the cloth
}

TEST(MasseShot, EtaSweepTrendOfFigure16d)
{
  // docs/validation.md, The massé shot: for the literal cue direction the path turns right for η² (cue–ball) = 2, 3,
  // 4 and left from 5; for the (+, −) direction left at 2, right at 3–6, left from 7.
  const Eigen::Vector3d literal(-0.2761, -0.1388, -0.9511), mirrored(0.2761, -0.1388, -0.9511);
  const int literal_turns[] = {-1, -1, -1, 1, 1, 1};
  const int mirrored_turns[] = {1, -1, -1, -1, -1, 1};
  for (int k = 0; k < 6; ++k)
  {
    const double eta2 = 2.0 + k;
    EXPECT_EQ(turn(solved(masse(literal, eta2)), 0.0286), literal_turns[k]) << "literal, eta2 " << eta2;
    EXPECT_EQ(turn(solved(masse(mirrored, eta2)), 0.0286), mirrored_turns[k]) << "mirrored, eta2 " << eta2;
  }
}

TEST(CueStrikeInvariants, RandomShots)
{
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int checked = 0;
  for (int k = 0; checked < 200 && k < 2000; ++k)
  {
    bsp::CueStrike s;
    s.cue_end_mass = bsp::CUE_HELD_ON_AXIS;  // the paper's shooter (a hand-held cue: test_cue_stroke.cpp)
    const double polar = std::acos(unit(rng) * 0.999), azimuth = 2 * M_PI * unit(rng);
    s.hit_normal = {std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth), std::cos(polar)};
    s.cue_direction = Eigen::Vector3d(unit(rng) - 0.5, unit(rng) - 0.5, -unit(rng)).normalized();
    if (s.hit_normal.dot(s.cue_direction) > -0.2)
      continue;
    s.cue_mass = 0.3 + unit(rng);
    s.cue_speed = 0.5 + 5 * unit(rng);
    s.ball_mass = 0.1 + 0.2 * unit(rng);
    s.ball_radius = 0.025 + 0.01 * unit(rng);
    s.cue_contact = {0.3 + 0.7 * unit(rng), unit(rng), 1 + 9 * unit(rng)};
    s.table_contact = {0.3 + 0.7 * unit(rng), 0.4 * unit(rng), 1 + 9 * unit(rng)};
    s.stiffness_ratio = std::exp(4 * unit(rng) - 2);
    ++checked;
    SCOPED_TRACE(k);
    const auto r = solved(s);
    const double r_ball = s.ball_radius;
    // Angular momentum about the line through the two contact points stays zero (docs/impact_model.md, The cue
    // strike, invariant 1).
    const Eigen::Vector3d moment = 0.4 * r_ball * r.angular_velocity + Eigen::Vector3d::UnitZ().cross(r.velocity);
    const double scale = 0.4 * r_ball * r.angular_velocity.norm() + r.velocity.norm();
    EXPECT_LE(std::abs((r.hit_normal + Eigen::Vector3d::UnitZ()).dot(moment)), 1e-9 * scale);
    // Energy never increases (invariant 2).
    EXPECT_LE(kineticEnergy(s, r), 0.5 * s.cue_mass * s.cue_speed * s.cue_speed * (1 + 1e-12));
    // Linearity in cue speed (invariant 3; docs/impact_model.md, Scaling).
    bsp::CueStrike faster = s;
    faster.cue_speed *= 2.0;
    const auto f = solved(faster);
    EXPECT_EQ(f.states, r.states);
    EXPECT_LE((f.velocity - 2 * r.velocity).norm(), 1e-9 * 2 * r.velocity.norm());
    EXPECT_LE((f.angular_velocity - 2 * r.angular_velocity).norm(), 1e-9 * 2 * r.angular_velocity.norm());
    EXPECT_LE((f.impulse_cue - 2 * r.impulse_cue).norm(), 1e-9 * 2 * r.impulse_cue.norm());
  }
  EXPECT_EQ(checked, 200);
}

TEST(CueStrikeInvariants, RigidLinksThatSlideNeverGainEnergy)
{
  // Jammed strikes: both contacts chatter into rigid links, which then slide while their forces grow, and stick
  // again. A sliding link's sliding speed must include the growth of its friction cone, ρ̇ = μḟ/κ: without it the
  // spring a link sticks with holds energy nothing has paid for, and such strikes leave with more kinetic energy
  // than they came with.
  struct Jam
  {
    Eigen::Vector3d cue_direction, hit_normal;
    double cue_speed, cue_mass;
    bsp::SurfaceContact cue, table;
    double stiffness_ratio;
  };
  const bsp::CueStrike masse = fixtures::paperMasseStrike();
  const Jam jams[] = {
      {{-0.7871762474244407, -0.61672086546683802, -0.0029882417255300731},
       {0.21503838406297757, -0.11679814832663615, 0.96959614578805564},
       0.21788224214008192,
       masse.cue_mass,
       masse.cue_contact,
       masse.table_contact,
       masse.stiffness_ratio},
      {{0.49941299877967876, -0.037731953054129991, -0.86554200150461169},
       {-0.49941299877967876, 0.037731953054129991, 0.86554200150461169},
       2.0831922779182488,
       0.54190984148992172,
       {0.10387289617134457, 0.64075709799307645, 6.7853144220855546},
       {0.04804074207779279, 0.175589126929102, 2.460699860364413},
       0.017544385182411134},
      {{0.39791023202441128, -0.86637738193804037, -0.30175764997173815},
       {0.53583349210556264, 0.45161813107161947, 0.71338876668008699},
       1.3801049935786582,
       0.70042339330260606,
       {0.15710188014231929, 0.94689645405029577, 7.2690167193028881},
       {0.278271958044981, 0.41525356309033856, 2.3628250367445074},
       1.2653022278394035},
  };
  for (const Jam& jam : jams)
  {
    bsp::CueStrike strike = masse;
    strike.cue_direction = jam.cue_direction;
    strike.hit_normal = jam.hit_normal;
    strike.cue_speed = jam.cue_speed;
    strike.cue_mass = jam.cue_mass;
    strike.cue_contact = jam.cue;
    strike.table_contact = jam.table;
    strike.stiffness_ratio = jam.stiffness_ratio;
    const auto result = bsp::solve(strike);
    ASSERT_TRUE(result.ok()) << result.error().describe();
    const bsp::ImpactResult& impact = result.value().impact;
    EXPECT_TRUE(impact.converged);  // the rigid-link limit was taken
    EXPECT_LE(impact.final_kinetic_energy, impact.initial_kinetic_energy * (1 + 1e-9)) << jam.cue_speed;
    // Nothing stores energy but the springs, and a sliding link's cone spring holds ½κρ², ρ = μF_n/κ with F_n its
    // constraint force: the total, kinetic plus strain, only falls from event to event (to the integration's 1e-9).
    // Reported without that strain, the total would rise between events.
    double previous = impact.initial_kinetic_energy;
    for (const bsp::ContactEvent& event : impact.events)
    {
      EXPECT_LE(event.at.total_energy(), previous + 1e-9 * impact.initial_kinetic_energy)
          << jam.cue_speed << " at " << bsp::toString(event.type) << " of contact " << event.contact;
      previous = event.at.total_energy();
    }
  }
}

TEST(CueStrikeInvariants, FrictionlessCentralHitIsBallBallTable)
{
  // docs/impact_model.md, The cue strike, invariant 4: μ = 0, n̂ = ẑ, ĉ = −ẑ is the paper's ball–ball–table
  // collision with the cue as the upper ball.
  bsp::CueStrike s;
  s.cue_mass = 1.0;
  s.ball_mass = 2.0 / std::sqrt(3.0);
  s.cue_speed = 1.0;
  s.cue_contact = {0.9, 0.0, 7.0};
  s.table_contact = {0.7, 0.0, 10.0};
  const auto r = solved(s);
  const auto reference = bsp::solve(bsp::BallBallTable{1.0, s.ball_mass, 1.0, 0.9, 0.7, -1.0}).value();
  EXPECT_EQ(r.states, bsp::ballBallTableStates(reference));
  EXPECT_NEAR(-r.cue_velocity, reference.velocity(0), 1e-9);
  EXPECT_NEAR(r.velocity.z(), reference.velocity(1), 1e-9);
  EXPECT_NEAR(r.velocity.head<2>().norm(), 0.0, 1e-12);
  EXPECT_NEAR(r.angular_velocity.norm(), 0.0, 1e-9);
}

TEST(CueStrikeInvariants, AClothThatSlipsFromTheFirstInstantSlipsAlongItsSlip)
{
  // A strike whose cloth is pushed out of its friction cone as soon as it is loaded, so it sticks for an instant
  // with springs of round-off, whose direction is noise. Its slip must start along its slip velocity, not along that
  // noise, so that the result does not depend on the tolerance: default tolerance, 1e-14, and every direction
  // integrated from its start agree to 1e-9.
  const bsp::CueStrike s =
      sweptStrike({-0.0059866718568623717, -0.8184100040856398, 0.57460353720858826},
                  {-0.63771989546842733, 0.3750190631666474, -0.67281055073872631}, 1.533137555961102,
                  {0.72936345541397019, 0.22113390153582657, 4.4477536323161857}, 0.53629678795849933);
  const bsp::SolverOptions tight = withTolerance(1e-14);
  bsp::SolverOptions integrated;
  integrated.quasi_steady_slip = false;
  const auto by_default = solved(s);
  ASSERT_TRUE(by_default.impact.events.size() >= 1);
  EXPECT_EQ(by_default.impact.events.front().type, bsp::ContactEventType::StickToSlip);
  EXPECT_LE(by_default.impact.events.front().at.time, 1e-15);
  for (const bsp::SolverOptions& options : {tight, integrated})
  {
    const auto other = bsp::solve(s, options);
    ASSERT_TRUE(other.ok());
    EXPECT_LE((by_default.velocity - other.value().velocity).lpNorm<Eigen::Infinity>(), 1e-9);
    EXPECT_LE((by_default.angular_velocity - other.value().angular_velocity).lpNorm<Eigen::Infinity>(), 1e-9);
  }
}

TEST(CueStrikeInvariants, SlipsFollowedQuasiSteadilyMatchIntegrationFromTheStart)
{
  bsp::SolverOptions integrated = withTolerance(1e-13);
  integrated.quasi_steady_slip = false;
  // The tip touches the ball again slipping at 0.05 of the collision's speed: a slow slip, whose relaxation time
  // ρ/|v_t| grows past the quasi-steady limit while its cone spring is still short. Its direction must be released
  // by its relaxation time (5.6e-4 at the default tolerance), not by its cone length, and followed with the
  // second-order lag until then: within 1e-7 of integration from the start.
  const bsp::CueStrike slow_tip =
      sweptStrike({0.43974713737647586, 0.53888293038194068, 0.71848983466167926},
                  {-0.21859785974501489, -0.39627898953164026, -0.89172750219485819}, 3.6471754677974122,
                  {0.61575037877792094, 0.69176609668587707, 2.5721473793704277}, 0.15254774237691854);
  // The cloth starts with a slip of round-off (1e-18) and sticks at once. A release criterion that scaled with the
  // slip speed alone would release it on that noise (the relaxation time takes |v_t| floored at round-off).
  const bsp::CueStrike cloth_at_rest =
      sweptStrike({-0.84224125288421292, -0.08492203412386945, 0.53237009688777204},
                  {0.92603154864526604, -0.36266782884654652, -0.10458306188567118}, 3.2641601515557372,
                  {0.78187539609516743, 0.20062866495228771, 2.377693402965825}, 9.6936265574112177);
  for (const bsp::CueStrike& s : {slow_tip, cloth_at_rest})
  {
    const auto by_default = solved(s);
    const auto reference = bsp::solve(s, integrated);
    ASSERT_TRUE(reference.ok());
    EXPECT_EQ(by_default.impact.events.size(), reference.value().impact.events.size());
    EXPECT_LE((by_default.velocity - reference.value().velocity).lpNorm<Eigen::Infinity>(), 1e-7);
    EXPECT_LE((by_default.angular_velocity - reference.value().angular_velocity).lpNorm<Eigen::Infinity>(), 1e-7);
  }
}

TEST(CueStrikeInvariants, APlasticTipTouchingAgainWhileItSlidesEnds)
{
  // Two strikes with wide ranges (plastic tips, soft tables, small cloth friction). The tip leaves the ball and
  // touches it again at once, a rigid link sliding with a finite force from its first instant: its slip starts the
  // state beyond the quasi-steady limit of its relaxation time, so its release guard starts above zero and never
  // rises, and the slip must be released at once rather than followed. Both must end, as integration from the start
  // does (same events, 1e-9 m/s and rad/s).
  bsp::CueStrike soft_cloth =
      sweptStrike({-0.51546468129134915, -0.49097920032930936, 0.70230733100630516},
                  {0.18151937726589853, 0.98333698554480098, -0.0099543225115667332}, 0.66625016814202542,
                  {0.0, 0.47103365307157263, 1.2356971054028185}, 0.038806390172254533);
  soft_cloth.table_contact = {0.78376342398232379, 0.01854753889423252, 1.125160856305558};
  soft_cloth.cue_mass = 0.2077372739156659;
  bsp::CueStrike plastic_cloth =
      sweptStrike({0.063230379963425537, -0.53517305376236246, 0.84237267380675895},
                  {-0.039959711853070415, 0.89305556648221229, -0.44816846899771334}, 0.24624558453242479,
                  {0.0, 0.32301849272996969, 3.6591689786174353}, 0.036302273784967504);
  plastic_cloth.table_contact = {0.0, 0.062859644805376327, 8.2356032927085092};
  plastic_cloth.cue_mass = 0.36912585136289217;
  bsp::SolverOptions integrated = withTolerance(1e-13);
  integrated.quasi_steady_slip = false;
  for (const bsp::CueStrike& s : {soft_cloth, plastic_cloth})
  {
    const auto by_default = bsp::solve(s);
    const auto reference = bsp::solve(s, integrated);
    ASSERT_TRUE(by_default.ok()) << by_default.error().describe();
    ASSERT_TRUE(reference.ok()) << reference.error().describe();
    same_solution::expectSameSolution(by_default.value().impact, reference.value().impact, 1e-9, "plastic tip");
    EXPECT_LE((by_default.value().velocity - reference.value().velocity).lpNorm<Eigen::Infinity>(), 1e-9);
    EXPECT_LE((by_default.value().angular_velocity - reference.value().angular_velocity).lpNorm<Eigen::Infinity>(),
              1e-9);
  }
}

TEST(CueStrikeInvariants, AJammedTipChattersToItsLimitAtAnyTolerance)
{
  // The tip stays pressed on the ball and chatters, some 30 ends of compression, each with a brief slip, under a
  // force of order one; its deformation F/k shrinks as k grows. Once it falls below the integrator's absolute
  // tolerance its cycles have no correct digit, so the chatter must be cut where the integrator stops resolving it
  // (SolverOptions::chatter_resolution): within 1e-3 of a run at 1e-14, and within 2e-3 at 1e-10.
  const bsp::CueStrike s =
      sweptStrike({0.071073528144835946, -0.32959503703661114, 0.94144339455852588},
                  {0.26118970035386446, 0.66031324152832349, -0.70410678415380734}, 2.2777475086951036,
                  {0.55560555170016734, 0.4320372610856939, 2.7412141132931365}, 0.21546825439538067);
  const auto reference = bsp::solve(s, withTolerance(1e-14));
  ASSERT_TRUE(reference.ok());
  const auto by_default = solved(s);
  EXPECT_TRUE(std::any_of(by_default.impact.events.begin(), by_default.impact.events.end(),
                          [](const bsp::ContactEvent& e) { return e.type == bsp::ContactEventType::RigidLink; }));
  const auto spinError = [&](const bsp::CueStrikeResult& r)
  { return (r.angular_velocity - reference.value().angular_velocity).lpNorm<Eigen::Infinity>(); };
  EXPECT_LE(spinError(by_default), 1e-3);
  EXPECT_LE((by_default.velocity - reference.value().velocity).lpNorm<Eigen::Infinity>(), 1e-4);
  const auto loosely = bsp::solve(s, withTolerance(1e-10));
  ASSERT_TRUE(loosely.ok());
  EXPECT_LE(spinError(loosely.value()), 2e-3);
}

TEST(CueStrikeInvariants, GrazingHitIsAMiscue)
{
  auto s = masse({-0.2761, -0.1388, -0.9511});
  s.cue_contact.friction = 0.05;
  s.cue_contact.eta2 = 2.0;
  EXPECT_TRUE(solved(s).miscue);
}

TEST(CueStrikeBadInput, InvalidShotsAndFields)
{
  const Eigen::Vector3d c(-0.2761, -0.1388, -0.9511);
  auto s = masse(c);
  s.cue_direction = -c;  // pointing away
  EXPECT_EQ(bsp::solve(s).error().code, bsp::ErrorKind::InvalidShot);
  s = masse(c);
  s.hit_normal = {0.6, 0.0, -0.8};  // below the equator, and the cue pointing down into the ball from above
  EXPECT_EQ(bsp::solve(s).error().code, bsp::ErrorKind::InvalidShot);
  s = masse(c);
  s.cue_end_mass = -1.0;
  EXPECT_EQ(bsp::solve(s).error().field, "cue_end_mass");
  s = masse(c);
  s.cue_speed = 0.0;
  EXPECT_EQ(bsp::solve(s).error().field, "cue_speed");
  s = masse(c);
  s.cue_contact.friction = -0.1;
  EXPECT_EQ(bsp::solve(s).error().field, "cue_contact.friction");
  s = masse(c);
  s.table_contact.eta2 = 0.0;
  EXPECT_EQ(bsp::solve(s).error().field, "table_contact.eta2");
  s = masse(c);
  s.hit_normal = {NAN, 0, 1};
  EXPECT_EQ(bsp::solve(s).error().field, "hit_normal");
  s = masse(c);
  s.cue_direction = Eigen::Vector3d::Zero();
  EXPECT_EQ(bsp::solve(s).error().field, "cue_direction");
  s = masse(c);
  s.stiffness_ratio = -1;
  EXPECT_EQ(bsp::solve(s).error().field, "stiffness_ratio");
}

TEST(CueStrikeGeometry, HitNormalFromTheCueAxis)
{
  const Eigen::Vector3d centre(0.1, -0.2, 0.0286);
  const double r = 0.0286;
  const Eigen::Vector3d n(0.480151, -0.102889, 0.871131);
  const Eigen::Vector3d c(-0.2761, -0.1388, -0.9511);
  // A point on the axis 5 cm before the hit point.
  const Eigen::Vector3d tip = centre + r * n.normalized() - 0.05 * c.normalized();
  const auto normal = bsp::hitNormal(tip, c, centre, r);
  ASSERT_TRUE(normal.ok());
  EXPECT_LT((normal.value() - n.normalized()).norm(), 1e-9);
  // An axis that passes 2 radii from the centre misses.
  const Eigen::Vector3d off = centre + Eigen::Vector3d(0, 0, 2 * r) - 0.05 * Eigen::Vector3d::UnitX();
  EXPECT_EQ(bsp::hitNormal(off, Eigen::Vector3d::UnitX(), centre, r).error().code, bsp::ErrorKind::InvalidShot);
  // The ball behind the cue.
  EXPECT_EQ(bsp::hitNormal(centre + Eigen::Vector3d(0.1, 0, 0), Eigen::Vector3d::UnitX(), centre, r).error().code,
            bsp::ErrorKind::InvalidShot);
}

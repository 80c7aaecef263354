// Ball–ball collisions on the cloth as one multiple impact: the classical rigid results they must approach (head-on
// stun shots, throw, spin transfer), the chain they must reproduce, and invariants over random clusters.
//
// The rigid reference (Alciatore, TP A-14, with a coefficient of restitution e): two equal balls of mass m and
// inertia (2/5)mR², the cue ball moving at V without spin, the line of centres at the cut angle φ to V.
// - Normal and tangential responses decouple for spheres: a normal impulse passes through both centres and turns
//   neither ball, and a tangential impulse moves the contact points only tangentially. So the normal impulse is
//   that of a frictionless impact, P_n = (1 + e)/2 · m V cosφ (reduced mass m/2).
// - A tangential impulse P_t moves each ball's contact point by P_t/m + R²P_t/I = (7/2)P_t/m: each ball's tangential
//   effective mass at the contact is (2/7)m, the pair's m/7. The slip u0 = V sinφ stops at P_t = m u0/7, and
//   Coulomb bounds P_t by μP_n; slip never reverses in the rigid limit, so P_t = min(μP_n, m u0/7).
// - The object ball leaves along P_n n̂ + P_t t̂, so the throw is
//       tan θ = P_t/P_n = min(μ, 2 tanφ / (7(1 + e))).
// With spin the slip u0 is the relative surface velocity at the contact (horizontal V sinφ − Rω_z, vertical
// −Rω_y cosφ for the cue ball's follow), P_t = min(μP_n, m|u0|/7) along u0, and the throw is the horizontal part:
//       tan θ = min(μP_n, m|u0|/7) · u0_h/|u0| / P_n.
// The compliant contact (η̄² = k/κ) slips from the first instant when |u0| > μη̄²|v_n|. In the rigid gross-slip
// regime (μP_n < m|u0|/7) it slips to the end, so P_t = μP_n exactly; where the rigid contact would stop slipping,
// the tangential spring stores energy and gives part of it back (the slip can reverse), so P_t lies between 0 and
// min(μP_n, 2m|u0|/7) and differs from the rigid value.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "billiard_shot_planner/scenarios/ball_chain.hpp"
#include "billiard_shot_planner/scenarios/ball_collision.hpp"

namespace bsp = billiard_shot_planner;

namespace
{
constexpr double R = 0.0286;
constexpr double M = 0.17;
constexpr double E = 0.95;  // the default ball–ball restitution
constexpr double DEG = M_PI / 180.0;

bsp::BallCollision twoBalls(double cut, double speed)
{
  // The cue ball at the origin moving along +x, the object ball with the line of centres at `cut` to +x.
  bsp::BallCollision c;
  c.balls.resize(2);
  c.balls[0].velocity = Eigen::Vector3d(speed, 0.0, 0.0);
  c.balls[1].position = 2.0 * R * Eigen::Vector2d(std::cos(cut), std::sin(cut));
  return c;
}

bsp::BallCollision constantFriction(bsp::BallCollision c, double mu)
{
  c.friction_model = bsp::BallBallFriction::Constant;
  c.ball_ball.friction = mu;
  return c;
}

bsp::BallCollisionResult solved(const bsp::BallCollision& c)
{
  auto result = bsp::solve(c);
  EXPECT_TRUE(result.ok()) << result.error().describe();
  return std::move(result).value();
}

/// The angle of the object ball's horizontal velocity from the line of centres, positive towards the slip of the
/// cue ball's surface at a cut to the left (−t̂ with t̂ = ẑ × n̂).
double throwAngle(const bsp::BallCollisionResult& r, double cut)
{
  const Eigen::Vector3d n(std::cos(cut), std::sin(cut), 0.0);
  const Eigen::Vector3d slip_direction(std::sin(cut), -std::cos(cut), 0.0);
  const Eigen::Vector3d& v = r.balls[1].velocity;
  return std::atan2(v.dot(slip_direction), v.dot(n));
}

/// The rigid throw of a stun cut shot (header comment).
double rigidStunThrow(double cut, double mu, double e = E)
{
  return std::atan(std::min(mu, 2.0 * std::tan(cut) / (7.0 * (1.0 + e))));
}

/// The rigid throw with the cue ball's spin: the slip u0 at the contact from both balls' surfaces (header comment).
double rigidThrow(const bsp::BallCollision& c, double mu)
{
  const Eigen::Vector3d n(c.balls[1].position.x(), c.balls[1].position.y(), 0.0);
  const Eigen::Vector3d normal = n.normalized();
  const Eigen::Vector3d cue_surface = c.balls[0].velocity + c.balls[0].angular_velocity.cross(R * normal);
  const Eigen::Vector3d u0 = cue_surface - cue_surface.dot(normal) * normal;
  const double normal_impulse = 0.5 * (1.0 + E) * M * c.balls[0].velocity.dot(normal);
  const double tangential_impulse = std::min(mu * normal_impulse, M * u0.norm() / 7.0);
  const Eigen::Vector3d slip_direction(normal.y(), -normal.x(), 0.0);
  return std::atan(tangential_impulse * u0.dot(slip_direction) / u0.norm() / normal_impulse);
}

Eigen::Vector3d clothImpulse(const bsp::BallCollisionResult& r, std::size_t ball)
{
  const bsp::ContactImpulse& impulse = r.impact.impulses[r.clothContact(ball)];
  return {impulse.tangential.x(), impulse.tangential.y(), impulse.normal};
}
}  // namespace

// --- Head-on ---------------------------------------------------------------------------------------------------

TEST(BallCollision, HeadOnStunShotSplitsTheSpeedByRestitution)
{
  // The impulse acts along the level line of centres: it presses neither ball into the cloth, turns neither, and
  // leaves no slip at the contact, so neither the cloth nor ball–ball friction takes part and the result is the
  // frictionless one, exact to the solver's tolerance. (The model leaves out the weight; the cloth friction that the
  // weight carries during the 0.3 ms contact would change the speeds by μ_s g T ≈ 5e-4 m/s.)
  for (double speed : {0.3, 1.0, 3.0})
    for (double cloth_friction : {0.0, 0.152479})
    {
      bsp::BallCollision c = twoBalls(0.0, speed);
      c.cloth.friction = cloth_friction;
      const auto r = solved(c);
      EXPECT_NEAR(r.balls[1].velocity.x(), 0.5 * (1.0 + E) * speed, 1e-9 * speed);
      EXPECT_NEAR(r.balls[0].velocity.x(), 0.5 * (1.0 - E) * speed, 1e-9 * speed);
      for (const auto& ball : r.balls)
      {
        EXPECT_NEAR(ball.velocity.tail<2>().norm(), 0.0, 1e-12 * speed);
        EXPECT_NEAR(ball.angular_velocity.norm(), 0.0, 1e-12 * speed / R);
      }
      EXPECT_EQ(clothImpulse(r, 0).norm(), 0.0);
      EXPECT_EQ(clothImpulse(r, 1).norm(), 0.0);
    }
}

TEST(BallCollision, HeadOnRollingCueBallKeepsItsSpinAndPressesTheObjectBall)
{
  // A rolling cue ball's surface moves down at the contact (ω_y R = V), so friction pushes the object ball into
  // the cloth and lifts the cue ball. The normal split stays (1 ± e)/2 V up to what the cloth's friction does with
  // that vertical impulse: at most μ_cloth (1 + e_cloth) μ P_n on each ball.
  const double speed = 1.0;
  bsp::BallCollision c = constantFriction(twoBalls(0.0, speed), 0.05);
  c.balls[0].angular_velocity = Eigen::Vector3d(0.0, speed / R, 0.0);
  const auto r = solved(c);
  const double normal_impulse = 0.5 * (1.0 + E) * M * speed;
  const double cloth_bound = c.cloth.friction * (1.0 + c.cloth.restitution) * 0.05 * normal_impulse / M;
  EXPECT_NEAR(r.balls[1].velocity.x(), 0.5 * (1.0 + E) * speed, cloth_bound);
  EXPECT_NEAR(r.balls[0].velocity.x(), 0.5 * (1.0 - E) * speed, cloth_bound);
  EXPECT_GT(clothImpulse(r, 1).z(), 0.0);     // the object ball is pressed into the cloth
  EXPECT_EQ(clothImpulse(r, 0).norm(), 0.0);  // and the cue ball lifted off it
  // The slip (V, downward) outlasts the impact: friction lifts the cue ball by μ times the ball–ball impulse, which
  // the cloth's friction on the object ball makes slightly larger than P_n.
  EXPECT_NEAR(r.balls[0].velocity.z(), 0.05 * r.impact.impulses[0].normal / M, 1e-9);
  // The cloth gives back at most e_cloth of the downward push: the object ball hops by a few hundredths of a
  // metre per second (a few hundredths of a millimetre high), never sinks.
  EXPECT_GE(r.balls[1].velocity.z(), 0.0);
  EXPECT_LE(r.balls[1].velocity.z(), c.cloth.restitution * 0.05 * normal_impulse / M);
}

// --- Throw -----------------------------------------------------------------------------------------------------

TEST(BallCollision, ThrowOfStunCutShotsAgainstTheRigidClosedForm)
{
  const double mu = 0.05;
  std::printf("stun throw, mu = %g, e = %g: cut angle x speed, engine / rigid closed form (deg)\n", mu, E);
  std::printf("  cut  |   0.5 m/s        |   1 m/s          |   2 m/s          |   3 m/s\n");
  for (double cut_deg : {0.0, 5.0, 10.0, 15.0, 20.0, 30.0, 45.0, 60.0})
  {
    std::printf("  %4.0f ", cut_deg);
    const double cut = cut_deg * DEG;
    for (double speed : {0.5, 1.0, 2.0, 3.0})
    {
      const double engine = throwAngle(solved(constantFriction(twoBalls(cut, speed), mu)), cut);
      const double rigid = rigidStunThrow(cut, mu);
      std::printf("| %6.3f / %6.3f  ", engine / DEG, rigid / DEG);
      const bool gross_slip = mu < 2.0 * std::tan(cut) / (7.0 * (1.0 + E));
      if (gross_slip)
      {
        EXPECT_NEAR(engine, rigid, 1e-9) << cut_deg << "° at " << speed << " m/s";
      }
      // Anywhere: within the friction cone, and no more than twice the impulse that stops the slip.
      EXPECT_GE(engine, -1e-12);
      EXPECT_LE(std::tan(engine), std::min(mu, 4.0 * std::tan(cut) / (7.0 * (1.0 + E))) + 1e-9);
    }
    std::printf("\n");
  }
}

TEST(BallCollision, ThrowIsLinearInSpeedWithConstantFriction)
{
  // Every velocity scales with the speed (docs/impact_model.md, Scaling), so the throw angle does not depend on it.
  const double cut = 12.0 * DEG;
  const double slow = throwAngle(solved(constantFriction(twoBalls(cut, 0.5), 0.05)), cut);
  const double fast = throwAngle(solved(constantFriction(twoBalls(cut, 3.0), 0.05)), cut);
  EXPECT_NEAR(slow, fast, 1e-9);
}

TEST(BallCollision, ThrowWithSpeedDependentFriction)
{
  // Alciatore's μ(v) falls with the slip speed V sinφ: the throw is largest near a half-ball hit (φ = 30°) at low
  // speed, and smaller at higher speed.
  std::printf("stun throw, Alciatore's mu(v): cut angle x speed, engine / rigid closed form (deg)\n");
  double largest = 0.0, largest_at = 0.0;
  for (double cut_deg : {5.0, 10.0, 15.0, 20.0, 25.0, 30.0, 35.0, 40.0, 45.0, 60.0})
  {
    const double cut = cut_deg * DEG;
    std::printf("  %4.0f ", cut_deg);
    double previous = INFINITY;
    for (double speed : {0.5, 1.0, 2.0, 3.0})
    {
      const double engine = throwAngle(solved(twoBalls(cut, speed)), cut);
      const double mu = bsp::alciatoreFriction(speed * std::sin(cut));
      const double rigid = rigidStunThrow(cut, mu);
      std::printf("| %6.3f / %6.3f  ", engine / DEG, rigid / DEG);
      if (mu < 2.0 * std::tan(cut) / (7.0 * (1.0 + E)))
      {
        EXPECT_NEAR(engine, rigid, 1e-9) << cut_deg << "° at " << speed << " m/s";
      }
      if (cut_deg >= 20.0)
      {
        EXPECT_LT(engine, previous) << cut_deg << "° at " << speed << " m/s";
      }
      previous = engine;
      if (speed == 0.5 && engine > largest)
        std::tie(largest, largest_at) = std::pair{engine, cut_deg};
    }
    std::printf("\n");
  }
  EXPECT_GE(largest_at, 25.0);
  EXPECT_LE(largest_at, 35.0);
  EXPECT_GT(largest, 4.0 * DEG);  // Alciatore: up to about 5° for slow stun shots
}

TEST(BallCollision, FollowAndDrawReduceTheThrow)
{
  // Topspin or backspin adds a vertical slip at the contact: the slip is faster (smaller μ) and friction turns out
  // of the horizontal plane, so less of it throws the object ball sideways.
  const double cut = 30.0 * DEG, speed = 1.0;
  const double stun = throwAngle(solved(twoBalls(cut, speed)), cut);
  for (double spin : {1.0, -1.0})  // rolling (follow) and as much draw
  {
    bsp::BallCollision c = twoBalls(cut, speed);
    c.balls[0].angular_velocity = Eigen::Vector3d(0.0, spin * speed / R, 0.0);
    const double engine = throwAngle(solved(c), cut);
    const double mu = bsp::alciatoreFriction(speed * std::hypot(std::sin(cut), std::cos(cut)));
    EXPECT_LT(engine, 0.75 * stun) << spin;
    // The rigid value leaves out the cloth under the pressed ball: its friction, μ_cloth (1 + e_cloth) times the
    // vertical impulse at most, changes the object ball's sideways speed by that much.
    const double cloth_bound = c.cloth.friction * (1.0 + c.cloth.restitution) * mu;
    EXPECT_NEAR(engine, rigidThrow(c, mu), cloth_bound) << spin;
    std::printf("cut 30°, 1 m/s, spin %+g V/R: throw %.3f° (stun %.3f°, rigid %.3f°)\n", spin, engine / DEG, stun / DEG,
                rigidThrow(c, mu) / DEG);
  }
}

TEST(BallCollision, OutsideEnglishThatMatchesTheSurfacesGivesNoThrow)
{
  // Side spin ω_z = V sinφ / R makes the cue ball's surface move with the object ball's at the contact: no slip,
  // no friction, no throw and no spin transfer.
  for (double cut_deg : {10.0, 30.0, 50.0})
  {
    const double cut = cut_deg * DEG, speed = 1.5;
    bsp::BallCollision c = twoBalls(cut, speed);
    c.balls[0].angular_velocity = Eigen::Vector3d(0.0, 0.0, speed * std::sin(cut) / R);
    const auto r = solved(c);
    EXPECT_NEAR(throwAngle(r, cut), 0.0, 1e-9) << cut_deg;
    EXPECT_NEAR(r.balls[1].angular_velocity.norm() * R, 0.0, 1e-9) << cut_deg;
  }
}

TEST(BallCollision, SideSpinTransfersASmallOppositeSpin)
{
  // Head-on with side spin ω_z: the cue ball's surface slips by Rω_z ŷ over the object ball's; friction on the
  // object ball at −R x̂ from its centre turns it the other way: Δω_z = −(5/2) P_t/(mR) sign(ω_z) with
  // P_t = min(μP_n, m R|ω_z|/7), at most 5/14 of the cue ball's spin.
  const double speed = 1.0, mu = 0.05;
  for (double surface_speed : {0.2, 0.5, 1.0, 2.0})
  {
    bsp::BallCollision c = constantFriction(twoBalls(0.0, speed), mu);
    c.balls[0].angular_velocity = Eigen::Vector3d(0.0, 0.0, surface_speed / R);
    const auto r = solved(c);
    const double normal_impulse = 0.5 * (1.0 + E) * M * speed;
    const double sticking = M * surface_speed / 7.0;
    const double rigid = -2.5 * std::min(mu * normal_impulse, sticking) / (M * R);
    const double engine = r.balls[1].angular_velocity.z();
    std::printf("side spin R w_z = %.1f m/s: object ball w_z %.3f rad/s (rigid %.3f)\n", surface_speed, engine, rigid);
    EXPECT_LT(engine, 0.0);
    if (mu * normal_impulse < sticking)
    {
      EXPECT_NEAR(engine, rigid, 1e-9 * std::abs(rigid));
    }
    else
    {
      EXPECT_GE(engine, 2.0 * rigid);  // no more than twice the impulse that stops the slip
    }
  }
}

// --- The cloth ---------------------------------------------------------------------------------------------------

TEST(BallCollision, StiffnessRatioMattersOnlyThroughTheCloth)
{
  // A stun cut shot presses no ball into the cloth: the ratio k_cloth/k_ball_ball cannot matter. A follow cut shot
  // presses the object ball with the vertical part of the friction, at most μP_n; the cloth returns at most
  // (1 + e_cloth) of it and its friction μ_cloth times that: the bound on how much the ratio can move the balls.
  const double cut = 30.0 * DEG, speed = 2.0;
  std::vector<Eigen::Vector3d> stun, follow;
  for (double ratio : {0.01, 0.03, 0.1, 0.3, 1.0})
  {
    bsp::BallCollision c = twoBalls(cut, speed);
    c.stiffness_ratio = ratio;
    stun.push_back(solved(c).balls[1].velocity);
    c.balls[0].angular_velocity = Eigen::Vector3d(0.0, speed / R, 0.0);
    follow.push_back(solved(c).balls[1].velocity);
    std::printf("k_cloth/k_bb = %5.2f: follow cut 30°, 2 m/s: object ball v = (%.6f, %.6f, %.6f)\n", ratio,
                follow.back().x(), follow.back().y(), follow.back().z());
  }
  const double mu = bsp::alciatoreFriction(speed);  // the rolling cue ball slips at V over the object ball
  const double bound = 0.152479 * (1.0 + 0.51625) * mu * 0.5 * (1.0 + E) * speed;
  for (std::size_t k = 1; k < stun.size(); ++k)
  {
    EXPECT_NEAR((stun[k] - stun[0]).norm(), 0.0, 1e-9 * speed);
    EXPECT_LE((follow[k] - follow[0]).norm(), bound);
  }
}

// --- Rows of balls -----------------------------------------------------------------------------------------------

TEST(BallCollision, NewtonsCradleOnTheClothIsTheBallChain)
{
  // A row of touching balls hit head-on along the row: the same physics as BallChain with the ball–ball stiffness
  // and restitution, configured independently (one coordinate per ball there, six here, with the cloth).
  for (std::size_t n = 2; n <= 7; ++n)
    for (double cloth_friction : {0.0, 0.152479})
    {
      bsp::BallCollision c;
      c.cloth.friction = cloth_friction;
      c.balls.resize(n);
      for (std::size_t i = 0; i < n; ++i)
        c.balls[i].position = Eigen::Vector2d(2.0 * R * static_cast<double>(i), 0.0);
      c.balls[0].velocity = Eigen::Vector3d(2.0, 0.0, 0.0);
      bsp::BallChain chain{std::vector<double>(n, M), std::vector<double>(n, 0.0), std::vector<double>(n - 1, 1.0),
                           std::vector<double>(n - 1, E), false};
      chain.velocities[0] = 2.0;
      const auto row = solved(c);
      const auto reference = bsp::solve(chain).value();
      for (std::size_t i = 0; i < n; ++i)
        EXPECT_NEAR(row.balls[i].velocity.x(), reference.velocity(static_cast<Eigen::Index>(i)), 1e-9)
            << n << " balls, ball " << i;
      for (std::size_t k = 0; k + 1 < n; ++k)
        EXPECT_EQ(row.impact.ends_of_compression[k], reference.ends_of_compression[k]) << n << " balls, pair " << k;
    }
}

// --- Invariants over random clusters ------------------------------------------------------------------------------

// A row of touching balls against a cushion whose nose is at the height of their centres, hit head-on along the
// row: the cushion is one more contact of the same impact, and the physics that of BallChain with a wall (the
// cushion's stiffness k_cloth/k_bb · k_cushion/k_cloth and restitution), configured independently.
TEST(BallCollision, ARowFrozenToACushionIsTheChainAgainstAWall)
{
  for (std::size_t n = 2; n <= 5; ++n)
  {
    bsp::BallCollision c;
    c.balls.resize(n);
    for (std::size_t i = 0; i < n; ++i)
      c.balls[i].position = Eigen::Vector2d(2.0 * R * static_cast<double>(i), 0.0);
    c.balls[0].velocity = Eigen::Vector3d(2.0, 0.0, 0.0);
    c.cushions.push_back({n - 1, -Eigen::Vector3d::UnitX()});
    bsp::BallChain chain{std::vector<double>(n, M), std::vector<double>(n, 0.0), std::vector<double>(n, 1.0),
                         std::vector<double>(n, E), true};
    chain.velocities[0] = 2.0;
    chain.stiffness.back() = c.stiffness_ratio * c.cushion_stiffness_ratio;
    chain.restitution.back() = c.cushion.restitution;
    const auto row = solved(c);
    const auto reference = bsp::solve(chain).value();
    EXPECT_EQ(row.contact_names[row.cushionContact(0)], "ball" + std::to_string(n - 1) + "-cushion");
    for (std::size_t i = 0; i < n; ++i)
      EXPECT_NEAR(row.balls[i].velocity.x(), reference.velocity(static_cast<Eigen::Index>(i)), 1e-9)
          << n << " balls, ball " << i;
    EXPECT_NEAR(row.impact.impulses[row.cushionContact(0)].normal, reference.impulses[n - 1].normal, 1e-9 * M * 2.0);
  }
}

// A ball frozen to a real cushion (nose above its centre) hit by a stun ball at an angle: one impact of the pair,
// both cloth contacts and the cushion. The cushion only pushes (along its normal, within its friction cone), the
// frozen ball does not end moving into it, energy does not rise, and the balls' momentum changes by the cloth's
// and the cushion's impulses alone.
TEST(BallCollision, ABallFrozenToACushionTakesTheCushionIntoTheImpact)
{
  const double h = 0.0363;  // the default table's nose height
  const double sin_nose = (h - R) / R, cos_nose = std::sqrt(1.0 - sin_nose * sin_nose);
  const Eigen::Vector3d normal(-cos_nose, 0.0, -sin_nose);  // from the nose (at +x) to the frozen ball's centre
  for (double cut_deg : {0.0, 20.0, 45.0})
    for (double speed : {0.5, 2.0})
    {
      const double cut = cut_deg * DEG;
      bsp::BallCollision c = twoBalls(cut, speed);
      c.cushions.push_back({1, normal});
      const bsp::BallCollisionResult r = solved(c);
      const bsp::ContactImpulse& at_cushion = r.impact.impulses[r.cushionContact(0)];
      EXPECT_GT(at_cushion.normal, 0.0) << cut_deg << "°, " << speed << " m/s";
      EXPECT_LE(at_cushion.tangential.norm(), c.cushion.friction * at_cushion.normal * (1.0 + 1e-9));
      EXPECT_GE(r.balls[1].velocity.dot(normal), -1e-9 * speed) << cut_deg << "°, " << speed << " m/s";
      const Eigen::Matrix3d frame = bsp::contactFrame(normal);
      const Eigen::Vector3d cushion = frame.row(0).transpose() * at_cushion.tangential.x() +
                                      frame.row(1).transpose() * at_cushion.tangential.y() +
                                      frame.row(2).transpose() * at_cushion.normal;
      Eigen::Vector3d momentum = Eigen::Vector3d::Zero();
      double before = 0.0, after = 0.0;
      for (std::size_t i = 0; i < 2; ++i)
      {
        momentum += M * (r.balls[i].velocity - c.balls[i].velocity);
        before +=
            0.5 * M * c.balls[i].velocity.squaredNorm() + 0.2 * M * R * R * c.balls[i].angular_velocity.squaredNorm();
        after +=
            0.5 * M * r.balls[i].velocity.squaredNorm() + 0.2 * M * R * R * r.balls[i].angular_velocity.squaredNorm();
      }
      EXPECT_NEAR((momentum - clothImpulse(r, 0) - clothImpulse(r, 1) - cushion).norm(), 0.0, 1e-9 * M * speed);
      EXPECT_LE(after, before * (1.0 + 1e-10));
    }
}

TEST(BallCollision, RefusesACushionOfNoBall)
{
  bsp::BallCollision c = twoBalls(0.0, 1.0);
  c.cushions.push_back({2, Eigen::Vector3d::UnitX()});
  auto result = bsp::solve(c);
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error().field, "cushions[0].ball");
  c.cushions[0] = {1, Eigen::Vector3d::Zero()};
  result = bsp::solve(c);
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error().field, "cushions[0].normal");
}

namespace
{
/// A cluster of n touching balls grown from the origin, each new ball touching a random earlier one (in line with
/// its own last neighbour a third of the time, which makes rows), with random velocities and spins on some of them.
bsp::BallCollision randomCluster(std::mt19937& rng, std::size_t n)
{
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  bsp::BallCollision c;
  c.balls.resize(1);
  std::vector<double> heading(1, 2.0 * M_PI * unit(rng));
  while (c.balls.size() < n)
  {
    const std::size_t from = std::uniform_int_distribution<std::size_t>(0, c.balls.size() - 1)(rng);
    const double angle = unit(rng) < 1.0 / 3.0 ? heading[from] : 2.0 * M_PI * unit(rng);
    bsp::CollidingBall ball;
    ball.position = c.balls[from].position + 2.0 * R * Eigen::Vector2d(std::cos(angle), std::sin(angle));
    const bool clear = std::all_of(c.balls.begin(), c.balls.end(),
                                   [&](const bsp::CollidingBall& other)
                                   { return (other.position - ball.position).norm() > 2.0 * R - 1e-9; });
    if (!clear)
      continue;
    c.balls.push_back(ball);
    heading.push_back(angle);
  }
  do  // until some touching pair approaches
  {
    for (bsp::CollidingBall& ball : c.balls)
    {
      const double direction = 2.0 * M_PI * unit(rng);
      const bool moving = unit(rng) < 0.5;
      ball.velocity = Eigen::Vector3d(std::cos(direction), std::sin(direction), 0.0) * (moving ? 3.0 * unit(rng) : 0.0);
      const Eigen::Vector3d spin(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5);
      ball.angular_velocity = spin * (moving ? 4.0 / R * unit(rng) : 0.0);
    }
  } while (!bsp::makeImpactProblem(c).ok());
  c.ball_ball.friction = 0.2 * unit(rng);
  c.friction_model = unit(rng) < 0.5 ? bsp::BallBallFriction::Constant : bsp::BallBallFriction::Alciatore;
  return c;
}

/// Coulomb bounds every instant's force, so each contact's total impulse too: |I_t| ≤ μ I_n.
bool withinFrictionCones(const bsp::BallCollision& c, const bsp::BallCollisionResult& r)
{
  for (std::size_t j = 0; j < r.impact.impulses.size(); ++j)
  {
    const double mu = j < r.pairs.size() ? r.pairs[j].friction : c.cloth.friction;
    const bsp::ContactImpulse& impulse = r.impact.impulses[j];
    if (impulse.tangential.norm() > mu * impulse.normal + 1e-9 * M)
      return false;
  }
  return true;
}

double kineticEnergy(const std::vector<Eigen::Vector3d>& v, const std::vector<Eigen::Vector3d>& w)
{
  double energy = 0.0;
  for (std::size_t i = 0; i < v.size(); ++i)
    energy += 0.5 * M * v[i].squaredNorm() + 0.2 * M * R * R * w[i].squaredNorm();
  return energy;
}
}  // namespace

TEST(BallCollision, RandomClustersKeepTheInvariants)
{
  // Energy never rises; the balls' linear and angular momentum change only by the cloth's impulses (ball–ball
  // impulses are internal); the cloth only pushes up and no ball ends moving into it; each contact's impulse lies in
  // its friction cone. Every solve finishes.
  std::mt19937 rng(20240611);
  std::size_t solves = 0, events = 0, refined = 0;
  double slowest = 0.0;
  const auto start = std::chrono::steady_clock::now();
  for (int k = 0; k < 1016; ++k)
  {
    // Mostly 2–5 balls (a tenth of a second at most each), and two clusters of each size from 8 to 15.
    const std::size_t n = k < 1000 ? 2 + static_cast<std::size_t>(k % 4) : 8 + static_cast<std::size_t>(k % 8);
    const bsp::BallCollision c = randomCluster(rng, n);
    const auto t0 = std::chrono::steady_clock::now();
    auto result = bsp::solve(c);
    slowest = std::max(slowest, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    ASSERT_TRUE(result.ok()) << k << ": " << result.error().describe();
    if (!withinFrictionCones(c, result.value()))
    {
      // At the default tolerance the engine can miss a stick-to-slip crossing in a large cluster and leave a pair's
      // impulse outside its cone (a 13-ball cluster of another seed: 4.3 μI_n; at 1e-13 on the cone): solve again.
      ++refined;
      bsp::SolverOptions finer;
      finer.relative_tolerance = 1e-13;
      finer.absolute_tolerance = 1e-15;
      result = bsp::solve(c, finer);
      ASSERT_TRUE(result.ok()) << k << ": " << result.error().describe();
      EXPECT_TRUE(withinFrictionCones(c, result.value())) << k;
    }
    const bsp::BallCollisionResult& r = result.value();
    ++solves;
    events += r.impact.events.size();
    double speed = 0.0;
    Eigen::Vector3d momentum = Eigen::Vector3d::Zero(), angular = Eigen::Vector3d::Zero(),
                    cloth = Eigen::Vector3d::Zero(), cloth_moment = Eigen::Vector3d::Zero();
    std::vector<Eigen::Vector3d> v0, w0, v1, w1;
    for (std::size_t i = 0; i < n; ++i)
    {
      const Eigen::Vector3d centre(c.balls[i].position.x(), c.balls[i].position.y(), R);
      const Eigen::Vector3d dv = r.balls[i].velocity - c.balls[i].velocity;
      const Eigen::Vector3d dw = r.balls[i].angular_velocity - c.balls[i].angular_velocity;
      momentum += M * dv;
      angular += M * centre.cross(dv) + 0.4 * M * R * R * dw;
      cloth += clothImpulse(r, i);
      cloth_moment += (centre - R * Eigen::Vector3d::UnitZ()).cross(clothImpulse(r, i));
      speed = std::max({speed, c.balls[i].velocity.norm(), R * c.balls[i].angular_velocity.norm()});
      v0.push_back(c.balls[i].velocity), w0.push_back(c.balls[i].angular_velocity);
      v1.push_back(r.balls[i].velocity), w1.push_back(r.balls[i].angular_velocity);
      EXPECT_GE(clothImpulse(r, i).z(), -1e-12 * M * speed) << k;
      EXPECT_GE(r.balls[i].velocity.z(), -1e-9 * speed) << k << " ball " << i;
    }
    const double scale = M * speed * static_cast<double>(n);
    EXPECT_LE(kineticEnergy(v1, w1), kineticEnergy(v0, w0) * (1.0 + 1e-10)) << k;
    EXPECT_NEAR((momentum - cloth).norm(), 0.0, 1e-9 * scale) << k;
    EXPECT_NEAR((angular - cloth_moment).norm(), 0.0, 1e-9 * scale * R * static_cast<double>(n)) << k;
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("%zu random clusters solved (%zu again at a finer tolerance), %zu events, %.2f s, slowest %.3f s\n",
              solves, refined, events, seconds, slowest);
  EXPECT_GE(solves, 1000u);
}

TEST(BallCollision, BreakOfARackedPackIsOneImpact)
{
  // Fifteen balls racked in a triangle, all touching, and the cue ball hitting the apex at 8 m/s: one impact of 30
  // ball–ball and 16 cloth contacts.
  bsp::BallCollision c;
  c.balls.resize(1);
  c.balls[0].velocity = Eigen::Vector3d(8.0, 0.0, 0.0);
  c.balls[0].position = Eigen::Vector2d(-2.0 * R, 0.0);
  for (int row = 0; row < 5; ++row)
    for (int k = 0; k <= row; ++k)
    {
      bsp::CollidingBall ball;
      ball.position = 2.0 * R * Eigen::Vector2d(row * std::sqrt(3.0) / 2.0, k - 0.5 * row);
      c.balls.push_back(ball);
    }
  const auto t0 = std::chrono::steady_clock::now();
  const auto r = solved(c);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_EQ(r.pairs.size(), 31u);  // 30 in the rack and the cue ball on the apex
  Eigen::Vector3d momentum = Eigen::Vector3d::Zero();
  for (const auto& ball : r.balls)
    momentum += M * ball.velocity;
  EXPECT_NEAR(momentum.x(), M * 8.0, 1e-9);
  EXPECT_LE(r.impact.final_kinetic_energy, r.impact.initial_kinetic_energy);
  std::printf("break: %zu events, %zu states, %.3f s; energy %.4f -> %.4f J\n", r.impact.events.size(),
              r.impact.states.size(), seconds, r.impact.initial_kinetic_energy, r.impact.final_kinetic_energy);
}

// --- Refused input -----------------------------------------------------------------------------------------------

TEST(BallCollision, RefusesBadInputNamingTheField)
{
  const auto refused = [](const bsp::BallCollision& c, const char* field, bsp::ErrorKind code)
  {
    const auto result = bsp::solve(c);
    ASSERT_FALSE(result.ok()) << field;
    EXPECT_EQ(result.error().field, field) << result.error().describe();
    EXPECT_EQ(result.error().code, code) << result.error().describe();
  };
  const auto invalid = bsp::ErrorKind::InvalidArgument;
  bsp::BallCollision c = twoBalls(0.3, 1.0);
  {
    bsp::BallCollision one = c;
    one.balls.resize(1);
    refused(one, "balls", invalid);
  }
  {
    bsp::BallCollision overlap = c;
    overlap.balls.push_back(c.balls[1]);
    overlap.balls[2].position.x() += 1.9 * R;
    overlap.balls[2].position.y() += 0.1 * R;
    refused(overlap, "balls[2].position", invalid);
  }
  bsp::BallCollision bad = c;
  bad.balls[1].velocity.y() = NAN;
  refused(bad, "balls[1].velocity", invalid);
  bad = c;
  bad.balls[0].angular_velocity.z() = 1e6;
  refused(bad, "balls[0].angular_velocity", invalid);
  bad = c;
  bad.balls[1].position.x() = INFINITY;
  refused(bad, "balls[1].position", invalid);
  bad = c;
  bad.ball_ball.eta2 = 0.0;
  refused(bad, "ball_ball.eta2", invalid);
  bad = c;
  bad.cloth.restitution = 1.2;
  refused(bad, "cloth.restitution", invalid);
  bad = c;
  bad.stiffness_ratio = 1e-4;
  refused(bad, "stiffness_ratio", invalid);
  bad = c;
  bad.ball_radius = -1.0;
  refused(bad, "ball_radius", invalid);
  bad = c;
  bad.touching_tolerance = 0.1 * R;
  refused(bad, "touching_tolerance", invalid);
  // Nothing to collide: no pair touches (a gap of twice the tolerance), or pairs touch and none approaches.
  bad = c;
  bad.balls[1].position *= (2.0 * R + 2.0 * c.touching_tolerance) / (2.0 * R);
  refused(bad, "balls", bsp::ErrorKind::NoApproachingContact);
  bad = c;
  bad.balls[0].velocity = Eigen::Vector3d(-1.0, 0.0, 0.0);
  refused(bad, "balls", bsp::ErrorKind::NoApproachingContact);
  // Within the tolerance a gap or an overlap is a contact.
  bsp::BallCollision near = c;
  near.balls[1].position *= (2.0 * R + 0.5 * c.touching_tolerance) / (2.0 * R);
  EXPECT_TRUE(bsp::solve(near).ok());
  near.balls[1].position *= (2.0 * R - 0.5 * c.touching_tolerance) / (2.0 * R + 0.5 * c.touching_tolerance);
  EXPECT_TRUE(bsp::solve(near).ok());
}

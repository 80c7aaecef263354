// The contact laws behind NormalLaw: what every registered law must keep (a conformance test parametrised over
// lawTypes(): its spring's energy, rate and tangent stiffness agree with its force, an end of compression keeps e²
// of the energy at a continuous force, energy never rises, random strikes and ball–ball–cloth collisions end apart),
// and each law's own values against an independent computation.
//
// The elastic–plastic law's reference is Thornton 1997 (J. Appl. Mech. 64:383, eq. 39): for x = v_y/v < 1,
// e_T = √(6√3/5) · √(1 − x²/6) · [x / (x + 2√(6/5 − x²/5))]^¼. A lone contact (a ball dropped on a frictionless
// cloth) stores exactly the energy of its approach, so its restitution is e0 · e_T(v) at its approach speed v.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <variant>

#include "../../src/impact/normal_spring.hpp"
#include "billiard_shot_planner/impact/laws/normal_law.hpp"
#include "billiard_shot_planner/scenarios/ball_collision.hpp"
#include "billiard_shot_planner/scenarios/ball_table_impact.hpp"
#include "billiard_shot_planner/scenarios/cue_strike.hpp"
#include "billiard_shot_planner/shot/shot_prediction.hpp"

namespace bsp = billiard_shot_planner;

namespace
{
constexpr double ENERGY_SLACK = 1e-9;  // energy may rise by round-off only

double thornton(double yield_speed, double speed)
{
  if (speed <= yield_speed)
    return 1.0;
  const double x = yield_speed / speed;
  return std::sqrt(6.0 * std::sqrt(3.0) / 5.0) * std::sqrt(1.0 - x * x / 6.0) *
         std::pow(x / (x + 2.0 * std::sqrt(6.0 / 5.0 - x * x / 5.0)), 0.25);
}

double uniform(std::mt19937& rng, double low, double high)
{
  return std::uniform_real_distribution<double>(low, high)(rng);
}

double logUniform(std::mt19937& rng, double low, double high)
{
  return std::exp(uniform(rng, std::log(low), std::log(high)));
}

/// The law of `type` with random parameters in their physical range (every parameter a speed or a ratio of order 1).
bsp::NormalLaw randomLaw(const std::string& type, std::mt19937& rng)
{
  bsp::NormalLaw law = bsp::lawOfType(type, "law").value();
  bsp::visitLawParameters(law, [&](const char* /*name*/, double& value) { value = logUniform(rng, 0.05, 5.0); });
  return law;
}

bsp::SurfaceContact randomSurface(const std::string& type, std::mt19937& rng)
{
  bsp::SurfaceContact surface{uniform(rng, 0.0, 1.0), uniform(rng, 0.0, 1.0), logUniform(rng, 0.5, 20.0)};
  surface.normal_law = randomLaw(type, rng);
  return surface;
}

bool endedOnABound(const bsp::Error& error)
{
  return error.code == bsp::ErrorKind::EventLimitExceeded || error.code == bsp::ErrorKind::StepLimitExceeded ||
         error.code == bsp::ErrorKind::TimeLimitExceeded;
}

class EveryLaw : public testing::TestWithParam<std::string>
{
};

TEST_P(EveryLaw, RandomStrikesNeverGainEnergyAndEndApart)
{
  std::mt19937 rng(11);
  for (int k = 0; k < 120; ++k)
  {
    SCOPED_TRACE(testing::Message() << "strike " << k);
    bsp::CueStrike strike;
    // The cue from above at `elevation`, the hit point up to 0.55 rad off the axis in any direction.
    const double elevation = uniform(rng, 0.0, 1.3);
    strike.cue_direction = Eigen::Vector3d(std::cos(elevation), 0.0, -std::sin(elevation));
    const Eigen::Vector3d offset(uniform(rng, -0.6, 0.6), uniform(rng, -0.6, 0.6), uniform(rng, -0.6, 0.6));
    strike.hit_normal =
        -(strike.cue_direction + offset - offset.dot(strike.cue_direction) * strike.cue_direction).normalized();
    strike.cue_speed = logUniform(rng, 0.2, 8.0);
    strike.cue_contact = randomSurface(GetParam(), rng);
    strike.table_contact = randomSurface(GetParam(), rng);
    strike.stiffness_ratio = logUniform(rng, 0.1, 10.0);
    const auto result = bsp::solve(strike);
    if (!result.ok())
    {
      EXPECT_TRUE(result.error().code == bsp::ErrorKind::InvalidShot || endedOnABound(result.error()))
          << result.error().describe();
      continue;
    }
    const bsp::ImpactResult& impact = result.value().impact;
    EXPECT_TRUE(impact.velocity.allFinite());
    EXPECT_LE(impact.final_kinetic_energy, impact.initial_kinetic_energy * (1 + ENERGY_SLACK));
    EXPECT_GE(result.value().velocity.z(), -1e-9 * strike.cue_speed);  // not into the cloth
  }
}

TEST_P(EveryLaw, RandomBallBallClothCollisionsNeverGainEnergyAndEndApart)
{
  std::mt19937 rng(12);
  constexpr double R = 0.0286;
  for (int k = 0; k < 300; ++k)
  {
    SCOPED_TRACE(testing::Message() << "collision " << k);
    bsp::BallCollision c;
    c.balls.resize(2);
    const double speed = logUniform(rng, 0.05, 6.0), cut = uniform(rng, -1.4, 1.4);
    c.balls[0].velocity = Eigen::Vector3d(speed, 0.0, 0.0);
    c.balls[0].angular_velocity =
        Eigen::Vector3d(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)) * (speed / R);
    c.balls[1].position = 2.0 * R * Eigen::Vector2d(std::cos(cut), std::sin(cut));
    c.friction_model = bsp::BallBallFriction::Constant;
    c.ball_ball = randomSurface(GetParam(), rng);
    c.cloth = randomSurface(GetParam(), rng);
    c.stiffness_ratio = logUniform(rng, 0.01, 1.0);
    const auto result = bsp::solve(c);
    if (!result.ok())
    {
      EXPECT_TRUE(endedOnABound(result.error())) << result.error().describe();
      continue;
    }
    const bsp::BallCollisionResult& r = result.value();
    EXPECT_LE(r.impact.final_kinetic_energy, r.impact.initial_kinetic_energy * (1 + ENERGY_SLACK));
    const Eigen::Vector2d normal = c.balls[1].position.normalized();
    const Eigen::Vector3d n(normal.x(), normal.y(), 0.0);
    EXPECT_GE((r.balls[1].velocity - r.balls[0].velocity).dot(n), -1e-9 * speed);  // apart
    for (const bsp::CollidedBall& ball : r.balls)
      EXPECT_GE(ball.velocity.z(), -1e-9 * speed);  // not into the cloth
  }
}

TEST_P(EveryLaw, ItsSpringsEnergyRateAndStiffnessFollowFromItsForce)
{
  // Against central differences of the force (step h = 1e-6 of the deformation: truncation O(h²) ≈ 1e-12 and
  // round-off ε|s|/h ≈ 1e-10 relative, far inside the 1e-7 allowed), and at an end of compression against the
  // energy and force it must keep.
  std::mt19937 rng(41);
  for (int trial = 0; trial < 200; ++trial)
  {
    const bsp::NormalLaw law = randomLaw(GetParam(), rng);
    const double k = logUniform(rng, 0.1, 10.0);
    const double s = -logUniform(rng, 1e-3, 2.0);  // pressed
    const double rate = uniform(rng, -3.0, 3.0);
    const double e = uniform(rng, 0.05, 1.0);
    std::visit(
        [&](const auto& alternative)
        {
          const auto spring = alternative.spring();
          EXPECT_EQ(bsp::isLinear(law), decltype(spring)::LINEAR);
          const double h = 1e-6 * std::abs(s);
          const double force = spring.force(k, s);
          EXPECT_GT(force, 0.0);  // a pressed spring pushes apart
          EXPECT_EQ(spring.energy(k, 0.0), 0.0);
          EXPECT_GT(spring.energy(k, s), 0.0);
          const double energy_slope = -(spring.energy(k, s + h) - spring.energy(k, s - h)) / (2.0 * h);
          EXPECT_NEAR(energy_slope, force, 1e-7 * std::abs(force));  // F = −dE/ds
          const double stiffness = -(spring.force(k, s + h) - spring.force(k, s - h)) / (2.0 * h);
          EXPECT_NEAR(spring.stiffnessAt(k, s), stiffness, 1e-7 * std::abs(stiffness));
          EXPECT_NEAR(spring.forceRate(k, s, rate), -spring.stiffnessAt(k, s) * rate,
                      1e-12 * std::abs(stiffness * rate));
          if (decltype(spring)::LINEAR)
          {
            EXPECT_NEAR(spring.force(k, 2.0 * s), 2.0 * force, 1e-12 * std::abs(force));
          }
          const double k_restitution = spring.restitutionStiffness(k, e * e);
          const double s_restitution = spring.restitutionDeformation(s, e * e);
          EXPECT_NEAR(spring.force(k_restitution, s_restitution), force, 1e-12 * force);
          EXPECT_NEAR(spring.energy(k_restitution, s_restitution), e * e * spring.energy(k, s),
                      1e-12 * spring.energy(k, s));
        },
        law);
  }
}

TEST_P(EveryLaw, AContactsEndOfCompressionKeepsItsLawsShareOfTheEnergy)
{
  // The engine's normal spring (NormalSpring): the restitution of a compression is the law's at its speed, in
  // [0, e0], and ending it keeps e² of the stored energy at a continuous force, at the stiffness the chatter bound
  // reads beforehand.
  std::mt19937 rng(43);
  for (int trial = 0; trial < 200; ++trial)
  {
    bsp::detail::NormalSpring spring;
    spring.law = randomLaw(GetParam(), rng);
    spring.linear = bsp::isLinear(spring.law);
    spring.stiffness = logUniform(rng, 0.1, 10.0);
    spring.original_stiffness = spring.stiffness;
    spring.low_speed_restitution = uniform(rng, 0.05, 1.0);
    const double speed = logUniform(rng, 0.01, 10.0);
    const double e = spring.restituteAt(speed);
    EXPECT_EQ(e, bsp::restitutionOf(spring.law, spring.low_speed_restitution, speed));
    EXPECT_GE(e, 0.0);
    EXPECT_LE(e, spring.low_speed_restitution);
    const double s = -logUniform(rng, 1e-3, 2.0);
    const double force = spring.force(s);
    const double energy = spring.energy(s);
    const double restitution_stiffness = spring.restitutionStiffness();
    const double s_restitution = spring.endCompression(s);
    EXPECT_EQ(spring.stiffness, restitution_stiffness);
    EXPECT_NEAR(spring.force(s_restitution), force, 1e-12 * force);
    EXPECT_NEAR(spring.energy(s_restitution), e * e * energy, 1e-12 * energy);
  }
}

TEST_P(EveryLaw, ParametersRoundTripThroughTheirDeclaration)
{
  bsp::NormalLaw law = bsp::lawOfType(GetParam(), "law").value();
  EXPECT_EQ(bsp::lawType(law), GetParam());
  double next = 0.5;
  bsp::visitLawParameters(law, [&](const char* /*name*/, double& value) { value = next++; });
  double expected = 0.5;
  bsp::visitLawParameters(law, [&](const char* name, double& value) { EXPECT_EQ(value, expected++) << name; });
  EXPECT_TRUE(bsp::validate(law, "law").ok());
}

INSTANTIATE_TEST_SUITE_P(ContactLaws, EveryLaw, testing::ValuesIn(bsp::lawTypes()),
                         [](const testing::TestParamInfo<std::string>& info) { return info.param; });

bsp::BallTableImpactResult dropped(double speed, const bsp::NormalLaw& law, double e0)
{
  bsp::BallTableImpact drop;
  drop.mass = 0.17;
  drop.radius = 0.0286;
  drop.velocity = Eigen::Vector3d(0.0, 0.0, -speed);
  drop.table = {e0, 0.0, 1.0};
  drop.table.normal_law = law;
  return bsp::solve(drop).value();
}

}  // namespace

TEST(ElasticPlasticRestitution, FollowsThorntonsClosedFormAboveTheYieldSpeed)
{
  const bsp::ElasticPlasticRestitution law{1.0};
  EXPECT_NEAR(law.restitution(1.0, 1.0), 1.0, 1e-12);
  EXPECT_NEAR(law.restitution(1.0, 1.0 + 1e-9), 1.0, 1e-6);  // continuous at v_y
  EXPECT_EQ(law.restitution(0.9, 0.5), 0.9);                 // elastic below the yield speed
  double previous = 1.0;
  for (double v = 1.1; v < 1000.0; v *= 1.3)
  {
    const double e = law.restitution(1.0, v);
    EXPECT_LT(e, previous) << v;  // falls with speed
    EXPECT_GT(e, 0.0);
    previous = e;
  }
  // Far above v_y: e_T → √(6√3/5) · (x/(2√(6/5)))^¼, Thornton's asymptote ∝ v^(−¼).
  const double far = 1e6;
  const double asymptote = std::sqrt(6.0 * std::sqrt(3.0) / 5.0) * std::pow(1.0 / (far * 2.0 * std::sqrt(1.2)), 0.25);
  EXPECT_NEAR(law.restitution(1.0, far) / asymptote, 1.0, 1e-5);
}

TEST(ElasticPlasticRestitution, ALoneContactRestitutesAtItsApproachSpeed)
{
  // A ball dropped on a frictionless cloth: one contact, whose compression's energy is the approach's.
  const bsp::NormalLaw law = bsp::ElasticPlasticRestitution{0.8};
  for (double speed : {0.3, 0.8, 1.0, 1.5, 3.0, 7.0})
  {
    const auto r = dropped(speed, law, 0.95);
    EXPECT_NEAR(r.velocity.z() / speed, 0.95 * thornton(0.8, speed), 1e-6) << speed;
  }
}

TEST(ElasticPlasticRestitution, AboveEverySpeedIsTheConstantLawBitForBit)
{
  const auto constant = dropped(2.0, bsp::ConstantRestitution{}, 0.9);
  const auto never_yields = dropped(2.0, bsp::ElasticPlasticRestitution{1e9}, 0.9);
  EXPECT_EQ(never_yields.velocity, constant.velocity);
  EXPECT_EQ(never_yields.impact.events.size(), constant.impact.events.size());
}

TEST(NormalLaw, UnknownTypesAndParametersOutOfRangeNameTheirField)
{
  const auto unknown = bsp::lawOfType("hertz_typo", "cushion.law");
  ASSERT_FALSE(unknown.ok());
  EXPECT_EQ(unknown.error().field, "cushion.law.type");
  EXPECT_NE(unknown.error().message.find("elastic_plastic"), std::string::npos);  // lists the laws there are
  for (double bad : {0.0, -1.0, std::nan(""), HUGE_VAL})
  {
    const auto status = bsp::validate(bsp::NormalLaw{bsp::ElasticPlasticRestitution{bad}}, "cushion.law");
    ASSERT_FALSE(status.ok()) << bad;
    EXPECT_EQ(status.error().field, "cushion.law.yield_speed");
  }
  bsp::CueStrike strike;
  strike.cue_contact.normal_law = bsp::ElasticPlasticRestitution{-2.0};
  const auto refused = bsp::solve(strike);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error().code, bsp::ErrorKind::InvalidArgument);
  EXPECT_NE(refused.error().field.find("yield_speed"), std::string::npos) << refused.error().field;
}

TEST(NormalLaw, ALawsParametersAreConfigurationParameters)
{
  // The names every front end reads (node parameters, calibration, overrides) follow the law each contact has.
  bsp::ShotConfiguration c;
  c.table.cushion.normal_law = bsp::ElasticPlasticRestitution{1.2};
  ASSERT_TRUE(bsp::applyOverride(c, "table.cushion.law.yield_speed", 2.0).ok());
  EXPECT_EQ(std::get<bsp::ElasticPlasticRestitution>(c.table.cushion.normal_law).yield_speed, 2.0);
  const auto refused = bsp::applyOverride(c, "table.cushion.law.yield_speed", -1.0);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(std::get<bsp::ElasticPlasticRestitution>(c.table.cushion.normal_law).yield_speed, 2.0);  // unchanged
  EXPECT_FALSE(bsp::applyOverride(c, "table.cloth.law.yield_speed", 2.0).ok());  // the cloth's law is constant
}

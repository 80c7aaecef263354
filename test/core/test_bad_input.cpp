// Every class of bad input gives a typed error that names the field; nothing throws.
#include <gtest/gtest.h>

#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "billiard_shot_planner/impact/multiple_impact_solver.hpp"
#include "billiard_shot_planner/scenarios/ball_ball_table.hpp"
#include "billiard_shot_planner/scenarios/ball_chain.hpp"

namespace bsp = billiard_shot_planner;

namespace
{
const double NaN = std::numeric_limits<double>::quiet_NaN();
const double INF = std::numeric_limits<double>::infinity();

bsp::ImpactProblem validProblem()
{
  bsp::BallBallTable c;
  return bsp::makeImpactProblem(c).value();
}

/// One way to spoil a valid problem, and the error it must give.
struct SpoiledProblem
{
  const char* field;
  bsp::ErrorKind code;
  std::function<void(bsp::ImpactProblem&)> spoil;
};

void expectError(const bsp::ImpactProblem& problem, bsp::ErrorKind code, const std::string& field)
{
  const auto result = bsp::solveMultipleImpact(problem);
  ASSERT_FALSE(result.ok()) << "expected an error on " << field;
  EXPECT_EQ(result.error().code, code);
  EXPECT_EQ(result.error().field, field);
  EXPECT_FALSE(result.error().message.empty());
}
}  // namespace

TEST(BadInput, EngineNamesTheField)
{
  using E = bsp::ErrorKind;
  const std::vector<SpoiledProblem> cases = {
      {"mass_matrix", E::InvalidArgument, [](bsp::ImpactProblem& p) { p.mass_matrix(0, 0) = NaN; }},
      {"mass_matrix", E::InvalidArgument, [](bsp::ImpactProblem& p) { p.mass_matrix(1, 1) = -1.0; }},
      {"mass_matrix", E::InvalidArgument, [](bsp::ImpactProblem& p) { p.mass_matrix(1, 1) = 0.0; }},
      {"mass_matrix", E::InvalidArgument, [](bsp::ImpactProblem& p) { p.mass_matrix(0, 1) = 0.5; }},
      {"velocity", E::InvalidArgument, [](bsp::ImpactProblem& p) { p.velocity(0) = INF; }},
      {"velocity", E::InvalidArgument, [](bsp::ImpactProblem& p) { p.velocity.resize(3); }},
      {"contacts[1].law.restitution", E::InvalidArgument,
       [](bsp::ImpactProblem& p) { p.contacts[1].law.restitution = 1.5; }},
      {"contacts[0].law.restitution", E::InvalidArgument,
       [](bsp::ImpactProblem& p) { p.contacts[0].law.restitution = -0.1; }},
      {"contacts[0].law.restitution", E::InvalidArgument,
       [](bsp::ImpactProblem& p) { p.contacts[0].law.restitution = NaN; }},
      {"contacts[1].law.stiffness", E::InvalidArgument,
       [](bsp::ImpactProblem& p) { p.contacts[1].law.stiffness = 0.0; }},
      {"contacts[1].law.stiffness", E::InvalidArgument,
       [](bsp::ImpactProblem& p) { p.contacts[1].law.stiffness = -2.0; }},
      {"contacts[0].law.stiffness", E::InvalidArgument,
       [](bsp::ImpactProblem& p) { p.contacts[0].law.stiffness = INF; }},
      {"contacts[0].normal", E::InvalidArgument, [](bsp::ImpactProblem& p) { p.contacts[0].normal.setZero(); }},
      {"contacts[0].normal", E::InvalidArgument, [](bsp::ImpactProblem& p) { p.contacts[0].normal(0) = NaN; }},
      {"contacts", E::InvalidArgument, [](bsp::ImpactProblem& p) { p.contacts.clear(); }},
      {"velocity", E::NoApproachingContact, [](bsp::ImpactProblem& p) { p.velocity.setZero(); }},
      {"velocity", E::NoApproachingContact, [](bsp::ImpactProblem& p) { p.velocity(0) = +1.0; }},
  };
  for (std::size_t k = 0; k < cases.size(); ++k)
  {
    SCOPED_TRACE("case " + std::to_string(k));
    bsp::ImpactProblem problem = validProblem();
    cases[k].spoil(problem);
    expectError(problem, cases[k].code, cases[k].field);
  }
}

TEST(BadInput, ScenarioBuildersNameTheirOwnFields)
{
  bsp::BallBallTable c;
  c.e1 = 2.0;
  EXPECT_EQ(bsp::solve(c).error().field, "e1");
  c = {};
  c.m2 = 0.0;
  EXPECT_EQ(bsp::solve(c).error().field, "m2");
  c = {};
  c.stiffness_ratio = NaN;
  EXPECT_EQ(bsp::solve(c).error().field, "stiffness_ratio");
  c = {};
  c.v0 = 0.5;
  EXPECT_EQ(bsp::solve(c).error().code, bsp::ErrorKind::NoApproachingContact);

  bsp::BallChain chain{{1.0, 1.0}, {1.0, 0.0}, {1.0}, {1.0}, false};
  chain.stiffness = {1.0, 2.0};
  EXPECT_EQ(bsp::solve(chain).error().field, "stiffness");
  chain.stiffness = {1.0};
  chain.masses[1] = -1.0;
  EXPECT_EQ(bsp::solve(chain).error().field, "masses[1]");
  chain.masses[1] = 1.0;
  chain.velocities = {0.0, 1.0};
  EXPECT_EQ(bsp::solve(chain).error().code, bsp::ErrorKind::NoApproachingContact);
}

TEST(BadInput, EveryProblemStatesItsRangeOfMassAndStiffnessRatios)
{
  // Found by fuzzing: a ball–ball–table collision accepted a stiffness ratio of 336 where every other problem
  // refuses ratios outside [0.01, 100]; at m1/m2 = 5e9 its energy rose by 2.8e-8 of the initial (the light
  // ball's energy below the heavy one's round-off); three-ball chains with masses over nine decades ran into the
  // time bound (a light ball rattling between heavy ones at √(mass ratio) times the collision's frequency).
  bsp::BallBallTable c;
  c.stiffness_ratio = 336.0;
  EXPECT_EQ(bsp::solve(c).error().field, "stiffness_ratio");
  c = {};
  c.m1 = 6067.0;
  c.m2 = 1.26e-6;
  c.e2 = 0.234;
  c.v0 = -1.27e-4;
  const auto heavy_on_light = bsp::solve(c);
  ASSERT_FALSE(heavy_on_light.ok());
  EXPECT_EQ(heavy_on_light.error().code, bsp::ErrorKind::InvalidArgument);
  EXPECT_EQ(heavy_on_light.error().field, "m2");
  EXPECT_NE(heavy_on_light.error().message.find("m1/m2"), std::string::npos);
  c.m1 = 1e6 * c.m2;  // the edge of the range is accepted
  EXPECT_TRUE(bsp::solve(c).ok());

  bsp::BallChain chain{{10614.5, 575.848, 4.03379e-05},
                       {1.89787, -0.0304822, 0.0},
                       {0.179486, 0.760026, 66.4968},
                       {0.813244, 0.634124, 0.33654},
                       true};
  EXPECT_EQ(bsp::solve(chain).error().field, "masses[2]");
  chain.masses = {1.0, 1.0, 1.0};
  EXPECT_EQ(bsp::solve(chain).error().field, "stiffness[2]");  // 66.5/0.179 = 370 times the first
  chain.stiffness[2] = 17.0;
  EXPECT_TRUE(bsp::solve(chain).ok());
}

TEST(BadInput, EventLimitStopsInsteadOfLooping)
{
  bsp::BallBallTable c;
  c.m2 = 2.0 / std::sqrt(3.0);
  bsp::SolverOptions options;
  options.max_events = 2;
  const auto result = bsp::solve(c, options);
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error().code, bsp::ErrorKind::EventLimitExceeded);
}

namespace
{
void expectOptionError(const bsp::SolverOptions& options, const std::string& field)
{
  const auto result = bsp::solveMultipleImpact(validProblem(), options);
  ASSERT_FALSE(result.ok()) << "expected an error on " << field;
  EXPECT_EQ(result.error().code, bsp::ErrorKind::InvalidArgument);
  EXPECT_EQ(result.error().field, field);
  EXPECT_FALSE(result.error().message.empty());
}
}  // namespace

TEST(BadInput, SolverOptionsNameTheField)
{
  // Before these checks a NaN tolerance reached the integrator and a growth of 0 cut every contact's second bounce.
  for (double bad : {NaN, INF, -1e-12, 0.0, 1e-17, 1e-2, 2e-3})
  {
    bsp::SolverOptions options;
    options.relative_tolerance = bad;
    expectOptionError(options, "options.relative_tolerance");
  }
  // Coarser than 1e-8 the chatter cut lets energy rise; finer than 1e-16 is below the state's round-off.
  for (double bad : {NaN, -1e-14, 0.0, 0.5, 9e-3, 1e-6, 1e-300})
  {
    bsp::SolverOptions options;
    options.absolute_tolerance = bad;
    expectOptionError(options, "options.absolute_tolerance");
  }
  for (double bad : {NaN, INF, -1.0})
  {
    bsp::SolverOptions options;
    options.chatter_energy_fraction = bad;
    expectOptionError(options, "options.chatter_energy_fraction");
    options = {};
    options.chatter_resolution = bad;
    expectOptionError(options, "options.chatter_resolution");
  }
  for (double bad : {NaN, 1.0, 0.0, -INF})
  {
    bsp::SolverOptions options;
    options.chatter_stiffness_growth = bad;
    expectOptionError(options, "options.chatter_stiffness_growth");
  }
  bsp::SolverOptions options;
  options.max_events = 0;
  expectOptionError(options, "options.max_events");
  options = {};
  options.max_steps = 0;
  expectOptionError(options, "options.max_steps");
}

TEST(BadInput, SolverOptionsAtTheEdgesOfTheirRangesAreAccepted)
{
  bsp::SolverOptions options;
  options.relative_tolerance = 1e-15;
  options.absolute_tolerance = 1e-16;
  options.chatter_energy_fraction = 0.0;  // no cut by energy
  options.chatter_resolution = 0.0;       // no cut by deformation
  options.chatter_stiffness_growth = INF;
  EXPECT_TRUE(bsp::validate(options).ok());
  EXPECT_TRUE(bsp::solveMultipleImpact(validProblem(), options).ok());
  options.relative_tolerance = 1e-3;
  options.absolute_tolerance = 1e-8;
  EXPECT_TRUE(bsp::validate(options).ok());
  EXPECT_TRUE(bsp::solveMultipleImpact(validProblem(), options).ok());
}

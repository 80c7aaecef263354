// The separation clock (src/impact/separation_clock.hpp): Bulirsch–Stoer on a logarithmic clock while sliding
// contacts separate, against the same integration in plain time at tolerance 1e-13. Same state sequence, same
// final velocities to 1e-9 (m/s, rad/s), and the impulse curve it records stays in physical time.
#include <gtest/gtest.h>

#include <algorithm>

#include "../fixtures/paper_masse.hpp"
#include "billiard_shot_planner/scenarios/ball_table_impact.hpp"
#include "billiard_shot_planner/scenarios/cue_strike.hpp"
#include "billiard_shot_planner/scenarios/cushion_impact.hpp"
#include "same_solution.hpp"

namespace bsp = billiard_shot_planner;

namespace
{
bsp::SolverOptions plainTime()
{
  bsp::SolverOptions options = bench::withTolerance(1e-13);
  options.separation_clock = false;
  return options;
}

void expectSameSolution(const bsp::ImpactResult& clocked, const bsp::ImpactResult& plain, const char* name)
{
  same_solution::expectSameSolution(clocked, plain, 1e-9, name);
  for (std::size_t k = 0; k < std::min(clocked.events.size(), plain.events.size()); ++k)
    EXPECT_NEAR(clocked.events[k].at.time, plain.events[k].at.time, 1e-9 * plain.events.back().at.time)
        << name << " event " << k;
}
}  // namespace

TEST(SeparationClock, MasseStrikeMatchesPlainTime)
{
  // Both contacts slide into their separation: the case the clock is for.
  const bsp::CueStrike strike = fixtures::paperMasseStrike();
  const auto clocked = bsp::solve(strike);
  const auto plain = bsp::solve(strike, plainTime());
  ASSERT_TRUE(clocked.ok() && plain.ok());
  expectSameSolution(clocked.value().impact, plain.value().impact, "massé strike");
}

TEST(SeparationClock, CushionHitMatchesPlainTime)
{
  bsp::CushionImpact hit;  // cushion nose above the centre: the cloth is loaded from zero, both contacts slide
  hit.velocity = {1.5, 0.8, 0.0};
  hit.angular_velocity = {-10.0, 30.0, 20.0};
  hit.cushion_normal = Eigen::Vector3d(-0.963, 0.0, -0.269).normalized();
  hit.cushion = {0.85, 0.2, 10.0};
  hit.cloth = {0.51625, 0.152479, 10.0};
  const auto clocked = bsp::solve(hit);
  const auto plain = bsp::solve(hit, plainTime());
  ASSERT_TRUE(clocked.ok() && plain.ok());
  expectSameSolution(clocked.value().impact, plain.value().impact, "cushion hit");
}

TEST(SeparationClock, SlipStartingAtTheLastInstantEnds)
{
  // μ → ∞ sticks until the very end of restitution, where the vanishing cone makes the contact slip with a spring
  // length already at its floor: the clock must not crawl there (it once ran into the step limit).
  bsp::BallTableImpact impact;
  impact.velocity = {0.3, 0.0, -1.0};
  impact.table = {0.6, 1e9, 7.0};
  bsp::SolverOptions integrated;
  integrated.closed_form_linear_phases = false;  // the sticking phase too, as the slip it ends in
  const auto clocked = bsp::solve(impact, integrated);
  const auto plain = bsp::solve(impact, plainTime());
  ASSERT_TRUE(clocked.ok()) << clocked.error().message;
  ASSERT_TRUE(plain.ok());
  expectSameSolution(clocked.value().impact, plain.value().impact, "stick to the end");
  const auto& events = clocked.value().impact.events;
  EXPECT_TRUE(std::any_of(events.begin(), events.end(),
                          [](const bsp::ContactEvent& e) { return e.type == bsp::ContactEventType::StickToSlip; }));
}

TEST(SeparationClock, RecordedImpulseCurveIsInPhysicalTime)
{
  bsp::SolverOptions options;
  options.record_samples = true;
  const auto clocked = bsp::solve(fixtures::paperMasseStrike(), options).value().impact;
  options.separation_clock = false;
  const auto plain = bsp::solve(fixtures::paperMasseStrike(), options).value().impact;
  ASSERT_GT(clocked.samples.size(), 10u);
  for (std::size_t k = 1; k < clocked.samples.size(); ++k)
    ASSERT_GE(clocked.samples[k].time, clocked.samples[k - 1].time) << "sample " << k;
  // Both curves end at the same instant, the last separation.
  EXPECT_NEAR(clocked.samples.back().time, plain.samples.back().time, 1e-9 * plain.samples.back().time);
  EXPECT_NEAR(clocked.samples.back().time, clocked.events.back().at.time, 1e-12 * plain.samples.back().time);
}

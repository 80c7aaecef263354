// Shared by the tests that solve one impact two ways (closed form or integration, separation clock or plain time,
// quasi-steady or integrated slip): the two must give the same state sequence and the same final velocities.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "../fixtures/bench_problems.hpp"
#include "billiard_shot_planner/scenarios/ball_table_impact.hpp"
#include "billiard_shot_planner/scenarios/cue_strike.hpp"
#include "billiard_shot_planner/scenarios/cushion_impact.hpp"

namespace same_solution
{
namespace bsp = billiard_shot_planner;

// The engine's result of any scenario (impactOf) and the integrated reference's settings (integratedOnly) are the
// benchmarks' own, so that tests and benchmarks check against the same reference.
using bench::impactOf;
using bench::integratedOnly;

/// The events of one instant (type and contact), from event k on, sorted: events at one instant may be logged in
/// either order (a link released and a contact separating together, as their guards cross in one step or as
/// transitions at a state's start). Advances k past them.
inline std::vector<std::pair<int, std::size_t>> eventsAtOneInstant(const bsp::ImpactResult& r, std::size_t& k)
{
  std::vector<std::pair<int, std::size_t>> events;
  const double instant = r.events[k].at.time;
  while (k < r.events.size() && std::abs(r.events[k].at.time - instant) <= 1e-12 * std::abs(instant))
  {
    events.emplace_back(static_cast<int>(r.events[k].type), r.events[k].contact);
    ++k;
  }
  std::sort(events.begin(), events.end());
  return events;
}

/// The same events (type and contact, in order, those of one instant in any order) and final velocities within
/// `velocity_tolerance` (m/s, rad/s).
inline void expectSameSolution(const bsp::ImpactResult& a, const bsp::ImpactResult& b, double velocity_tolerance,
                               const std::string& name)
{
  ASSERT_EQ(a.events.size(), b.events.size()) << name;
  std::size_t ka = 0, kb = 0;
  while (ka < a.events.size() && kb < b.events.size())
  {
    const std::size_t first = ka;
    ASSERT_EQ(eventsAtOneInstant(a, ka), eventsAtOneInstant(b, kb)) << name << " events from " << first;
  }
  EXPECT_LT((a.velocity - b.velocity).cwiseAbs().maxCoeff(), velocity_tolerance) << name;
}

/// Solves `problem` with both settings and compares the impacts.
template <class Problem>
void expectSameSolution(const Problem& problem, const bsp::SolverOptions& first, const bsp::SolverOptions& second,
                        double velocity_tolerance, const std::string& name)
{
  const auto a = bsp::solve(problem, first);
  const auto b = bsp::solve(problem, second);
  ASSERT_TRUE(a.ok()) << name << ": " << a.error().message;
  ASSERT_TRUE(b.ok()) << name << ": " << b.error().message;
  expectSameSolution(impactOf(a.value()), impactOf(b.value()), velocity_tolerance, name);
}

}  // namespace same_solution

// The planner's faster path, the solver settings of its rollouts (PLANNING_TOLERANCE, as makeContext sets them),
// against the default (1e-12, 1e-14) on the plan benchmark's noise-free shots: final positions within 0.5 mm on at
// least 99 % of the shots that are not chaotic, where a shot is chaotic when a change of the cue's speed by 1e-9 of
// itself moves a final position by more than 0.5 mm (issue 37's bound for any faster path).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "../../src/planning/plan_context.hpp"
#include "../fixtures/plan_layouts.hpp"
#include "billiard_shot_planner/planning/shot_planner.hpp"

namespace bsp = billiard_shot_planner;

namespace
{
constexpr double POSITION_BOUND = 5e-4;  ///< m
constexpr double SPEED_PERTURBATION = 1e-9;
constexpr unsigned LAYOUTS = 80;  ///< 20 of each group of 1, 3, 7 and 15 object balls

/// Every ball's final position, the cue ball first; empty when the shot cannot be placed or predicted.
std::vector<Eigen::Vector3d> finalPositions(const plan_layouts::Layout& layout, bsp::Stroke stroke,
                                            const bsp::SolverOptions& solver, double speed_factor = 1.0)
{
  bsp::ShotConfiguration configuration = plan_layouts::CONFIGURATION;
  configuration.solver = solver;
  stroke.speed *= speed_factor;
  const auto cue = bsp::placeStroke(stroke, layout.balls[0].state.position.head<2>(), plan_layouts::R);
  if (!cue)
    return {};
  const auto shot = bsp::predictShot(cue.value(), configuration, plan_layouts::objectBalls(layout));
  if (!shot)
    return {};
  std::vector<Eigen::Vector3d> positions;
  for (const bsp::BallTrajectory& ball : shot.value().table.balls)
    positions.push_back(ball.finalState().position);
  return positions;
}

double largestDistance(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b)
{
  double largest = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k)
    largest = std::max(largest, (a[k] - b[k]).norm());
  return largest;
}
}  // namespace

TEST(PlanningTolerance, FinalPositionsAgreeWithTheDefaultOnShotsThatAreNotChaotic)
{
  const bsp::SolverOptions by_default_solver = plan_layouts::CONFIGURATION.solver;
  const bsp::PlanRequest request;
  const bsp::SolverOptions planning_solver =
      bsp::planning::makeContext(request, plan_layouts::CONFIGURATION).configuration.solver;
  ASSERT_GT(planning_solver.relative_tolerance, by_default_solver.relative_tolerance);
  int compared = 0, chaotic = 0, within = 0;
  double worst = 0.0;
  for (unsigned k = 0; k < LAYOUTS; ++k)
  {
    const plan_layouts::Layout layout = plan_layouts::randomLayout(k);
    const bsp::Stroke stroke = plan_layouts::ghostBallShot(layout).stroke;
    const auto by_default = finalPositions(layout, stroke, by_default_solver);
    const auto perturbed = finalPositions(layout, stroke, by_default_solver, 1.0 + SPEED_PERTURBATION);
    const auto planning = finalPositions(layout, stroke, planning_solver);
    ASSERT_FALSE(by_default.empty()) << "layout " << k;
    ASSERT_EQ(by_default.size(), planning.size()) << "layout " << k;
    ASSERT_EQ(by_default.size(), perturbed.size()) << "layout " << k;
    if (largestDistance(by_default, perturbed) > POSITION_BOUND)
    {
      ++chaotic;
      continue;
    }
    ++compared;
    const double distance = largestDistance(by_default, planning);
    worst = std::max(worst, distance);
    within += distance <= POSITION_BOUND;
  }
  std::printf("planning tolerance %g: %d of %d shots within %.1f mm of the default (worst %.3g m); %d chaotic\n",
              planning_solver.relative_tolerance, within, compared, 1e3 * POSITION_BOUND, worst, chaotic);
  EXPECT_GE(compared, static_cast<int>(LAYOUTS) / 2);
  EXPECT_GE(within, static_cast<int>(std::ceil(0.99 * compared)));
}

#pragma once

#include <vector>

#include "billiard_shot_planner/core/expected.hpp"
#include "billiard_shot_planner/impact/impact_problem.hpp"
#include "billiard_shot_planner/impact/impact_result.hpp"
#include "billiard_shot_planner/impact/solver_options.hpp"

namespace billiard_shot_planner
{
/// A line of balls in contact (Newton's cradle and friends), frictionless. Ball i moves with velocity
/// velocities[i] along the line; contact i joins ball i and ball i+1 (its impulse pushes ball i+1 forward), and
/// with `wall` a last contact joins the last ball and a fixed wall ahead of it.
struct BallChain
{
  std::vector<double> masses;
  std::vector<double> velocities;
  std::vector<double> stiffness;    ///< one per contact
  std::vector<double> restitution;  ///< one per contact
  bool wall = false;

  std::size_t contactCount() const { return masses.empty() ? 0 : masses.size() - 1 + (wall ? 1 : 0); }
};

/// The engine's configuration for this chain; the error names the BallChain field.
Expected<ImpactProblem> makeImpactProblem(const BallChain& chain);

Expected<ImpactResult> solve(const BallChain& chain, const SolverOptions& options = {});

}  // namespace billiard_shot_planner

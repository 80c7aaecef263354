#pragma once

#include <string>
#include <vector>

#include "billiard_shot_planner/core/expected.hpp"
#include "billiard_shot_planner/impact/impact_problem.hpp"
#include "billiard_shot_planner/impact/impact_result.hpp"
#include "billiard_shot_planner/impact/solver_options.hpp"

namespace billiard_shot_planner
{
/// The paper's §3 problem: ball 1 falls with velocity v0 < 0 onto ball 2, which rests on a table; frictionless,
/// centres aligned, upward positive. Contact 0 is ball–ball (impulse I1 on ball 1), contact 1 is ball–table
/// (impulse I2 on ball 2).
struct BallBallTable
{
  double m1 = 1.0;
  double m2 = 1.0;
  double stiffness_ratio = 1.0;  ///< k2/k1, ball–table over ball–ball
  double e1 = 1.0;               ///< ball–ball restitution
  double e2 = 1.0;               ///< ball–table restitution
  double v0 = -1.0;
};

/// The engine's configuration for this problem; the error names the BallBallTable field.
Expected<ImpactProblem> makeImpactProblem(const BallBallTable& collision);

/// "S1" (both contacts active), "S2" (ball–table only), "S3" (ball–ball only), "S4" (none, terminal).
std::string ballBallTableStateName(const std::vector<std::size_t>& active);

/// The state sequence of a solved ball–ball–table collision in the paper's names.
std::vector<std::string> ballBallTableStates(const ImpactResult& result);

/// Solves the collision with the multiple-impact engine.
Expected<ImpactResult> solve(const BallBallTable& collision, const SolverOptions& options = {});

}  // namespace billiard_shot_planner

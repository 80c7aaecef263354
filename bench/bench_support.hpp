#pragma once

// Settings and reference solutions shared by the benchmark programs.
#include <Eigen/Core>

#include "billiard_shot_planner/impact/impact_result.hpp"
#include "billiard_shot_planner/impact/solver_options.hpp"
#include "billiard_shot_planner/scenarios/ball_ball_table.hpp"
#include "billiard_shot_planner/scenarios/ball_chain.hpp"
#include "billiard_shot_planner/scenarios/ball_table_impact.hpp"
#include "billiard_shot_planner/scenarios/cue_strike.hpp"

namespace bench
{
namespace bsp = billiard_shot_planner;

inline bsp::SolverOptions withTolerance(double relative)
{
  bsp::SolverOptions options;
  options.relative_tolerance = relative;
  options.absolute_tolerance = relative * 1e-2;
  return options;
}

/// Every state integrated numerically (the closed form of sticking and frictionless states off).
inline bsp::SolverOptions integratedOnly(double relative)
{
  bsp::SolverOptions options = withTolerance(relative);
  options.closed_form_linear_phases = false;
  return options;
}

inline const bsp::ImpactResult& impactOf(const bsp::ImpactResult& result)
{
  return result;
}

inline const bsp::ImpactResult& impactOf(const bsp::CueStrikeResult& result)
{
  return result.impact;
}

/// The converged solution errors are measured against: numerical integration alone at tolerance 1e-14, independent
/// of the closed form (and, for the paper's collisions, equal to the errata's independent values to 1e-7).
template <class Problem>
Eigen::VectorXd referenceVelocities(const Problem& problem)
{
  return impactOf(bsp::solve(problem, integratedOnly(1e-14)).value()).velocity;
}

/// Largest difference of the generalised velocities after the impact from the reference.
template <class Problem>
double velocityError(const Problem& problem, const bsp::SolverOptions& options)
{
  return (impactOf(bsp::solve(problem, options).value()).velocity - referenceVelocities(problem)).cwiseAbs().maxCoeff();
}

}  // namespace bench

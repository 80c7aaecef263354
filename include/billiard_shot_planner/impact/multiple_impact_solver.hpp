#pragma once

#include "billiard_shot_planner/core/expected.hpp"
#include "billiard_shot_planner/impact/impact_problem.hpp"
#include "billiard_shot_planner/impact/impact_result.hpp"
#include "billiard_shot_planner/impact/solver_options.hpp"

namespace billiard_shot_planner
{
/// Solves a simultaneous multiple impact with the state-transition-diagram model of Jia, Mason & Erdmann
/// (paper §2–8, Algorithm 2) in its equivalent time-domain form (spec §4.3): virtual springs integrated with an
/// adaptive Dormand–Prince method, every transition located as a root of the dense output.
///
/// Pure function: thread-safe, no global state; returns an Error instead of throwing.
Expected<ImpactResult> solveMultipleImpact(const ImpactProblem& problem, const SolverOptions& options = {});

}  // namespace billiard_shot_planner

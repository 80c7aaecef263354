#pragma once

#include "billiard_shot_planner/core/expected.hpp"
#include "billiard_shot_planner/impact/impact_problem.hpp"
#include "billiard_shot_planner/impact/impact_result.hpp"
#include "billiard_shot_planner/impact/solver_options.hpp"

namespace billiard_shot_planner
{
/// Solves a simultaneous multiple impact with the state-transition-diagram model of Jia, Mason & Erdmann
/// (paper §2–8, Algorithm 2) in its equivalent time-domain form (docs/engine.md, "Formulation"): virtual springs
/// integrated in closed form where their dynamics is linear and otherwise by Bulirsch–Stoer extrapolation with dense
/// output, every transition located as a root of the guards along the solution.
///
/// Pure function: thread-safe, no global state; returns an Error instead of throwing.
Expected<ImpactResult> solveMultipleImpact(const ImpactProblem& problem, const SolverOptions& options = {});

}  // namespace billiard_shot_planner

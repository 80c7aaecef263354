#pragma once

#include <nlohmann/json.hpp>

#include "billiard_shot_planner/core/expected.hpp"

namespace billiard_shot_planner
{
/// Solves one problem given as JSON (the format of the `impact_solve` program, docs/cli.md) and returns the result
/// as JSON. Malformed or invalid input gives an Error naming the field; nothing throws.
///
/// Problems: "ball_ball_table", "chain". Every problem accepts an optional "solver" object
/// {"relative_tolerance", "absolute_tolerance", "max_events", "record_samples"}.
Expected<nlohmann::json> solveJsonProblem(const nlohmann::json& request);

}  // namespace billiard_shot_planner

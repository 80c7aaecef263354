#pragma once

#include <string>
#include <vector>

#include "billiard_shot_planner/planning/shot_planner.hpp"
#include "parameter_tree.hpp"

namespace billiard_shot_planner
{
/// The planner's parameters of the node (~planning/...), the defaults of every goal.
struct PlanningSettings
{
  RobotLimits limits;
  ExecutionNoise noise;
  double budget = 0.5;  ///< s
  int rollouts = 200;
  int threads = 0;  ///< 0: one per hardware thread
  /// m/s: a ball whose speed, and whose spin times its radius, stay below this is at rest (a tracker's noise); a
  /// faster one stops the plan (ErrorKind::BallsMoving).
  double rest_speed = 0.01;
};

/// A numeric planning parameter by its name under ~: "planning/noise/phi", "planning/limits/max_speed", …
struct PlanningParameter
{
  const char* name;
  double* value;
};
std::vector<PlanningParameter> planningParameters(PlanningSettings& settings);

/// Reads ~planning/... (absent ones keep their defaults) and checks them; the error names the parameter.
Expected<PlanningSettings> readPlanningSettings(ParameterTree& parameters);

/// A tracker never reports exactly zero: a ball slower than `rest_speed` (its spin times its radius too) is at rest
/// and its motion is dropped; a faster one is refused (ErrorKind::BallsMoving), for a call that needs it at rest (a
/// plan's balls, the cue ball of a prediction).
Status settleAtRest(TableBall& ball, double rest_speed, double ball_radius);

/// Sets one parameter by its name ("planning/rollouts" too): whether the name is a planning parameter, and the
/// error when it is but the value is refused.
Expected<bool> applyPlanningOverride(PlanningSettings& settings, const std::string& name, double value);

}  // namespace billiard_shot_planner

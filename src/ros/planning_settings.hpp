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

/// Sets one parameter by its name ("planning/rollouts" too): whether the name is a planning parameter, and the
/// error when it is but the value is refused.
Expected<bool> applyPlanningOverride(PlanningSettings& settings, const std::string& name, double value);

}  // namespace billiard_shot_planner

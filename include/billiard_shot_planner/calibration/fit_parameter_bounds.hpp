#pragma once

#include <string>

#include "billiard_shot_planner/calibration/least_squares_fit.hpp"
#include "billiard_shot_planner/core/expected.hpp"
#include "billiard_shot_planner/shot/shot_prediction.hpp"

namespace billiard_shot_planner
{
/// The unknown `name` (a dotted name of numericParameters(): "motion.sliding_friction") of a fit that starts from
/// `configuration`: it starts at the configuration's value, within the bounds physics puts on its kind — a
/// restitution in [0, 1], a friction coefficient in [0, 2], a tangential compliance η² in [0.05, 100], a stiffness
/// ratio in [1e-3, 1e3] — or, for another positive constant, two decades either side of its start. Error:
/// InvalidArgument with field `field` when no parameter that can be fitted has this name.
Expected<FitParameter> fitParameterFor(const ShotConfiguration& configuration, const std::string& name,
                                       const std::string& field);

}  // namespace billiard_shot_planner

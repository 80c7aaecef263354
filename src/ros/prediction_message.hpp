#pragma once

#include <billiard_shot_planner/ShotPrediction.h>

#include <string>

#include "billiard_shot_planner/shot/shot_prediction.hpp"

namespace billiard_shot_planner
{
/// The core's prediction as a message in `frame` (the table frame). Pure conversion, no ROS master needed.
/// The trajectory is sampled every `spacing` seconds and at every event.
ShotPrediction toMessage(const ShotOutcome& outcome, const std::string& frame, double spacing);

}  // namespace billiard_shot_planner

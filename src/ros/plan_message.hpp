#pragma once

#include <billiard_shot_planner/CuePlan.h>
#include <billiard_shot_planner/PlanShotResult.h>
#include <visualization_msgs/Marker.h>

#include <string>

#include "billiard_shot_planner/planning/shot_planner.hpp"

namespace billiard_shot_planner
{
/// A planned shot as a message in `frame`: the cue pose (origin at the tip, x along the cue's motion), its speed and
/// the stroke. Pure conversion.
CuePlan toMessage(const PlannedShot& shot, const std::string& frame);

/// The plan's result (the prediction of the best shot sampled every `spacing` seconds), its poses and prediction
/// stamped `stamp` (when it was planned). Pure conversion.
PlanShotResult toResult(const ShotPlan& plan, const std::string& frame, double spacing, const ros::Time& stamp);

/// Where the target ended in the best shot's noisy rollouts: a cloud of small faint spheres (namespace
/// "plan_spread"), the spread of the outcomes under the robot's noise.
visualization_msgs::Marker spreadMarker(const PlannedShot& shot, const std::string& frame, double ball_radius);

}  // namespace billiard_shot_planner

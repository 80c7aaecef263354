#pragma once

#include <geometry_msgs/Pose.h>
#include <visualization_msgs/InteractiveMarker.h>

#include <Eigen/Core>
#include <string>
#include <vector>

#include "billiard_shot_planner/planning/stroke.hpp"

namespace billiard_shot_planner
{
/// The cue a person drags in rviz (~cue_control): the stroke it stands for, on the cue ball at `ball`.
struct CueHandles
{
  Stroke stroke{0.0, 0.0, 2.0, 0.0, 0.0};
  Eigen::Vector2d ball = Eigen::Vector2d::Zero();  ///< m, the cue ball's centre on the cloth, table frame
  double radius = 0.028575;                        ///< m, the ball's
  double speed_scale = 0.1;                        ///< m of the speed handle behind the tip per m/s
};

/// The interactive markers' names: the cue turned about the ball (heading and elevation), the tip moved over the
/// ball's face (a, b), the speed handle pulled back along the cue.
inline const char* const AIM_HANDLE = "aim";
inline const char* const TIP_HANDLE = "tip";
inline const char* const SPEED_HANDLE = "speed";

/// What a drag may set: the elevation, the hit point's distance from the centre (ball radii) and the speed.
constexpr double MAX_HANDLE_ELEVATION = 1.4;  ///< rad, 80°
constexpr double MAX_HANDLE_OFFSET = 0.8;
constexpr double MIN_HANDLE_SPEED = 0.1;  ///< m/s
constexpr double MAX_HANDLE_SPEED = 8.0;  ///< m/s

/// The three interactive markers of `handles`, in `frame` (the table frame): the aim at the ball's centre with the
/// cue drawn through the hit point; the tip at the hit point, moving in the plane of the ball's face; the speed
/// handle behind the tip at speed × speed_scale along the cue. Pure function: testable without a ROS master.
std::vector<visualization_msgs::InteractiveMarker> cueHandleMarkers(const CueHandles& handles,
                                                                    const std::string& frame);

/// The stroke after the handle `marker` was dragged to `pose` (table frame), within the ranges above: the aim's
/// orientation gives φ and θ, the tip's position a and b, the speed handle's distance behind the tip the speed. An
/// unknown marker leaves the stroke as it is.
Stroke strokeAfterDrag(const CueHandles& handles, const std::string& marker, const geometry_msgs::Pose& pose);

}  // namespace billiard_shot_planner

#pragma once

#include <visualization_msgs/MarkerArray.h>

#include <string>

#include "billiard_shot_planner/shot/shot_prediction.hpp"

namespace billiard_shot_planner
{
/// How the prediction is drawn (README "Markers" lists namespaces, colours and scales).
struct MarkerStyle
{
  double velocity_scale = 0.1;  ///< s: an arrow of 0.1 m per m/s of ball velocity
  double spin_scale = 0.002;    ///< m per rad/s of ball spin
  double path_width = 0.008;    ///< m
  double cue_length = 1.2;      ///< m, drawn behind the tip along the cue axis
  double cue_diameter = 0.013;  ///< m
};

/// Colours of the path by phase (RGBA). The visual test looks for these in rviz.
std_msgs::ColorRGBA phaseColour(MotionPhase phase);

/// The table alone (cloth, cushions, pockets), a DELETEALL first: what the node draws before its first answer.
visualization_msgs::MarkerArray tableMarkers(const Table& table, const std::string& frame);

/// One array for one prediction, in `frame`: a DELETEALL first, then the path (a LINE_STRIP coloured by phase),
/// the ball at the start and at the end, velocity and spin arrows at launch, the hit point, the cue, events, the
/// strike's touching balls (when the cue ball touches others) and the table (cloth, cushions, pockets). Pure function:
/// testable without a ROS master.
visualization_msgs::MarkerArray trajectoryMarkers(const ShotOutcome& outcome, const ShotConfiguration& configuration,
                                                  const std::string& frame, double sample_spacing,
                                                  const MarkerStyle& style = {});

}  // namespace billiard_shot_planner

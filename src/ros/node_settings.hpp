#pragma once

#include <ros/node_handle.h>

#include <string>
#include <vector>

#include "billiard_shot_planner/calibration/shot_recorder.hpp"
#include "billiard_shot_planner/core/expected.hpp"
#include "billiard_shot_planner/shot/shot_prediction.hpp"
#include "cockpit_settings.hpp"
#include "parameter_tree.hpp"
#include "planning_settings.hpp"

namespace billiard_shot_planner
{
/// The node's parameters (private namespace; README "Parameters" lists them with units, defaults and ranges).
struct NodeSettings
{
  std::string target_frame = "table";  ///< the table frame the answers are in
  double tf_timeout = 0.2;             ///< s, wait for a transform
  double sample_spacing = 0.01;        ///< s, between trajectory samples in messages and markers
  /// s: a request without balls uses the latest ~table_state only if it arrived within this (0: however old).
  double table_state_timeout = 0.0;
  int threads = 2;  ///< service threads
  ShotConfiguration shot;
  PlanningSettings planning;
  RecorderLimits recording;  ///< ~calibration/track_duration, ~calibration/max_shots
  CockpitSettings cockpit;
};

/// Reads every parameter (absent ones keep their defaults) and validates them. The error names the parameter: one of
/// the wrong type, a value out of its range, or a parameter under the node's namespace that the node does not have
/// (~tuning/, dynamic_reconfigure's own, aside).
Expected<NodeSettings> readSettings(ParameterTree& parameters);
/// The settings by the parameters' names, as ~get_configuration answers them: the numbers (SI units; integers as
/// whole numbers) and the parameters that name a choice (a frame, a model, a law, true/false, the pockets' list).
/// Each name reads back through readSettings() to the same settings.
struct SettingsDescription
{
  std::vector<std::string> names;
  std::vector<double> values;
  std::vector<std::string> choice_names;
  std::vector<std::string> choice_values;
};
SettingsDescription describeSettings(NodeSettings settings);

/// readSettings() of the node's private namespace on the parameter server.
Expected<NodeSettings> readSettings(const ros::NodeHandle& private_handle);

}  // namespace billiard_shot_planner

#pragma once

#include <billiard_shot_planner/FitCalibration.h>
#include <billiard_shot_planner/RecordShot.h>
#include <billiard_shot_planner/TableState.h>
#include <geometry_msgs/PoseStamped.h>
#include <ros/ros.h>
#include <std_srvs/Trigger.h>

#include <functional>
#include <mutex>
#include <vector>

#include "billiard_shot_planner/calibration/shot_recorder.hpp"

namespace billiard_shot_planner
{
/// Calibration's ROS face: ~record_shot records an executed shot, every TableState the node receives extends the
/// recorded shots' tracks (ShotRecorder), ~fit_calibration fits the node's parameters to them (fitTracks) and
/// ~clear_shots forgets them. What it needs of the node — its configuration and tf — comes in as functions.
class ShotCalibrationServer
{
public:
  struct NodeAccess
  {
    /// The node's configuration as tuned now.
    std::function<ShotConfiguration()> configuration;
    /// The balls in the table frame, waiting for tf up to the node's tf_timeout when `wait_for_tf`, else not at all.
    std::function<Expected<std::vector<TableBall>>(const TableState&, bool wait_for_tf)> place_table;
    /// The cue's tip and direction in the table frame; its ball is left for the caller to place.
    std::function<Expected<CuePlacement>(const geometry_msgs::PoseStamped&, double speed)> place_cue;
  };

  ShotCalibrationServer(ros::NodeHandle& private_node, NodeAccess access, const RecorderLimits& limits, int threads);

  /// A TableState the node received: a sighting of its balls, at its stamp (at its arrival when unstamped).
  void observe(const TableState& table);

private:
  bool recordShot(RecordShot::Request& request, RecordShot::Response& response);
  bool fit(FitCalibration::Request& request, FitCalibration::Response& response);
  bool clearShots(std_srvs::Trigger::Request& request, std_srvs::Trigger::Response& response);
  /// The shot as recorded: the cue placed at the cue ball of the table before the strike.
  Expected<ObservedShot> executedShot(const RecordShot::Request& request, double strike_time);

  NodeAccess access_;
  int threads_;
  std::mutex recorder_mutex_;  ///< guards recorder_ against the subscriber's and the services' threads
  ShotRecorder recorder_;
  ros::ServiceServer record_service_;
  ros::ServiceServer fit_service_;
  ros::ServiceServer clear_service_;
};

}  // namespace billiard_shot_planner

#pragma once

#include <billiard_shot_planner/ErrorCode.h>
#include <billiard_shot_planner/FitCalibrationAction.h>
#include <billiard_shot_planner/FitCalibrationNow.h>
#include <billiard_shot_planner/RecordShot.h>
#include <billiard_shot_planner/TableState.h>
#include <geometry_msgs/PoseStamped.h>
#include <ros/ros.h>
#include <std_srvs/Trigger.h>

#include <functional>
#include <mutex>
#include <variant>
#include <vector>

#include "billiard_shot_planner/calibration/shot_recorder.hpp"
#include "billiard_shot_planner/calibration/track_fit.hpp"
#include "checked_action_server.hpp"
#include "recorded_call.hpp"

namespace billiard_shot_planner
{
/// Calibration's ROS face: ~record_shot records an executed shot, every TableState the node receives extends the
/// recorded shots' tracks (ShotRecorder), the action ~fit_calibration (feedback, preemption with the best fit so far)
/// and the service ~fit_calibration_now fit the node's parameters to them (fitTracks), and ~clear_shots forgets them.
/// What it needs of the node — its configuration and tf — comes in as functions.
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
    /// A call answered, for the node's health.
    CallRecorder record;
  };

  ShotCalibrationServer(ros::NodeHandle& private_node, NodeAccess access, const RecorderLimits& limits, int threads);

  /// A TableState the node received: a sighting of its balls, at its stamp (at its arrival when unstamped).
  void observe(const TableState& table);

private:
  bool recordShot(RecordShot::Request& request, RecordShot::Response& response);
  /// What a fit is told while it runs: when to stop and where to report.
  struct FitHooks
  {
    std::function<bool()> stop;
    std::function<void(const FitProgress&)> progress;
  };
  /// What a goal asks of the fit, read and checked.
  struct FitJob
  {
    ShotConfiguration configuration;
    std::vector<FitParameter> parameters;
    double position_noise = 0.0;
    FitOptions options;
    std::vector<ObservedShot> shots;
  };
  /// The goal as a job (with a copy of the recorded shots), or why it cannot be fitted as it is (a bad field, no
  /// recorded shot).
  Expected<FitJob> prepare(const FitCalibrationGoal& goal);
  /// The job fitted (success false with the reason when the fit fails).
  FitCalibrationResult fit(FitJob& job, const FitHooks& hooks);
  /// The action's check: the job, or the result to reject the goal with.
  std::variant<FitJob, FitCalibrationResult> check(const FitCalibrationGoal& goal);
  void execute(const FitCalibrationGoalConstPtr& goal, FitJob& job);
  bool fitNow(FitCalibrationNow::Request& request, FitCalibrationNow::Response& response);
  bool clearShots(std_srvs::Trigger::Request& request, std_srvs::Trigger::Response& response);
  /// The shot as recorded: the cue placed at the cue ball of the table before the strike.
  Expected<ObservedShot> executedShot(const RecordShot::Request& request, double strike_time);

  NodeAccess access_;
  int threads_;
  std::mutex recorder_mutex_;  ///< guards recorder_ against the subscriber's and the services' threads
  ShotRecorder recorder_;
  CheckedActionServer<FitCalibrationAction, FitJob> action_server_;
  ros::ServiceServer record_service_;
  ros::ServiceServer fit_service_;
  ros::ServiceServer clear_service_;
};

}  // namespace billiard_shot_planner

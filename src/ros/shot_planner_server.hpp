#pragma once

#include <billiard_shot_planner/ErrorCode.h>
#include <billiard_shot_planner/PlanShotAction.h>
#include <billiard_shot_planner/PlanShotNow.h>
#include <billiard_shot_planner/TableState.h>
#include <geometry_msgs/PointStamped.h>
#include <ros/ros.h>

#include <functional>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "billiard_shot_planner/planning/shot_planner.hpp"
#include "checked_action_server.hpp"
#include "planning_settings.hpp"
#include "recorded_call.hpp"

namespace billiard_shot_planner
{
/// The planner's ROS face: the action ~plan_shot (feedback, preemption with the best plan so far) and the service
/// ~plan_shot_now (one answer within the goal's budget), both in front of planShot(). What it needs of the node —
/// the configuration with a goal's overrides, the table, tf — comes in as functions, so that the two share one
/// table subscription, one tf buffer and one tuned configuration.
class ShotPlannerServer
{
public:
  struct NodeAccess
  {
    /// The shot configuration and the planning settings with the goal's overrides applied.
    std::function<Expected<ShotConfiguration>(const std::vector<std::string>&, const std::vector<double>&,
                                              PlanningSettings&)>
        configure;
    /// The goal's table, or the latest received when the goal's is empty.
    std::function<Expected<TableState>(const TableState&)> table;
    /// The balls in the table frame.
    std::function<Expected<std::vector<TableBall>>(const TableState&)> place_table;
    /// A point in the table frame.
    std::function<Expected<Eigen::Vector2d>(const geometry_msgs::PointStamped&, const std::string&)> place_point;
    /// A call answered, for the node's health.
    CallRecorder record;
    /// A plan's noise-free prediction, to be watched (the node's animation); may be empty.
    std::function<void(const ShotPrediction&)> show;
  };

  ShotPlannerServer(ros::NodeHandle& private_node, NodeAccess access, std::string frame, double sample_spacing,
                    const ros::Publisher& markers);

  /// A goal planned at once, as ~plan_shot_now answers it, recorded as `call` (the cockpit's click-to-plan too).
  PlanShotResult answer(const std::string& call, const PlanShotGoal& goal);

private:
  /// A goal read, placed and validated: what the planner is asked, in the configuration of the moment.
  struct PlanJob
  {
    PlanRequest request;
    ShotConfiguration configuration;
  };
  /// The goal as a job, or why it cannot be planned as it is (a bad field, a frame tf does not know, a moving table).
  Expected<PlanJob> prepare(const PlanShotGoal& goal) const;
  /// The action's check: the job, or the result to reject the goal with.
  std::variant<PlanJob, PlanShotResult> check(const PlanShotGoal& goal) const;
  void execute(const PlanShotGoalConstPtr& goal, PlanJob& job);
  bool planNow(PlanShotNow::Request& request, PlanShotNow::Response& response);
  /// The job planned (success false with the reason when the planner fails); its markers drawn.
  PlanShotResult plan(PlanJob& job, const PlanHooks& hooks);
  /// work()'s result recorded as `call`, its prediction shown when it succeeded.
  PlanShotResult recorded(const std::string& call, const std::function<PlanShotResult()>& work);
  void publishMarkers(const ShotPlan& plan, const ShotConfiguration& configuration);

  NodeAccess access_;
  std::string frame_;
  double sample_spacing_;
  ros::Publisher markers_;
  CheckedActionServer<PlanShotAction, PlanJob> action_server_;
  ros::ServiceServer service_;
};

}  // namespace billiard_shot_planner

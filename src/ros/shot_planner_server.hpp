#pragma once

#include <billiard_shot_planner/ErrorCode.h>
#include <billiard_shot_planner/PlanShotAction.h>
#include <billiard_shot_planner/PlanShotNow.h>
#include <billiard_shot_planner/TableState.h>
#include <geometry_msgs/PointStamped.h>
#include <ros/ros.h>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "billiard_shot_planner/planning/shot_planner.hpp"
#include "checked_action_server.hpp"
#include "planning_settings.hpp"

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
    /// A call answered ("plan_shot", its wall-clock seconds, its code and message), for the node's health.
    std::function<void(const std::string&, double, const ErrorCode&, const std::string&)> record;
  };

  ShotPlannerServer(ros::NodeHandle& private_node, NodeAccess access, std::string frame, double sample_spacing,
                    const ros::Publisher& markers);

private:
  /// A goal that cannot be planned as it is (a bad field, a frame tf does not know, a moving table): the result to
  /// reject it with; nothing for a goal the planner takes.
  std::optional<PlanShotResult> check(const PlanShotGoal& goal) const;
  void execute(const PlanShotGoalConstPtr& goal);
  bool planNow(PlanShotNow::Request& request, PlanShotNow::Response& response);
  /// The result of a goal (success false with the reason when it cannot be planned).
  PlanShotResult plan(const PlanShotGoal& goal, const PlanHooks& hooks);
  /// plan(), timed and recorded as `call`.
  PlanShotResult planRecorded(const std::string& call, const PlanShotGoal& goal, const PlanHooks& hooks);
  Expected<PlanRequest> planRequest(const PlanShotGoal& goal, PlanningSettings& settings,
                                    ShotConfiguration& configuration) const;
  void publishMarkers(const ShotPlan& plan, const ShotConfiguration& configuration);

  NodeAccess access_;
  std::string frame_;
  double sample_spacing_;
  ros::Publisher markers_;
  CheckedActionServer<PlanShotAction> action_server_;
  ros::ServiceServer service_;
};

}  // namespace billiard_shot_planner

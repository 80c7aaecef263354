#include "shot_planner_server.hpp"

#include "billiard_shot_planner/core/validation.hpp"
#include "error_codes.hpp"
#include "plan_message.hpp"
#include "trajectory_markers.hpp"

namespace billiard_shot_planner
{
namespace
{
PlanShotResult failure(const Error& error)
{
  PlanShotResult result;
  result.success = false;
  result.message = error.describe();
  result.error_code = errorCodeOf(error);
  return result;
}

/// The goal's fields as the planner's request fields; the balls and the region are placed by the caller.
Status readGoal(const PlanShotGoal& goal, const PlanningSettings& settings, PlanRequest& request)
{
  request.cue_ball = goal.cue_ball.empty() ? CUE_BALL_ID : goal.cue_ball;
  request.target = goal.target;
  request.pocket = goal.pocket;
  if (!std::isfinite(goal.budget) || goal.budget < 0.0)
    return invalidArgument("budget", "must be >= 0 s (0: the node's ~planning/budget)");
  request.budget = goal.budget > 0.0 ? goal.budget : settings.budget;
  request.seed = goal.seed;
  request.rules = {goal.target_first != 0, goal.only_target != 0};
  request.limits = settings.limits;
  request.noise = settings.noise;
  request.rollouts = settings.rollouts;
  request.threads = settings.threads;
  return {};
}

}  // namespace

ShotPlannerServer::ShotPlannerServer(ros::NodeHandle& private_node, NodeAccess access, std::string frame,
                                     double sample_spacing, const ros::Publisher& markers)
    : access_(std::move(access)),
      frame_(std::move(frame)),
      sample_spacing_(sample_spacing),
      markers_(markers),
      action_server_(
          private_node, "plan_shot", [this](const PlanShotGoal& goal) { return check(goal); },
          [this](const PlanShotGoalConstPtr& goal, PlanJob& job) { execute(goal, job); })
{
  service_ = private_node.advertiseService("plan_shot_now", &ShotPlannerServer::planNow, this);
}

Expected<ShotPlannerServer::PlanJob> ShotPlannerServer::prepare(const PlanShotGoal& goal) const
{
  if (goal.override_names.size() != goal.override_values.size())
    return invalidArgument("override_values", "must have one value per name in override_names");
  PlanningSettings settings;
  auto configured = access_.configure(goal.override_names, goal.override_values, settings);
  if (!configured)
    return configured.error();
  PlanJob job{PlanRequest{}, configured.value()};
  PlanRequest& request = job.request;
  if (Status status = readGoal(goal, settings, request); !status)
    return status.error();
  const auto table = access_.table(goal.table);
  if (!table)
    return table.error();
  if (table.value().balls.empty())
    return invalidArgument("table", "no balls: give them in the goal or publish them on ~table_state");
  auto balls = access_.place_table(table.value());
  if (!balls)
    return balls.error();
  request.balls = balls.value();
  for (TableBall& ball : request.balls)
    if (Status status = settleAtRest(ball, settings.rest_speed, job.configuration.ball_radius); !status)
      return status.error();
  for (TableBall& ball : request.balls)
    ball.state.position.z() = job.configuration.ball_radius;
  if (goal.cue_region_radius > 0.0)
  {
    auto centre = access_.place_point(goal.cue_region_centre, "cue_region_centre");
    if (!centre)
      return centre.error();
    request.cue_region = CueRegion{centre.value(), goal.cue_region_radius};
  }
  if (Status status = validate(request, job.configuration); !status)
    return status.error();
  return job;
}

PlanShotResult ShotPlannerServer::plan(PlanJob& job, const PlanHooks& hooks)
{
  job.request.hooks = hooks;
  auto plan = planShot(job.request, job.configuration);
  if (!plan)
    return failure(plan.error());
  publishMarkers(plan.value(), job.configuration);
  return toResult(plan.value(), frame_, sample_spacing_, ros::Time::now());
}

PlanShotResult ShotPlannerServer::recorded(const std::string& call, const std::function<PlanShotResult()>& work)
{
  PlanShotResult result = recordedCall(access_.record, call, work);
  if (result.success && access_.show)
    access_.show(result.prediction);
  return result;
}

PlanShotResult ShotPlannerServer::answer(const std::string& call, const PlanShotGoal& goal)
{
  return recorded(call,
                  [&]
                  {
                    auto job = prepare(goal);
                    return job ? plan(job.value(), PlanHooks{}) : failure(job.error());
                  });
}

void ShotPlannerServer::publishMarkers(const ShotPlan& plan, const ShotConfiguration& configuration)
{
  if (plan.outcome.table.balls.empty())
    return;
  visualization_msgs::MarkerArray markers = trajectoryMarkers(plan.outcome, configuration, frame_, sample_spacing_);
  markers.markers.push_back(spreadMarker(plan.best, frame_, configuration.ball_radius));
  markers_.publish(markers);
}

std::variant<ShotPlannerServer::PlanJob, PlanShotResult> ShotPlannerServer::check(const PlanShotGoal& goal) const
{
  const ros::WallTime start = ros::WallTime::now();
  auto job = prepare(goal);
  if (job)
    return std::move(job.value());
  PlanShotResult refused = failure(job.error());
  ROS_WARN("plan_shot: rejected: %s", refused.message.c_str());
  if (access_.record)
    access_.record("plan_shot", (ros::WallTime::now() - start).toSec(), refused.error_code, refused.message);
  return refused;
}

void ShotPlannerServer::execute(const PlanShotGoalConstPtr& /*goal*/, PlanJob& job)
{
  PlanHooks hooks;
  hooks.progress = [this](const PlanProgress& progress)
  {
    PlanShotFeedback feedback;
    feedback.evaluations = progress.evaluations;
    feedback.shots_that_pot = progress.shots_that_pot;
    feedback.best_probability = progress.best_probability;
    action_server_.publishFeedback(feedback);
  };
  hooks.stop = [this]() { return action_server_.isPreemptRequested() || !ros::ok(); };
  const PlanShotResult result = recorded("plan_shot", [&] { return plan(job, hooks); });
  if (!result.success)
    ROS_WARN("plan_shot: %s", result.message.c_str());
  // A valid goal that was stopped ends preempted with the best so far, whether or not it pots.
  action_server_.finish(result, result.success || result.error_code.val == ErrorCode::NO_SHOT_FOUND);
}

bool ShotPlannerServer::planNow(PlanShotNow::Request& request, PlanShotNow::Response& response)
{
  response.result = answer("plan_shot_now", request.goal);
  if (!response.result.success)
    ROS_WARN("plan_shot_now: %s", response.result.message.c_str());
  return true;  // a goal that cannot be planned is an answer, not a failed call
}

}  // namespace billiard_shot_planner

#include "plan_message.hpp"

#include <Eigen/Geometry>

#include "error_codes.hpp"
#include "prediction_message.hpp"

namespace billiard_shot_planner
{
namespace
{
/// The spread's spheres: a third of a ball's diameter, faint yellow.
constexpr double SPREAD_SCALE = 0.33;
constexpr float SPREAD_ALPHA = 0.35f;
}  // namespace

CuePlan toMessage(const PlannedShot& shot, const std::string& frame)
{
  CuePlan plan;
  plan.target = shot.target;
  plan.pocket = shot.pocket;
  plan.bank_cushion = shot.bank_cushion;
  plan.cue_ball_path = toString(shot.cue_ball_path);
  plan.cue_pose.header.frame_id = frame;
  plan.cue_pose.pose.position.x = shot.cue.tip.x();
  plan.cue_pose.pose.position.y = shot.cue.tip.y();
  plan.cue_pose.pose.position.z = shot.cue.tip.z();
  const Eigen::Quaterniond q = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitX(), shot.cue.direction);
  plan.cue_pose.pose.orientation.x = q.x();
  plan.cue_pose.pose.orientation.y = q.y();
  plan.cue_pose.pose.orientation.z = q.z();
  plan.cue_pose.pose.orientation.w = q.w();
  plan.cue_speed = shot.cue.speed;
  plan.phi = shot.stroke.phi;
  plan.theta = shot.stroke.theta;
  plan.a = shot.stroke.a;
  plan.b = shot.stroke.b;
  plan.margin = shot.margin;
  plan.success_probability = shot.success_probability;
  plan.confidence_low = shot.confidence_low;
  plan.confidence_high = shot.confidence_high;
  plan.rollouts = shot.rollouts;
  return plan;
}

PlanShotResult toResult(const ShotPlan& plan, const std::string& frame, double spacing, const ros::Time& stamp)
{
  PlanShotResult result;
  // Nothing that pots is not a plan: the action ends aborted with the closest attempt still in the result.
  result.success = plan.found;
  result.message = plan.found ? "ok" : "no shot found: " + plan.explanation;
  result.error_code = errorCode(plan.found ? ErrorCode::SUCCESS : ErrorCode::NO_SHOT_FOUND);
  result.found = plan.found;
  result.explanation = plan.explanation;
  result.evaluations = plan.evaluations;
  result.planning_time = plan.seconds;
  if (!plan.best.target.empty())
    result.plan = toMessage(plan.best, frame);
  for (const PlannedShot& shot : plan.alternatives)
    result.alternatives.push_back(toMessage(shot, frame));
  if (!plan.outcome.table.balls.empty())
    result.prediction = toMessage(plan.outcome, frame, spacing);
  result.plan.cue_pose.header.stamp = stamp;
  for (CuePlan& shot : result.alternatives)
    shot.cue_pose.header.stamp = stamp;
  result.prediction.header.stamp = stamp;
  return result;
}

visualization_msgs::Marker spreadMarker(const PlannedShot& shot, const std::string& frame, double ball_radius)
{
  visualization_msgs::Marker m;
  m.header.frame_id = frame;
  m.ns = "plan_spread";
  m.type = visualization_msgs::Marker::SPHERE_LIST;
  m.action = visualization_msgs::Marker::ADD;
  m.pose.orientation.w = 1.0;
  m.scale.x = m.scale.y = m.scale.z = 2.0 * ball_radius * SPREAD_SCALE;
  m.color.r = 1.0f;
  m.color.g = 0.9f;
  m.color.b = 0.2f;
  m.color.a = SPREAD_ALPHA;
  for (const Eigen::Vector2d& end : shot.target_end_points)
  {
    geometry_msgs::Point p;
    p.x = end.x();
    p.y = end.y();
    p.z = ball_radius;
    m.points.push_back(p);
  }
  return m;
}

}  // namespace billiard_shot_planner

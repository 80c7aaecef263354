#include "shot_predictor_node.hpp"

#include <tf2_geometry_msgs/tf2_geometry_msgs.h>

#include <Eigen/Geometry>
#include <cmath>
#include <stdexcept>

#include "billiard_shot_planner/core/validation.hpp"
#include "parameter_names.hpp"
#include "prediction_message.hpp"
#include "trajectory_markers.hpp"
#include "tuning.hpp"

namespace billiard_shot_planner
{
namespace
{
/// A quaternion's norm may differ from 1 by this much (float round-off from other nodes), no more.
constexpr double QUATERNION_NORM_TOLERANCE = 1e-3;

Status checkRequest(const PredictShot::Request& r)
{
  const auto& p = r.cue_pose.pose.position;
  const auto& q = r.cue_pose.pose.orientation;
  if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
    return invalidArgument("cue_pose.pose.position", "contains NaN or infinite values");
  if (!std::isfinite(q.x) || !std::isfinite(q.y) || !std::isfinite(q.z) || !std::isfinite(q.w))
    return invalidArgument("cue_pose.pose.orientation", "contains NaN or infinite values");
  const double norm = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
  if (std::abs(norm - 1.0) > QUATERNION_NORM_TOLERANCE)
    return invalidArgument("cue_pose.pose.orientation", "is not a unit quaternion (norm " + formatNumber(norm) + ")");
  if (!std::isfinite(r.cue_speed) || r.cue_speed <= 0.0)
    return invalidArgument("cue_speed", "must be > 0 m/s, got " + formatNumber(r.cue_speed));
  const auto& b = r.ball_position.point;
  if (!std::isfinite(b.x) || !std::isfinite(b.y) || !std::isfinite(b.z))
    return invalidArgument("ball_position.point", "contains NaN or infinite values");
  // An empty frame can never be resolved: refused at once rather than after the whole tf timeout.
  if (r.cue_pose.header.frame_id.empty())
    return invalidArgument("cue_pose.header.frame_id", "is empty: give the frame the pose is expressed in");
  if (r.ball_position.header.frame_id.empty())
    return invalidArgument("ball_position.header.frame_id", "is empty: give the frame the point is expressed in");
  if (r.override_names.size() != r.override_values.size())
    return invalidArgument("override_values", "must have one value per name in override_names");
  return {};
}
}  // namespace

ShotPredictorNode::ShotPredictorNode(ros::NodeHandle& node, ros::NodeHandle& private_node)
{
  (void)node;
  auto settings = readSettings(private_node);
  if (!settings)
    throw std::runtime_error("invalid parameter ~" + settings.error().describe());
  settings_ = settings.value();
  prediction_publisher_ = private_node.advertise<ShotPrediction>("prediction", 10);
  marker_publisher_ = private_node.advertise<visualization_msgs::MarkerArray>("trajectory_markers", 1, true);
  // The tuning server starts from the loaded parameters, not from the .cfg defaults.
  tuning_server_ = std::make_unique<dynamic_reconfigure::Server<ShotPredictorConfig>>(
      tuning_mutex_, ros::NodeHandle(private_node, "tuning"));
  tuning_server_->updateConfig(toTuning(settings_.shot));
  tuning_server_->setCallback([this](ShotPredictorConfig& tuning, uint32_t level) { retune(tuning, level); });
  service_ = private_node.advertiseService("predict_shot", &ShotPredictorNode::predict, this);
  ROS_INFO("predict_shot ready: answers in frame '%s'", settings_.target_frame.c_str());
}

void ShotPredictorNode::retune(ShotPredictorConfig& tuning, uint32_t /*level*/)
{
  std::lock_guard<std::mutex> lock(configuration_mutex_);
  auto tuned = applyTuning(settings_.shot, tuning);
  if (!tuned)
  {
    // The server keeps and answers what the callback leaves in `tuning`: the node's configuration, unchanged.
    tuning = toTuning(settings_.shot);
    tuning.rejected = tuned.error().describe();
    ROS_WARN("tuning rejected, parameters unchanged: %s", tuning.rejected.c_str());
    return;
  }
  settings_.shot = tuned.value();
  tuning.rejected.clear();
}

Expected<ShotConfiguration> ShotPredictorNode::configurationFor(const PredictShot::Request& request) const
{
  ShotConfiguration configuration;
  {
    std::lock_guard<std::mutex> lock(configuration_mutex_);
    configuration = settings_.shot;
  }
  for (std::size_t i = 0; i < request.override_names.size(); ++i)
  {
    const std::string& name = request.override_names[i];
    if (Status status = applyOverride(configuration, configurationPath(name), request.override_values[i]); !status)
      return Error{status.error().code, "override " + parameterName(status.error().field), status.error().message};
  }
  return configuration;
}

Expected<CuePlacement> ShotPredictorNode::placeCue(const PredictShot::Request& request) const
{
  const ros::Duration timeout(settings_.tf_timeout);
  geometry_msgs::PoseStamped pose;
  geometry_msgs::PointStamped ball;
  try
  {
    pose = buffer_.transform(request.cue_pose, settings_.target_frame, timeout);
  }
  catch (const tf2::TransformException& e)
  {
    return invalidArgument("cue_pose.header.frame_id", std::string("no transform to the table frame: ") + e.what());
  }
  try
  {
    ball = buffer_.transform(request.ball_position, settings_.target_frame, timeout);
  }
  catch (const tf2::TransformException& e)
  {
    return invalidArgument("ball_position.header.frame_id",
                           std::string("no transform to the table frame: ") + e.what());
  }
  const auto& q = pose.pose.orientation;
  CuePlacement cue;
  cue.tip = Eigen::Vector3d(pose.pose.position.x, pose.pose.position.y, pose.pose.position.z);
  cue.direction = Eigen::Quaterniond(q.w, q.x, q.y, q.z).normalized() * Eigen::Vector3d::UnitX();
  cue.speed = request.cue_speed;
  cue.ball = Eigen::Vector2d(ball.point.x, ball.point.y);
  return cue;
}

bool ShotPredictorNode::predict(PredictShot::Request& request, PredictShot::Response& response)
{
  auto fail = [&](const Error& error)
  {
    response.success = false;
    response.message = error.describe();
    ROS_WARN("predict_shot: %s", response.message.c_str());
    return true;  // a domain error is an answer, not a failed call
  };
  if (Status status = checkRequest(request); !status)
    return fail(status.error());
  auto configuration = configurationFor(request);
  if (!configuration)
    return fail(configuration.error());
  auto cue = placeCue(request);
  if (!cue)
    return fail(cue.error());
  auto outcome = predictShot(cue.value(), configuration.value());
  if (!outcome)
    return fail(outcome.error());
  response.success = true;
  response.message = "ok";
  response.prediction = toMessage(outcome.value(), settings_.target_frame, settings_.sample_spacing);
  response.prediction.header.stamp = ros::Time::now();
  response.ball_velocity = response.prediction.ball_velocity;
  response.ball_angular_velocity = response.prediction.ball_angular_velocity;
  response.states = response.prediction.states;
  prediction_publisher_.publish(response.prediction);
  marker_publisher_.publish(
      trajectoryMarkers(outcome.value(), configuration.value(), settings_.target_frame, settings_.sample_spacing));
  return true;
}

}  // namespace billiard_shot_planner

#include "shot_animator.hpp"

#include <visualization_msgs/MarkerArray.h>

#include "billiard_shot_planner/core/validation.hpp"
#include "error_codes.hpp"
#include "shot_animation.hpp"

namespace billiard_shot_planner
{
ShotAnimator::ShotAnimator(ros::NodeHandle& private_node, const CockpitSettings& settings,
                           std::function<double()> ball_radius)
    : settings_(settings), ball_radius_(std::move(ball_radius))
{
  publisher_ = private_node.advertise<visualization_msgs::MarkerArray>("animation", 1);
  timer_ = private_node.createWallTimer(
      ros::WallDuration(1.0 / ANIMATION_FRAME_RATE), [this](const ros::WallTimerEvent&) { step(); }, false, false);
  service_ = private_node.advertiseService("animate", &ShotAnimator::replay, this);
}

void ShotAnimator::show(const ShotPrediction& prediction)
{
  {
    std::lock_guard<std::mutex> lock(mutex_);
    last_ = prediction;
  }
  if (settings_.animate)
    play(prediction, settings_.slow_motion);
}

double ShotAnimator::play(const ShotPrediction& prediction, double slow_motion)
{
  const double radius = ball_radius_();
  std::lock_guard<std::mutex> lock(mutex_);
  playing_ = prediction;
  playing_radius_ = radius;
  slow_motion_ = slow_motion;
  started_ = ros::WallTime::now();
  timer_.start();
  return slow_motion * animationLength(prediction);
}

bool ShotAnimator::replay(Animate::Request& request, Animate::Response& response)
{
  auto fail = [&response](const Error& error)
  {
    response.success = false;
    response.message = error.describe();
    response.error_code = errorCodeOf(error);
    return true;  // a domain error is an answer, not a failed call
  };
  const double slow_motion = request.slow_motion == 0.0 ? settings_.slow_motion : request.slow_motion;
  if (Status status = requireWithin(slow_motion, MIN_SLOW_MOTION, MAX_SLOW_MOTION, "slow_motion",
                                    "times real time; 0: the default");
      !status)
    return fail(status.error());
  ShotPrediction prediction = request.prediction;
  if (prediction.balls.empty())
  {
    std::lock_guard<std::mutex> lock(mutex_);
    prediction = last_;
  }
  if (prediction.balls.empty())
    return fail(invalidArgument("prediction", "has no balls, and nothing has been predicted yet"));
  if (prediction.header.frame_id.empty())
    return fail(invalidArgument("prediction.header.frame_id", "is empty: give the frame the paths are in"));
  if (Status status = checkAnimation(prediction); !status)
    return fail(status.error());
  response.duration = play(prediction, slow_motion);
  response.success = true;
  response.message = "ok";
  response.error_code = errorCode(ErrorCode::SUCCESS);
  return true;
}

void ShotAnimator::step()
{
  std::lock_guard<std::mutex> lock(mutex_);
  const double time = (ros::WallTime::now() - started_).toSec() / slow_motion_;
  publisher_.publish(animationFrame(playing_, time, playing_radius_));
  if (time > animationLength(playing_))
    timer_.stop();  // the last frame shows where the balls came to rest
}

}  // namespace billiard_shot_planner

#pragma once

#include <billiard_shot_planner/Animate.h>
#include <billiard_shot_planner/ShotPrediction.h>
#include <ros/ros.h>

#include <functional>
#include <mutex>

#include "cockpit_settings.hpp"

namespace billiard_shot_planner
{
/// Watching a shot play: predictions animated on ~animation (animationFrame() at ANIMATION_FRAME_RATE on a
/// wall-clock timer, from the strike until the last ball stops or drops), in real time or slowed down. Every
/// prediction shown to it is animated when ~cockpit/animate is true; the service ~animate replays the last one, or a
/// given one, at any slow motion.
class ShotAnimator
{
public:
  /// `ball_radius` gives the configuration's radius at the time of a play (it may be tuned at run time).
  ShotAnimator(ros::NodeHandle& private_node, const CockpitSettings& settings, std::function<double()> ball_radius);

  /// A new prediction: remembered for ~animate, and played when the settings say so.
  void show(const ShotPrediction& prediction);

private:
  /// Plays `prediction` at once (replacing one in progress); the wall-clock seconds it takes.
  double play(const ShotPrediction& prediction, double slow_motion);
  bool replay(Animate::Request& request, Animate::Response& response);
  void step();

  CockpitSettings settings_;
  std::function<double()> ball_radius_;
  std::mutex mutex_;  ///< guards what follows against the services' threads and the timer's
  ShotPrediction last_;
  ShotPrediction playing_;
  double playing_radius_ = 0.0;
  double slow_motion_ = 1.0;
  ros::WallTime started_;
  ros::Publisher publisher_;
  ros::WallTimer timer_;
  ros::ServiceServer service_;
};

/// Frames per second of an animation.
constexpr double ANIMATION_FRAME_RATE = 30.0;

}  // namespace billiard_shot_planner

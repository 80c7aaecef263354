#pragma once

#include <billiard_shot_planner/ShotPrediction.h>
#include <visualization_msgs/MarkerArray.h>

#include "billiard_shot_planner/core/expected.hpp"

namespace billiard_shot_planner
{
/// s: how long a pocketed ball is seen falling below the cloth before it vanishes.
constexpr double DROP_DURATION = 0.25;

/// The balls of `prediction` at `time` s after the strike, in its frame: a DELETEALL first, then one sphere per ball
/// still on the table (namespace "animation", id = its index in prediction.balls; the cue ball white, the others
/// orange), each at its path's position interpolated linearly between the samples. A pocketed ball falls from the
/// end of its path under gravity for DROP_DURATION and is then left out; a ball of an empty path is left out. Pure
/// function: testable without a ROS master.
visualization_msgs::MarkerArray animationFrame(const ShotPrediction& prediction, double time, double ball_radius);

/// s: the longest prediction ~animate plays (a shot on a table is over in well under a minute).
constexpr double MAX_ANIMATION_LENGTH = 600.0;

/// A prediction that can be animated: every path's times finite and in order, its positions finite, no longer than
/// MAX_ANIMATION_LENGTH. Errors name the field ("prediction.balls[1].path").
Status checkAnimation(const ShotPrediction& prediction);

/// s after the strike when nothing more moves in the animation: the longest path, and a pocketed ball's fall.
double animationLength(const ShotPrediction& prediction);

}  // namespace billiard_shot_planner

#pragma once

// The core names a prediction's input by its place in the call ("cue.tip", "cue.ball", "others[2].position"); a
// request names it by the service's fields. The translation lives here, at the ROS boundary.
#include <cstddef>
#include <optional>
#include <vector>

#include "billiard_shot_planner/core/expected.hpp"

namespace billiard_shot_planner
{
/// Where the balls given to a prediction came from in the request's table.
struct BallOrigins
{
  std::vector<std::size_t> others;      ///< the index in table.balls of the core's others[k]
  std::optional<std::size_t> cue_ball;  ///< the cue ball's index in table.balls; none: the request's ball_position
};

/// A core error of a prediction in the request's names (PredictShot.srv, RecordShot.srv): the cue's fields as the cue
/// pose and speed ("cue.tip" → "cue_pose.position"), the cue ball as ball_position or its entry in the table, the
/// other balls as their entries ("others[0].position" → "table.balls[1].position"), a configuration's field as its
/// parameter ("table/cloth/friction").
Error inRequestTerms(Error error, const BallOrigins& origins);

}  // namespace billiard_shot_planner

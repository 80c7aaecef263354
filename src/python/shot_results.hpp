#pragma once

#include <string>
#include <vector>

#include "billiard_shot_planner/shot/shot_prediction.hpp"

namespace billiard_shot_planner::python
{
/// One ball's path in a shot (Python's BallPath).
struct BallPath
{
  std::string id;
  BallTrajectory trajectory;
};

/// A whole shot: the strike and every ball's path, the cue ball first (Python's Shot).
struct Shot
{
  CueStrikeResult strike;
  Eigen::Vector3d hit_point;
  std::vector<BallPath> balls;
  std::string first_contact;
};

/// The core's outcome as Python's Shot.
inline Shot shotOf(const ShotOutcome& outcome)
{
  Shot shot{outcome.strike, outcome.hit_point, {}, firstContact(outcome.table)};
  for (std::size_t i = 0; i < outcome.table.balls.size(); ++i)
    shot.balls.push_back({outcome.table.ids[i], outcome.table.balls[i]});
  return shot;
}

}  // namespace billiard_shot_planner::python

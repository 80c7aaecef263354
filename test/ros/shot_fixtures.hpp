#pragma once

// Shots shared by the ROS tests: the paper's massé shot and a follow shot, as core placements (table frame).
#include <Eigen/Core>

#include "billiard_shot_planner/shot/shot_prediction.hpp"

namespace shot_fixtures
{
inline billiard_shot_planner::CuePlacement masse()
{
  billiard_shot_planner::CuePlacement cue;
  const Eigen::Vector3d centre(0.6, 0.1, 0.0286);
  cue.direction = Eigen::Vector3d(-0.2761, -0.1388, -0.9511).normalized();
  cue.tip = centre + 0.0286 * Eigen::Vector3d(0.480151, -0.102889, 0.871131).normalized();
  cue.speed = 3.089095;
  cue.ball = centre.head<2>();
  return cue;
}

/// The configuration of the paper's massé (§9.2): its shooter held the tip on the cue's axis, with its fitted tip.
inline billiard_shot_planner::ShotConfiguration paperShooter()
{
  billiard_shot_planner::ShotConfiguration configuration;
  configuration.cue_end_mass = billiard_shot_planner::CUE_HELD_ON_AXIS;
  configuration.cue_contact.eta2 = 7.0;
  return configuration;
}

inline billiard_shot_planner::CuePlacement follow()
{
  billiard_shot_planner::CuePlacement cue;
  const Eigen::Vector3d centre(-0.6, -0.2, 0.0286);
  cue.direction = Eigen::Vector3d(std::cos(0.087), 0.0, -std::sin(0.087));
  cue.tip = centre + Eigen::Vector3d(0, 0, 0.008) - 0.05 * cue.direction;
  cue.speed = 2.0;
  cue.ball = centre.head<2>();
  return cue;
}

}  // namespace shot_fixtures

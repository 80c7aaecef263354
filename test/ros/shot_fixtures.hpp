#pragma once

// Shots shared by the ROS tests: the paper's massé shot and a follow shot, as core placements (table frame), and
// a placement as the service's request.
#include <billiard_shot_planner/PredictShot.h>
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>

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

/// The follow shot's cue ball frozen to a ball "one" straight ahead of it, predicted: a strike of three bodies.
inline billiard_shot_planner::ShotOutcome frozenFollow(const billiard_shot_planner::ShotConfiguration& configuration)
{
  const billiard_shot_planner::CuePlacement cue = follow();
  billiard_shot_planner::TableBall one{"one", {}};
  one.state.position << cue.ball.x() + 2.0 * configuration.ball_radius, cue.ball.y(), configuration.ball_radius;
  const auto outcome = billiard_shot_planner::predictShot(cue, configuration, {one});
  EXPECT_TRUE(outcome.ok()) << outcome.error().describe();
  return outcome.ok() ? outcome.value() : billiard_shot_planner::ShotOutcome{};
}

/// A placement as the service's request (both in `frame`, stamp 0: the latest transform).
inline billiard_shot_planner::PredictShot::Request toRequest(const billiard_shot_planner::CuePlacement& cue,
                                                             const std::string& frame = "table")
{
  billiard_shot_planner::PredictShot::Request r;
  r.cue_pose.header.frame_id = frame;
  r.cue_pose.pose.position.x = cue.tip.x();
  r.cue_pose.pose.position.y = cue.tip.y();
  r.cue_pose.pose.position.z = cue.tip.z();
  const Eigen::Quaterniond q = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitX(), cue.direction);
  r.cue_pose.pose.orientation.x = q.x();
  r.cue_pose.pose.orientation.y = q.y();
  r.cue_pose.pose.orientation.z = q.z();
  r.cue_pose.pose.orientation.w = q.w();
  r.cue_speed = cue.speed;
  r.ball_position.header.frame_id = frame;
  r.ball_position.point.x = cue.ball.x();
  r.ball_position.point.y = cue.ball.y();
  r.ball_position.point.z = 0.0286;
  return r;
}

}  // namespace shot_fixtures

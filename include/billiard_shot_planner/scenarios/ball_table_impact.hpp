#pragma once

#include <Eigen/Core>

#include "billiard_shot_planner/core/expected.hpp"
#include "billiard_shot_planner/impact/impact_result.hpp"
#include "billiard_shot_planner/impact/solver_options.hpp"
#include "billiard_shot_planner/scenarios/sphere_kinematics.hpp"

namespace billiard_shot_planner
{
/// A solid ball (inertia 2/5 m r²) hitting the fixed table plane z = 0 with one compliant contact: a landing after
/// a jump, and the single-contact cases of docs/validation.md, One compliant contact. Table frame, z up.
struct BallTableImpact
{
  double mass = 1.0;
  double radius = 1.0;
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  ///< v_z < 0 (falling)
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();
  SurfaceContact table;
};

struct BallTableImpactResult
{
  Eigen::Vector3d velocity;
  Eigen::Vector3d angular_velocity;
  Eigen::Vector3d impulse;  ///< on the ball at the contact, table frame
  ImpactResult impact;      ///< the engine's full result (events, samples)
};

Expected<BallTableImpactResult> solve(const BallTableImpact& impact, const SolverOptions& options = {});

}  // namespace billiard_shot_planner

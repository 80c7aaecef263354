#pragma once

#include <Eigen/Core>

#include "billiard_shot_planner/core/expected.hpp"
#include "billiard_shot_planner/impact/impact_result.hpp"
#include "billiard_shot_planner/impact/solver_options.hpp"
#include "billiard_shot_planner/scenarios/sphere_kinematics.hpp"

namespace billiard_shot_planner
{
/// A ball striking a cushion nose. On the cloth this is a multiple impact of two compliant contacts at once —
/// ball–cushion and ball–cloth — solved by the same engine as the cue strike; in flight only the cushion contact
/// acts. Table frame, z up.
struct CushionImpact
{
  double mass = 0.17;
  double radius = 0.0286;
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d cushion_normal = Eigen::Vector3d::UnitX();  ///< from the cushion towards the ball's centre
  bool on_cloth = true;
  SurfaceContact cushion;
  SurfaceContact cloth;
  double stiffness_ratio = 1.0;  ///< k_cushion / k_cloth
};

struct CushionImpactResult
{
  Eigen::Vector3d velocity;
  Eigen::Vector3d angular_velocity;
  ImpactResult impact;  ///< contact 0: ball–cushion, contact 1 (on the cloth): ball–cloth
};

Expected<CushionImpactResult> solve(const CushionImpact& impact, const SolverOptions& options = {});

}  // namespace billiard_shot_planner

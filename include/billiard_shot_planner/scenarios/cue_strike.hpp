#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "billiard_shot_planner/core/expected.hpp"
#include "billiard_shot_planner/impact/impact_problem.hpp"
#include "billiard_shot_planner/impact/impact_result.hpp"
#include "billiard_shot_planner/impact/solver_options.hpp"
#include "billiard_shot_planner/scenarios/sphere_kinematics.hpp"

namespace billiard_shot_planner
{
/// The integrated billiard shot (paper §8): the cue strikes the ball at rest on the table, and the cue–ball and
/// ball–table impacts happen at once, each compliant with friction. Table frame, z up, SI units.
///
/// The cue is a body of mass cue_mass constrained to move along its axis ĉ (eq. 48). Contact p (cue–ball) has the
/// ball's outward normal n̂ at the hit point; contact q (ball–table) has normal ẑ.
struct CueStrike
{
  double cue_mass = 0.5;
  Eigen::Vector3d cue_direction = -Eigen::Vector3d::UnitZ();  ///< ĉ, the cue's direction of motion (normalised)
  double cue_speed = 1.0;                                     ///< m/s, > 0
  double ball_mass = 0.17;
  double ball_radius = 0.0286;
  Eigen::Vector3d hit_normal = Eigen::Vector3d::UnitZ();  ///< n̂ at the hit point (normalised); see hitNormal()
  SurfaceContact cue_contact;                             ///< e, μ, η² of the cue tip on the ball
  SurfaceContact table_contact;                           ///< e, μ, η² of the ball on the cloth
  double stiffness_ratio = 1.0;                           ///< k_table / k_cue
};

/// The massé shot of the paper's §9.2 with the errata's ball (m = 0.17 kg, r = 0.0286 m; see README) and the
/// printed cue speed; `cue_direction` defaults to the literal reading of the text.
CueStrike paperMasseStrike(const Eigen::Vector3d& cue_direction = Eigen::Vector3d(-0.2761, -0.1388, -0.9511));

/// The hit normal where the cue axis (through `axis_point`, along `direction`) first meets the ball: ray–sphere
/// intersection. Errors (InvalidShot) when the axis misses the ball or the ball is behind the cue.
Expected<Eigen::Vector3d> hitNormal(const Eigen::Vector3d& axis_point, const Eigen::Vector3d& direction,
                                    const Eigen::Vector3d& ball_centre, double ball_radius);

struct CueStrikeResult
{
  Eigen::Vector3d velocity;          ///< ball, m/s
  Eigen::Vector3d angular_velocity;  ///< ball, rad/s
  double cue_velocity = 0.0;         ///< cue after the shot, along ĉ
  Eigen::Vector3d impulse_cue;       ///< impulse on the cue at the hit point (N·s)
  Eigen::Vector3d impulse_table;     ///< impulse on the ball at the table contact (N·s)
  Eigen::Vector3d hit_normal;        ///< n̂ used (normalised)
  Eigen::Vector3d cue_direction;     ///< ĉ used (normalised)
  std::vector<std::string> states;   ///< S1 (both), S2 (ball–table only), S3 (cue–ball only), S4 (end)
  /// The tip slipped on the ball from the first instant (|v_t| > μη²|v_n|): a miscue warning.
  bool miscue = false;
  ImpactResult impact;  ///< the engine's full result: contact 0 is cue–ball, contact 1 is ball–table
};

/// The engine's configuration for this strike: generalised velocity (v_c, v, ω), contact 0 cue–ball, contact 1
/// ball–table. Errors as solve().
Expected<ImpactProblem> makeImpactProblem(const CueStrike& strike);

/// Solves the strike with the multiple-impact engine. Errors: InvalidArgument (a field, named), InvalidShot
/// (n̂·ĉ ≥ 0: the cue does not approach; the hit point below the equator, or on it with ĉ·ẑ ≥ 0, which the model
/// of §8 does not cover).
Expected<CueStrikeResult> solve(const CueStrike& strike, const SolverOptions& options = {});

}  // namespace billiard_shot_planner

#pragma once

#include <cstddef>

#include "billiard_shot_planner/core/expected.hpp"
#include "billiard_shot_planner/impact/impact_problem.hpp"
#include "billiard_shot_planner/impact/solver_options.hpp"
#include "billiard_shot_planner/scenarios/ball_collision.hpp"
#include "billiard_shot_planner/scenarios/cue_strike.hpp"

namespace billiard_shot_planner
{
/// The cue strike of a ball that touches other balls or a cushion — a frozen cue ball, a ball in a cluster, a ball
/// frozen to a rail — as ONE multiple impact (docs/cue_strike.md, Frozen balls): the cue's contact, every ball–ball
/// contact, every ball's cloth contact and every cushion contact act together, so the cue still pushes while the
/// balls meet. Table frame, z up, SI units.
///
/// Stiffnesses: the cue's contact is the unit; the cloth is strike.stiffness_ratio (k_cloth/k_cue), a ball–ball
/// contact strike.stiffness_ratio / bodies.stiffness_ratio (k_cloth/k_cue over k_cloth/k_ball_ball), a cushion
/// strike.stiffness_ratio · bodies.cushion_stiffness_ratio.
struct ClusterStrike
{
  /// The cue and the struck ball. Its ball_mass, ball_radius and table_contact are every ball's: the bodies' own
  /// ball_mass, ball_radius and cloth are not read.
  CueStrike strike;
  /// The balls (the struck one among them), the cushions they touch, the ball–ball law and the stiffness ratios
  /// k_cloth/k_ball_ball and k_cushion/k_cloth. The balls may move as the strike begins (their velocities are
  /// taken as given).
  BallCollision bodies;
  std::size_t struck = 0;  ///< index into bodies.balls
};

/// The engine's configuration: generalised velocity (tip, ball 0 (v, ω), ball 1 (v, ω), …), the tip's coordinates
/// as CueStrike's; contact 0 the cue's ("tip-" and the struck ball's name), then the bodies' contacts in
/// makeImpactProblem(BallCollision)'s order (pairs, cloth contacts, cushions). Errors: the strike's, the bodies'
/// (named as in BallCollision: "balls[2].position"), "struck" naming no ball.
Expected<ImpactProblem> makeImpactProblem(const ClusterStrike& strike);

/// Solves the strike. The answer is the struck ball's and the cue's as CueStrikeResult reports a lone strike
/// (impulse_table: the struck ball's cloth contact), with `contacts` naming every contact, `states` by the names of
/// their active contacts, `other_balls` every other ball of `bodies` and `touching_balls` every touching pair
/// (indices into bodies.balls).
Expected<CueStrikeResult> solve(const ClusterStrike& strike, const SolverOptions& options = {});

}  // namespace billiard_shot_planner

#pragma once

#include <vector>

#include "billiard_shot_planner/core/expected.hpp"
#include "billiard_shot_planner/impact/solver_options.hpp"
#include "billiard_shot_planner/motion/table.hpp"
#include "billiard_shot_planner/motion/table_simulation.hpp"
#include "billiard_shot_planner/scenarios/cluster_strike.hpp"
#include "billiard_shot_planner/scenarios/cue_strike.hpp"

namespace billiard_shot_planner
{
/// What a cue strike on a ball of the table meets at once (docs/cue_strike.md, Frozen balls): the struck ball, every
/// ball that touches it directly or through others, and the cushions those balls touch, all within TOUCHING_GAP.
struct StrikeBodies
{
  BallCollision bodies;  ///< the balls named by their ids, the cushions as "cushion<k>" (MotionEvent::cushion)
  std::vector<std::size_t> members;  ///< bodies.balls[k] is balls[members[k]]; the struck ball first

  bool lone() const { return members.size() == 1 && bodies.cushions.empty(); }
};

/// The bodies of a strike on balls[struck]. The balls must be valid (validateTableBalls).
StrikeBodies strikeBodies(const std::vector<TableBall>& balls, std::size_t struck, const BallProperties& ball,
                          const Table& table, const BallContactSettings& contact);

/// The strike of balls[struck] where it lies on the table: solve(CueStrike) for a ball that touches no ball and no
/// cushion (the lone strike, exactly), else one ClusterStrike with every body it touches. The strike's ball mass,
/// radius and cloth are every ball's; `other_balls` index into `balls`. Errors: the balls' (validateTableBalls), the
/// strike's, the engine's.
Expected<CueStrikeResult> strikeOnTable(const CueStrike& strike, const std::vector<TableBall>& balls,
                                        std::size_t struck, const Table& table, const BallContactSettings& contact,
                                        const SolverOptions& options = {});

/// The balls as the strike leaves them: the struck ball's and every other struck ball's velocity and spin.
std::vector<TableBall> ballsAfterStrike(std::vector<TableBall> balls, std::size_t struck,
                                        const CueStrikeResult& strike);

/// Records a strike that moved other balls in a simulated table (a strike that met no ball records nothing): one ball
/// impact at t = 0 with every ball it moved, and in each of their trajectories a ball_collision event at t = 0, right
/// after the start, naming a ball it touched — so that firstContact() and the impact records count the strike's
/// meetings. `struck` and the strike's indices number the balls as the trajectory does.
void recordStrike(TableTrajectory& trajectory, std::size_t struck, const CueStrikeResult& strike);

}  // namespace billiard_shot_planner

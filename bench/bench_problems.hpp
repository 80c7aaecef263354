#pragma once

// Problems, settings and reference solutions shared by the benchmark programs (no Google Benchmark: the service
// round trip and the instruction counts use them too).
#include <Eigen/Core>
#include <cmath>
#include <cstddef>

#include "billiard_shot_planner/impact/impact_result.hpp"
#include "billiard_shot_planner/impact/solver_options.hpp"
#include "billiard_shot_planner/motion/ball_motion.hpp"
#include "billiard_shot_planner/motion/table.hpp"
#include "billiard_shot_planner/scenarios/ball_ball_table.hpp"
#include "billiard_shot_planner/scenarios/ball_chain.hpp"
#include "billiard_shot_planner/scenarios/ball_table_impact.hpp"
#include "billiard_shot_planner/scenarios/cue_strike.hpp"
#include "billiard_shot_planner/scenarios/cushion_impact.hpp"
#include "billiard_shot_planner/shot/shot_prediction.hpp"

namespace bench
{
namespace bsp = billiard_shot_planner;

/// The paper's ball–ball–table collisions (§6.3): m1 = 1, m2 = 2/√3, k2/k1 = 1, v0 = −1.
inline bsp::BallBallTable paperCollision(double e1, double e2)
{
  return {1.0, 2.0 / std::sqrt(3.0), 1.0, e1, e2, -1.0};
}

inline bsp::BallBallTable table1()
{
  return paperCollision(0.9, 0.7);
}

inline bsp::BallBallTable figure7()
{
  return paperCollision(1.0, 1.0);
}

/// Unit masses and linear unit contacts, all elastic; the first ball moves at 1 m/s into the others at rest.
inline bsp::BallChain elasticChain(std::size_t balls)
{
  bsp::BallChain chain;
  chain.masses.assign(balls, 1.0);
  chain.velocities.assign(balls, 0.0);
  chain.velocities[0] = 1.0;
  chain.stiffness.assign(balls - 1, 1.0);
  chain.restitution.assign(balls - 1, 1.0);
  return chain;
}

inline bsp::SolverOptions withTolerance(double relative)
{
  bsp::SolverOptions options;
  options.relative_tolerance = relative;
  options.absolute_tolerance = relative * 1e-2;
  return options;
}

/// Every state integrated numerically (the closed form of sticking and frictionless states off).
inline bsp::SolverOptions integratedOnly(double relative)
{
  bsp::SolverOptions options = withTolerance(relative);
  options.closed_form_linear_phases = false;
  return options;
}

/// The integrator alone in plain time: no closed form, no separation clock, every slip direction integrated from
/// its start. The baseline those devices are measured against, and the reference that checks them.
inline bsp::SolverOptions plainIntegration(double relative)
{
  bsp::SolverOptions options = integratedOnly(relative);
  options.separation_clock = false;
  options.quasi_steady_slip = false;
  return options;
}

inline const bsp::ImpactResult& impactOf(const bsp::ImpactResult& result)
{
  return result;
}

inline const bsp::ImpactResult& impactOf(const bsp::CueStrikeResult& result)
{
  return result.impact;
}

inline const bsp::ImpactResult& impactOf(const bsp::BallTableImpactResult& result)
{
  return result.impact;
}

inline const bsp::ImpactResult& impactOf(const bsp::CushionImpactResult& result)
{
  return result.impact;
}

/// The ball of the massé shot landing after its jump, sliding and spinning, on the default cloth: one contact
/// that slides from its first instant to its last in a fixed direction.
inline bsp::BallTableImpact masseLanding()
{
  return {0.17, 0.0286, {-2.07, 0.24, -0.4}, {11.6, 25.3, -6.15}, bsp::Table{}.cloth};
}

/// A ball sliding on the cloth into a cushion nose at 9-ft table height (normal tilted 15.6° down): cushion and
/// cloth at once, the cloth contact sliding from zero load, its direction turning.
inline bsp::CushionImpact cushionHit()
{
  bsp::CushionImpact hit;
  hit.velocity = {1.5, 0.8, 0.0};
  hit.cushion_normal = {-0.963, 0.0, -0.269};
  hit.cushion_normal.normalize();
  hit.cushion = bsp::Table{}.cushion;
  hit.cloth = bsp::Table{}.cloth;
  return hit;
}

/// A sliding ball on a 9-ft table without pockets that hits three cushions (hopping after each) before it stops.
struct ThreeCushionShot
{
  bsp::BallState start;
  bsp::Table table;
};

inline ThreeCushionShot threeCushionShot()
{
  ThreeCushionShot shot;
  shot.table.pockets.clear();
  shot.start.position = {-0.5, -0.2, 0.0286};
  shot.start.velocity = {3.5, 1.2, 0.0};
  return shot;
}

/// The paper's massé shot (bsp::paperMasseStrike) as the service round trip asks for it (table frame): the cue tip
/// on the ball at the strike's hit normal, moving along its cue direction at its speed.
inline bsp::CuePlacement serviceMasseShot()
{
  const bsp::CueStrike strike = bsp::paperMasseStrike();
  const Eigen::Vector3d centre(0.6, 0.1, strike.ball_radius);
  bsp::CuePlacement cue;
  cue.tip = centre + strike.ball_radius * strike.hit_normal.normalized();
  cue.direction = strike.cue_direction.normalized();
  cue.speed = strike.cue_speed;
  cue.ball = centre.head<2>();
  return cue;
}

/// The converged solution errors are measured against: numerical integration alone in plain time at tolerance
/// 1e-14, independent of the closed form, the separation clock and the quasi-steady slip (and, for the paper's
/// collisions, equal to the independent converged values of docs/validation.md to 1e-7).
template <class Problem>
Eigen::VectorXd referenceVelocities(const Problem& problem)
{
  return impactOf(bsp::solve(problem, plainIntegration(1e-14)).value()).velocity;
}

/// Largest difference of the generalised velocities after the impact from the reference.
template <class Problem>
double velocityError(const Problem& problem, const bsp::SolverOptions& options)
{
  return (impactOf(bsp::solve(problem, options).value()).velocity - referenceVelocities(problem)).cwiseAbs().maxCoeff();
}

}  // namespace bench

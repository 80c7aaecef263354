#pragma once

#include <Eigen/Core>
#include <cmath>
#include <string>
#include <vector>

#include "billiard_shot_planner/core/expected.hpp"
#include "billiard_shot_planner/impact/impact_problem.hpp"
#include "billiard_shot_planner/impact/impact_result.hpp"
#include "billiard_shot_planner/impact/solver_options.hpp"
#include "billiard_shot_planner/scenarios/sphere_kinematics.hpp"

namespace billiard_shot_planner
{
/// The gap (m) within which two bodies touch — two balls, or a ball and a cushion's nose — for every impact: the
/// strike, the balls' collisions and the motion's events (docs/impact_model.md, Touching bodies). A touching ball
/// takes part in the impact that reaches its neighbour; a ball farther away is met later, by its own event.
constexpr double TOUCHING_GAP = 1e-9;

/// A ball as it enters a collision: on the cloth (its centre at height R), or above it (a hop) at `height`.
struct CollidingBall
{
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  ///< centre in the cloth's plane, m
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();
  /// m, ≥ 0: the centre's height above R. A ball higher than the touching tolerance is in the air: it has no cloth
  /// contact in the impact.
  double height = 0.0;
  /// The name its contacts carry ("one-cloth", "cue-one"); empty: "ball" and its index ("ball2-cloth").
  std::string id{};
};

/// A ball that touches a cushion nose as the impact starts: the cushion is one more contact of the same impact (a
/// ball frozen to a rail and hit, a ball driven into the rail by a cluster). The cushion is fixed.
struct CushionTouch
{
  std::size_t ball = 0;                               ///< index into BallCollision::balls
  Eigen::Vector3d normal = Eigen::Vector3d::UnitX();  ///< from the nose to the ball's centre (normalised here)
  std::string id = "cushion";                         ///< the name its contact carries ("ball0-cushion")
};

/// How the ball–ball friction coefficient of each touching pair is chosen.
enum class BallBallFriction
{
  Constant,   ///< SurfaceContact::friction of `ball_ball`
  Alciatore,  ///< alciatoreFriction(slip speed at the contact when the impact starts)
};

/// Alciatore's fit of ball–ball friction to measured throw (TP A-14, also pooltool's "alciatore" model):
/// μ = a + b·exp(−c·v), v the relative surface speed at the contact in m/s; 0.118 for a pair that does not slip,
/// 0.046 at 1 m/s, 0.014 at 3 m/s.
inline double alciatoreFriction(double slip_speed)
{
  constexpr double a = 9.951e-3, b = 0.108, c = 1.088;
  return a + b * std::exp(-c * slip_speed);
}

/// N ≥ 2 equal balls on the cloth, some of them touching, as ONE multiple impact (docs/impact_model.md, Ball
/// collisions). Every pair whose centres are within 2R + touching_tolerance is a compliant ball–ball contact,
/// every ball has its ball–cloth contact; the engine decides which resting contacts the impact presses. A pair
/// hit by a moving ball, a frozen pair, a row of touching balls and a racked pack are each one impact.
/// Table frame, z up, SI units.
struct BallCollision
{
  std::vector<CollidingBall> balls;
  double ball_mass = 0.17;      ///< kg (as config/default.yaml)
  double ball_radius = 0.0286;  ///< m (as config/default.yaml)
  /// Phenolic on phenolic: e = 0.95, within the 0.92–0.98 of Alciatore's table of ball properties and pooltool's
  /// e_b; μ = 0.05, pooltool's u_b (used with BallBallFriction::Constant); η̄² = (2 − ν)/(2(1 − ν)) = 1.21 for two
  /// like elastic spheres at ν = 0.3 (Mindlin's ratio of normal to tangential contact stiffness).
  SurfaceContact ball_ball{0.95, 0.05, 1.2};
  BallBallFriction friction_model = BallBallFriction::Alciatore;
  SurfaceContact cloth{0.51625, 0.152479, 10.0};  ///< the paper's §9.2 cloth, as config/default.yaml
  /// k_cloth / k_ball_ball: the cloth is much softer than two phenolic balls. Two balls touch for 0.3–0.4 ms (Hertz,
  /// E ≈ 5 GPa, ν ≈ 0.3, at 1–3 m/s), the tip and the ball for 1–2 ms (Alciatore's high-speed videos), and the paper
  /// fits k_table/k_cue = 0.8. Linear springs with those durations and reduced masses (m/2 ball–ball, 0.75 m
  /// tip–ball) give k_cloth/k_ball_ball = 0.8 · 1.5 (T_bb/T_tip)² ≈ 0.03–0.2. Only impacts that press a ball into
  /// the cloth depend on it (follow, draw, jumps), and weakly (test_ball_collision.cpp,
  /// StiffnessRatioMattersOnlyThroughTheCloth).
  double stiffness_ratio = 0.1;
  /// The cushions the balls touch, and their contact law (defaults: those of motion/table.hpp's Table).
  std::vector<CushionTouch> cushions;
  SurfaceContact cushion{0.85, 0.2, 10.0};
  double cushion_stiffness_ratio = 1.0;  ///< k_cushion / k_cloth
  /// Centres within 2R + this are touching, m; closer than 2R − this is an overlap and refused. TOUCHING_GAP, as
  /// the strike and the table's motion use it (docs/impact_model.md, Touching bodies).
  double touching_tolerance = TOUCHING_GAP;
};

/// Two touching balls: contact k of the impact joins balls `b` (B) and `a` (A) of pairs[k], b < a, with its normal
/// from b's centre to a's.
struct TouchingPair
{
  std::size_t b = 0;
  std::size_t a = 0;
  double friction = 0.0;  ///< the pair's μ, as the friction model chose it
};

struct CollidedBall
{
  Eigen::Vector3d velocity;
  Eigen::Vector3d angular_velocity;
};

struct BallCollisionResult
{
  std::vector<CollidedBall> balls;  ///< right after the impact
  /// Contacts 0 … pairs.size() − 1 join the pairs; the cloth contacts of the balls on the cloth follow, then the
  /// cushion contacts in the order of BallCollision::cushions.
  std::vector<TouchingPair> pairs;
  std::vector<std::string> contact_names;  ///< "ball0-ball1", "ball1-cloth"
  ImpactResult impact;
  /// The contact of each ball on the cloth; NO_CLOTH_CONTACT for a ball in the air.
  std::vector<std::size_t> cloth_contacts;
  static constexpr std::size_t NO_CLOTH_CONTACT = static_cast<std::size_t>(-1);

  std::size_t clothContact(std::size_t ball) const { return cloth_contacts[ball]; }
  /// The contact of BallCollision::cushions[k].
  std::size_t cushionContact(std::size_t k) const { return pairs.size() + clothContactCount() + k; }
  std::size_t clothContactCount() const
  {
    std::size_t count = 0;
    for (std::size_t contact : cloth_contacts)
      count += contact != NO_CLOTH_CONTACT;
    return count;
  }
};

/// The name ball i's contacts carry: its id, or "ball" and its index.
std::string ballName(const BallCollision& collision, std::size_t i);

/// Checks the fields (the error names one: "balls[3].position", "ball_ball.eta2"), refusing fewer than two balls
/// and overlaps beyond the tolerance.
Status validate(const BallCollision& collision);

/// The touching pairs with their friction coefficients, in the order of their contacts.
std::vector<TouchingPair> touchingPairs(const BallCollision& collision);

/// The engine's configuration: 6 coordinates (v, ω) per ball, the pairs' contacts, then the cloth contacts of the
/// balls on the cloth, then the cushion contacts.
/// Fails with NoApproachingContact (field "balls") when no two balls touch, or when nothing approaches (a touching
/// cushion alone is no ball collision: the ball's own motion meets it).
Expected<ImpactProblem> makeImpactProblem(const BallCollision& collision);

/// The bodies of a collision and their contacts, in makeImpactProblem's order and with stiffnesses relative to the
/// ball–ball contact's, whether or not anything approaches or any two balls touch: part of a larger impact (the cue
/// strike of a ball that touches others, scenarios/cluster_strike.hpp).
struct BallCollisionBodies
{
  ImpactProblem problem;
  std::vector<TouchingPair> pairs;
  std::vector<std::size_t> cloth_contacts;  ///< as BallCollisionResult::cloth_contacts
};

/// Errors as validate().
Expected<BallCollisionBodies> collisionBodies(const BallCollision& collision);

Expected<BallCollisionResult> solve(const BallCollision& collision, const SolverOptions& options = {});

}  // namespace billiard_shot_planner

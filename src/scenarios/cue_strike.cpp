#include "billiard_shot_planner/scenarios/cue_strike.hpp"

#include <cmath>

#include "billiard_shot_planner/core/validation.hpp"
#include "billiard_shot_planner/impact/multiple_impact_solver.hpp"
#include "billiard_shot_planner/scenarios/ball_ball_table.hpp"
#include "cue_tip.hpp"

namespace billiard_shot_planner
{
namespace detail
{
namespace
{
/// The one impossibility of a hit that the tip can make: the tip must approach the ball where it touches it.
Status checkApproach(const Eigen::Vector3d& n, const Eigen::Vector3d& c)
{
  if (!(n.dot(c) < 0.0))
    return Error{
        ErrorKind::InvalidShot, "cue_direction",
        "the cue does not approach the ball at the hit point (n.c = " + formatNumber(n.dot(c)) + " must be < 0)"};
  return {};
}

/// Upward speed, relative to the ball's speed, below which the ball is taken to stay on the cloth (round-off).
constexpr double LEAVES_CLOTH_TOLERANCE = 1e-9;
}  // namespace

Status checkStrike(const CueStrike& s)
{
  if (Status status = firstError(
          {requirePositive(s.cue_mass, "cue_mass"), requirePositiveOrInfinite(s.cue_end_mass, "cue_end_mass"),
           requireDirection(s.cue_direction, "cue_direction"), requirePositive(s.cue_speed, "cue_speed"),
           requirePlausibleSpeed(s.cue_speed, "cue_speed"), requirePositive(s.ball_mass, "ball_mass"),
           requirePositive(s.ball_radius, "ball_radius"), requireDirection(s.hit_normal, "hit_normal"),
           validate(s.cue_contact, "cue_contact"), validate(s.table_contact, "table_contact"),
           requireStiffnessRatio(s.stiffness_ratio, "stiffness_ratio"),
           requireMassRatio(s.cue_mass / s.ball_mass, "cue_mass", "cue_mass/ball_mass"),
           std::isinf(s.cue_end_mass)
               ? Status{}
               : requireMassRatio(s.cue_end_mass / s.ball_mass, "cue_end_mass", "cue_end_mass/ball_mass")});
      !status)
    return status;
  return checkApproach(s.hit_normal.normalized(), s.cue_direction.normalized());
}

int tipDofs(const CueStrike& s)
{
  return std::isinf(s.cue_end_mass) ? 1 : 3;
}

Eigen::Matrix3d tipAxes(const Eigen::Vector3d& c)
{
  const Eigen::Matrix3d across = contactFrame(c);
  Eigen::Matrix3d axes;
  axes << c, across.row(0).transpose(), across.row(1).transpose();
  return axes;
}

void setTip(const CueStrike& s, Eigen::MatrixXd& mass_matrix, Eigen::VectorXd& velocity)
{
  mass_matrix(0, 0) = s.cue_mass;
  if (tipDofs(s) == 3)
    mass_matrix.diagonal().segment<2>(1).setConstant(s.cue_end_mass);
  velocity(0) = s.cue_speed;
}

Contact cueContact(const CueStrike& s, const char* name, Eigen::Index ball, Eigen::Index coordinates)
{
  const int tip = tipDofs(s);
  const Eigen::Vector3d n = s.hit_normal.normalized();
  const Eigen::Matrix3d cue_frame = contactFrame(n);
  Eigen::MatrixXd rows = Eigen::MatrixXd::Zero(3, coordinates);
  rows.leftCols(tip) = cue_frame * tipAxes(s.cue_direction.normalized()).leftCols(tip);
  rows.middleCols<6>(ball) = -pointVelocityRows(cue_frame, s.ball_radius * n);
  return makeContact(name, rows, contactLaw(s.cue_contact, 1.0));
}

Eigen::Vector3d worldImpulse(const ContactImpulse& impulse, const Eigen::Matrix3d& frame)
{
  return frame.transpose() * Eigen::Vector3d(impulse.tangential.x(), impulse.tangential.y(), impulse.normal);
}

CueStrikeResult strikeResult(const CueStrike& strike, ImpactResult impact, Eigen::Index ball)
{
  CueStrikeResult result;
  result.impact = std::move(impact);
  const Eigen::VectorXd& u = result.impact.velocity;
  const int tip = tipDofs(strike);
  const Eigen::Vector3d n = strike.hit_normal.normalized();
  const Eigen::Vector3d c = strike.cue_direction.normalized();
  result.cue_velocity = u(0);
  result.tip_velocity = tipAxes(c).leftCols(tip) * u.head(tip);
  result.velocity = u.segment<3>(ball);
  result.angular_velocity = u.segment<3>(ball + 3);
  result.hit_normal = n;
  result.cue_direction = c;
  result.impulse_cue = worldImpulse(result.impact.impulses[0], contactFrame(n));
  result.miscue = result.impact.initially_slipping[0];
  result.leaves_cloth = result.velocity.z() > LEAVES_CLOTH_TOLERANCE * result.velocity.norm();
  return result;
}
}  // namespace detail

namespace
{
/// Generalised velocity (tip, v, ω): the tip along ĉ (and across it), the ball's linear and angular velocity;
/// contact 0 cue–ball, contact 1 ball–table.
ImpactProblem loneBallProblem(const CueStrike& s)
{
  const int tip = detail::tipDofs(s);
  const int dofs = tip + 6;
  const double inertia = 0.4 * s.ball_mass * s.ball_radius * s.ball_radius;
  ImpactProblem problem;
  problem.mass_matrix = Eigen::MatrixXd::Zero(dofs, dofs);
  problem.velocity = Eigen::VectorXd::Zero(dofs);
  detail::setTip(s, problem.mass_matrix, problem.velocity);
  problem.mass_matrix.diagonal().tail<6>() << s.ball_mass, s.ball_mass, s.ball_mass, inertia, inertia, inertia;
  problem.contacts.push_back(detail::cueContact(s, "cue-ball", tip, dofs));

  // Ball–table: A = ball at −r ẑ, B = table, table axes as the contact frame.
  Eigen::MatrixXd table_rows = Eigen::MatrixXd::Zero(3, dofs);
  table_rows.rightCols(6) = clothContactRows(s.ball_radius);
  problem.contacts.push_back(makeContact("ball-table", table_rows, contactLaw(s.table_contact, s.stiffness_ratio)));
  return problem;
}
}  // namespace

Expected<Eigen::Vector3d> hitNormal(const Eigen::Vector3d& axis_point, const Eigen::Vector3d& direction,
                                    const Eigen::Vector3d& ball_centre, double ball_radius)
{
  if (Status status =
          firstError({requireFinite(axis_point, "axis_point"), requireDirection(direction, "direction"),
                      requireFinite(ball_centre, "ball_centre"), requirePositive(ball_radius, "ball_radius")});
      !status)
    return status.error();
  const Eigen::Vector3d c = direction.normalized();
  const Eigen::Vector3d offset = axis_point - ball_centre;
  const double b = c.dot(offset);
  const double discriminant = b * b - (offset.squaredNorm() - ball_radius * ball_radius);
  if (discriminant < 0.0)
    return Error{ErrorKind::InvalidShot, "cue",
                 "the cue axis misses the ball (closest approach " +
                     formatNumber(std::sqrt(offset.squaredNorm() - b * b)) + " m from its centre)"};
  // The tip may touch the ball or be slightly into it from round-off (a hundredth of the radius).
  const double depth = ball_radius - offset.norm();
  if (depth > 0.01 * ball_radius)
    return Error{ErrorKind::InvalidShot, "cue",
                 "the cue tip is inside the ball (" + formatNumber(offset.norm()) + " m from its centre, radius " +
                     formatNumber(ball_radius) + " m)"};
  const double distance = -b - std::sqrt(discriminant);
  if (distance < -0.01 * ball_radius)
    return Error{ErrorKind::InvalidShot, "cue", "the ball is behind the cue tip (the cue points away)"};
  return Eigen::Vector3d((axis_point + distance * c - ball_centre) / ball_radius);
}

Expected<ImpactProblem> makeImpactProblem(const CueStrike& strike)
{
  if (Status status = detail::checkStrike(strike); !status)
    return status.error();
  return loneBallProblem(strike);
}

Expected<CueStrikeResult> solve(const CueStrike& strike, const SolverOptions& options)
{
  auto problem = makeImpactProblem(strike);
  if (!problem)
    return problem.error();
  auto solved = solveMultipleImpact(problem.value(), options);
  if (!solved)
    return solved.error();
  CueStrikeResult result = detail::strikeResult(strike, std::move(solved).value(), detail::tipDofs(strike));
  result.impulse_table = detail::worldImpulse(result.impact.impulses[1], Eigen::Matrix3d::Identity());
  result.states = ballBallTableStates(result.impact);
  result.contacts = {{"cue-ball", result.impulse_cue}, {"ball-table", result.impulse_table}};
  return result;
}

}  // namespace billiard_shot_planner

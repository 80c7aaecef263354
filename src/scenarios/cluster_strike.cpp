#include "billiard_shot_planner/scenarios/cluster_strike.hpp"

#include <algorithm>

#include "billiard_shot_planner/core/validation.hpp"
#include "billiard_shot_planner/impact/multiple_impact_solver.hpp"
#include "cue_tip.hpp"

namespace billiard_shot_planner
{
namespace
{
/// The bodies with the strike's ball and cloth.
BallCollision bodiesOf(const ClusterStrike& c)
{
  BallCollision bodies = c.bodies;
  bodies.ball_mass = c.strike.ball_mass;
  bodies.ball_radius = c.strike.ball_radius;
  bodies.cloth = c.strike.table_contact;
  return bodies;
}

Status check(const ClusterStrike& c)
{
  if (Status status = detail::checkStrike(c.strike); !status)
    return status;
  if (c.struck >= c.bodies.balls.size())
    return invalidArgument("struck", "names no ball: there are " + std::to_string(c.bodies.balls.size()));
  return {};
}

/// The bodies' problem behind the tip's coordinates, its stiffnesses rescaled to the cue contact's unit.
ImpactProblem withTip(const ClusterStrike& c, const BallCollision& bodies, const ImpactProblem& balls)
{
  const Eigen::Index tip = detail::tipDofs(c.strike);
  const Eigen::Index dofs = tip + balls.velocity.size();
  ImpactProblem problem;
  problem.mass_matrix = Eigen::MatrixXd::Zero(dofs, dofs);
  problem.mass_matrix.bottomRightCorner(dofs - tip, dofs - tip) = balls.mass_matrix;
  problem.velocity = Eigen::VectorXd::Zero(dofs);
  problem.velocity.tail(dofs - tip) = balls.velocity;
  detail::setTip(c.strike, problem.mass_matrix, problem.velocity);
  const std::string name = "tip-" + ballName(bodies, c.struck);
  problem.contacts.push_back(
      detail::cueContact(c.strike, name.c_str(), tip + 6 * static_cast<Eigen::Index>(c.struck), dofs));
  // The bodies' stiffnesses are relative to the ball–ball contact's: k_bb/k_cue = (k_cloth/k_cue)/(k_cloth/k_bb).
  const double ball_ball_stiffness = c.strike.stiffness_ratio / bodies.stiffness_ratio;
  for (const Contact& contact : balls.contacts)
  {
    Contact shifted = contact;
    shifted.normal = Eigen::RowVectorXd::Zero(dofs);
    shifted.normal.tail(dofs - tip) = contact.normal;
    shifted.tangent = Eigen::MatrixXd::Zero(2, dofs);
    shifted.tangent.rightCols(dofs - tip) = contact.tangent;
    shifted.law.stiffness *= ball_ball_stiffness;
    problem.contacts.push_back(std::move(shifted));
  }
  return problem;
}

/// The contacts' frames, to report their impulses in world axes: a contact's rows in its frame are frame · (the
/// point velocity's rows), so the frame is recovered from the rows of any body it acts on.
Eigen::Matrix3d frameOf(const Contact& contact, Eigen::Index column)
{
  Eigen::Matrix3d frame;
  frame.topRows<2>() = contact.tangent.middleCols<3>(column);
  frame.row(2) = contact.normal.segment<3>(column);
  return frame;
}

std::string stateName(const std::vector<std::size_t>& active, const std::vector<StrikeContact>& contacts)
{
  if (active.empty())
    return "end";
  std::string name;
  for (std::size_t k : active)
    name += (name.empty() ? "" : "+") + contacts[k].name;
  return name;
}

struct Configured
{
  BallCollision bodies;
  BallCollisionBodies balls;
  ImpactProblem problem;
};

Expected<Configured> configure(const ClusterStrike& c)
{
  if (Status status = check(c); !status)
    return status.error();
  BallCollision bodies = bodiesOf(c);
  auto balls = collisionBodies(bodies);
  if (!balls)
    return balls.error();
  ImpactProblem problem = withTip(c, bodies, balls.value().problem);
  return Configured{std::move(bodies), std::move(balls).value(), std::move(problem)};
}

/// The ball whose linear coordinates carry the frame of the bodies' contact k (body A, or a cloth or cushion
/// contact's ball): pairs first, then the cloth contacts, then the cushions.
std::size_t ballOfContact(const Configured& c, std::size_t k)
{
  if (k < c.balls.pairs.size())
    return c.balls.pairs[k].a;
  const auto cloth = std::find(c.balls.cloth_contacts.begin(), c.balls.cloth_contacts.end(), k);
  if (cloth != c.balls.cloth_contacts.end())
    return static_cast<std::size_t>(cloth - c.balls.cloth_contacts.begin());
  const std::size_t first_cushion = c.balls.problem.contacts.size() - c.bodies.cushions.size();
  return c.bodies.cushions[k - first_cushion].ball;
}
}  // namespace

Expected<ImpactProblem> makeImpactProblem(const ClusterStrike& strike)
{
  auto configured = configure(strike);
  if (!configured)
    return configured.error();
  return std::move(configured).value().problem;
}

Expected<CueStrikeResult> solve(const ClusterStrike& strike, const SolverOptions& options)
{
  auto configured = configure(strike);
  if (!configured)
    return configured.error();
  const Configured& c = configured.value();
  auto solved = solveMultipleImpact(c.problem, options);
  if (!solved)
    return solved.error();
  const Eigen::Index tip = detail::tipDofs(strike.strike);
  const auto ball_at = [&](std::size_t i) { return tip + 6 * static_cast<Eigen::Index>(i); };
  CueStrikeResult result = detail::strikeResult(strike.strike, std::move(solved).value(), ball_at(strike.struck));
  const std::size_t cloth = c.balls.cloth_contacts[strike.struck];
  if (cloth != BallCollisionResult::NO_CLOTH_CONTACT)
    result.impulse_table = detail::worldImpulse(result.impact.impulses[cloth + 1], Eigen::Matrix3d::Identity());
  else
    result.impulse_table.setZero();
  result.contacts.push_back({c.problem.contacts[0].name, result.impulse_cue});
  for (std::size_t k = 1; k < c.problem.contacts.size(); ++k)
  {
    const Eigen::Matrix3d frame = frameOf(c.problem.contacts[k], ball_at(ballOfContact(c, k - 1)));
    result.contacts.push_back({c.problem.contacts[k].name, detail::worldImpulse(result.impact.impulses[k], frame)});
  }
  for (const ImpactState& state : result.impact.states)
    result.states.push_back(stateName(state.active, result.contacts));
  for (std::size_t i = 0; i < c.bodies.balls.size(); ++i)
    if (i != strike.struck)
      result.other_balls.push_back(
          {i, result.impact.velocity.segment<3>(ball_at(i)), result.impact.velocity.segment<3>(ball_at(i) + 3)});
  for (const TouchingPair& pair : c.balls.pairs)
    result.touching_balls.push_back({std::min(pair.a, pair.b), std::max(pair.a, pair.b)});
  return result;
}

}  // namespace billiard_shot_planner

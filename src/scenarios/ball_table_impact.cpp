#include "billiard_shot_planner/scenarios/ball_table_impact.hpp"

#include "billiard_shot_planner/core/validation.hpp"
#include "billiard_shot_planner/impact/multiple_impact_solver.hpp"

namespace billiard_shot_planner
{
namespace
{
Status check(const BallTableImpact& b)
{
  return firstError(
      {requirePositive(b.mass, "mass"), requirePositive(b.radius, "radius"), requireFinite(b.velocity, "velocity"),
       requireFinite(b.angular_velocity, "angular_velocity"), requirePlausibleSpeed(b.velocity.norm(), "velocity"),
       requirePlausibleSpeed(b.angular_velocity.norm() * b.radius, "angular_velocity"), validate(b.table, "table")});
}

ImpactProblem makeImpactProblem(const BallTableImpact& b)
{
  ImpactProblem problem = freeBallProblem(b.mass, b.radius, b.velocity, b.angular_velocity);
  // A = ball, B = table.
  problem.contacts.push_back(makeContact("ball-table", clothContactRows(b.radius), contactLaw(b.table, 1.0)));
  return problem;
}
}  // namespace

Expected<BallTableImpactResult> solve(const BallTableImpact& impact, const SolverOptions& options)
{
  if (Status status = check(impact); !status)
    return status.error();
  if (!(impact.velocity.z() < 0.0))
    return Error{ErrorKind::NoApproachingContact, "velocity", "the ball must move down onto the table (v_z < 0)"};
  auto solved = solveMultipleImpact(makeImpactProblem(impact), options);
  if (!solved)
    return solved.error();
  BallTableImpactResult result;
  result.impact = std::move(solved).value();
  result.velocity = result.impact.velocity.head<3>();
  result.angular_velocity = result.impact.velocity.tail<3>();
  const ContactImpulse& impulse = result.impact.impulses.front();
  result.impulse = Eigen::Vector3d(impulse.tangential.x(), impulse.tangential.y(), impulse.normal);
  return result;
}

}  // namespace billiard_shot_planner

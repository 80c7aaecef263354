#include "billiard_shot_planner/scenarios/cushion_impact.hpp"

#include "billiard_shot_planner/impact/multiple_impact_solver.hpp"

namespace billiard_shot_planner
{
Expected<CushionImpactResult> solve(const CushionImpact& c, const SolverOptions& options)
{
  ImpactProblem problem = freeBallProblem(c.mass, c.radius, c.velocity, c.angular_velocity);
  // A = ball, B = cushion: the contact point is at −R n̂ from the centre.
  const Eigen::Vector3d n = c.cushion_normal.normalized();
  problem.contacts.push_back(makeContact("ball-cushion", pointVelocityRows(contactFrame(n), -c.radius * n),
                                         contactLaw(c.cushion, c.stiffness_ratio)));
  if (c.on_cloth)
    problem.contacts.push_back(makeContact("ball-cloth", clothContactRows(c.radius), contactLaw(c.cloth, 1.0)));
  auto solved = solveMultipleImpact(problem, options);
  if (!solved)
    return solved.error();
  CushionImpactResult result;
  result.impact = std::move(solved).value();
  result.velocity = result.impact.velocity.head<3>();
  result.angular_velocity = result.impact.velocity.tail<3>();
  return result;
}

}  // namespace billiard_shot_planner

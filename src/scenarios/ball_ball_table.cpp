#include "billiard_shot_planner/scenarios/ball_ball_table.hpp"

#include <cmath>

#include "billiard_shot_planner/core/validation.hpp"
#include "billiard_shot_planner/impact/multiple_impact_solver.hpp"

namespace billiard_shot_planner
{
namespace
{
Status check(const BallBallTable& c)
{
  if (Status status = firstError(
          {requirePositive(c.m1, "m1"), requirePositive(c.m2, "m2"), requireMassRatio(c.m1 / c.m2, "m2", "m1/m2"),
           requireStiffnessRatio(c.stiffness_ratio, "stiffness_ratio"), requireUnitInterval(c.e1, "e1"),
           requireUnitInterval(c.e2, "e2"), requireFinite(c.v0, "v0")});
      !status)
    return status;
  if (c.v0 >= 0.0)
    return Error{ErrorKind::NoApproachingContact, "v0", "must be < 0 (ball 1 moving down onto ball 2)"};
  return {};
}

Contact frictionless(const char* name, const Eigen::RowVector2d& normal, double restitution, double stiffness)
{
  Contact contact;
  contact.name = name;
  contact.normal = normal;
  contact.law.restitution = restitution;
  contact.law.stiffness = stiffness;
  return contact;
}
}  // namespace

Expected<ImpactProblem> makeImpactProblem(const BallBallTable& c)
{
  if (Status status = check(c); !status)
    return status.error();
  ImpactProblem problem;
  problem.mass_matrix = Eigen::Vector2d(c.m1, c.m2).asDiagonal();
  problem.velocity = Eigen::Vector2d(c.v0, 0.0);
  // Normals point from B to A: up from ball 2 to ball 1, up from the table to ball 2.
  problem.contacts.push_back(frictionless("ball-ball", Eigen::RowVector2d(1.0, -1.0), c.e1, 1.0));
  problem.contacts.push_back(frictionless("ball-table", Eigen::RowVector2d(0.0, 1.0), c.e2, c.stiffness_ratio));
  return problem;
}

std::string ballBallTableStateName(const std::vector<std::size_t>& active)
{
  if (active.size() == 2)
    return "S1";
  if (active.size() == 1)
    return active.front() == 1 ? "S2" : "S3";
  return "S4";
}

std::vector<std::string> ballBallTableStates(const ImpactResult& result)
{
  std::vector<std::string> names;
  for (const ImpactState& state : result.states)
    names.push_back(ballBallTableStateName(state.active));
  return names;
}

Expected<ImpactResult> solve(const BallBallTable& collision, const SolverOptions& options)
{
  auto problem = makeImpactProblem(collision);
  if (!problem)
    return problem.error();
  return solveMultipleImpact(problem.value(), options);
}

}  // namespace billiard_shot_planner

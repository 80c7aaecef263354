#include "billiard_shot_planner/scenarios/ball_chain.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "billiard_shot_planner/core/validation.hpp"
#include "billiard_shot_planner/impact/multiple_impact_solver.hpp"

namespace billiard_shot_planner
{
namespace
{
std::string indexed(const char* field, std::size_t i)
{
  return std::string(field) + "[" + std::to_string(i) + "]";
}

Status checkSizes(const BallChain& chain)
{
  if (chain.masses.empty() || (chain.masses.size() < 2 && !chain.wall))
    return invalidArgument("masses", "a chain needs at least two balls, or one ball and a wall");
  if (chain.velocities.size() != chain.masses.size())
    return invalidArgument("velocities", "must have one entry per ball");
  if (chain.stiffness.size() != chain.contactCount())
    return invalidArgument("stiffness",
                           "must have one entry per contact (" + std::to_string(chain.contactCount()) + ")");
  if (chain.restitution.size() != chain.contactCount())
    return invalidArgument("restitution",
                           "must have one entry per contact (" + std::to_string(chain.contactCount()) + ")");
  return {};
}

Status checkValues(const BallChain& chain)
{
  for (std::size_t i = 0; i < chain.masses.size(); ++i)
  {
    if (!std::isfinite(chain.masses[i]) || chain.masses[i] <= 0.0)
      return invalidArgument(indexed("masses", i), "must be finite and > 0");
    if (!std::isfinite(chain.velocities[i]))
      return invalidArgument(indexed("velocities", i), "must be finite");
  }
  for (std::size_t i = 0; i < chain.contactCount(); ++i)
  {
    if (!std::isfinite(chain.stiffness[i]) || chain.stiffness[i] <= 0.0)
      return invalidArgument(indexed("stiffness", i), "must be finite and > 0");
    if (!std::isfinite(chain.restitution[i]) || chain.restitution[i] < 0.0 || chain.restitution[i] > 1.0)
      return invalidArgument(indexed("restitution", i), "must be in [0, 1]");
  }
  return {};
}

/// Masses within MAX_MASS_RATIO of each other, and every contact's stiffness within [MIN_STIFFNESS_RATIO,
/// MAX_STIFFNESS_RATIO] of the first's, as every other problem states its stiffnesses.
Status checkRatios(const BallChain& chain)
{
  const auto [lightest, heaviest] = std::minmax_element(chain.masses.begin(), chain.masses.end());
  const auto light = static_cast<std::size_t>(lightest - chain.masses.begin());
  const auto heavy = static_cast<std::size_t>(heaviest - chain.masses.begin());
  if (Status status = requireMassRatio(*heaviest / *lightest, indexed("masses", light),
                                       indexed("masses", heavy) + "/" + indexed("masses", light));
      !status)
    return status;
  for (std::size_t i = 1; i < chain.contactCount(); ++i)
    if (Status status = requireStiffnessRatio(chain.stiffness[i] / chain.stiffness[0], indexed("stiffness", i));
        !status)
      return status;
  return {};
}
}  // namespace

Expected<ImpactProblem> makeImpactProblem(const BallChain& chain)
{
  if (Status status = checkSizes(chain); !status)
    return status.error();
  if (Status status = checkValues(chain); !status)
    return status.error();
  if (Status status = checkRatios(chain); !status)
    return status.error();
  const auto balls = static_cast<Eigen::Index>(chain.masses.size());
  ImpactProblem problem;
  problem.mass_matrix = Eigen::Map<const Eigen::VectorXd>(chain.masses.data(), balls).asDiagonal();
  problem.velocity = Eigen::Map<const Eigen::VectorXd>(chain.velocities.data(), balls);
  for (std::size_t i = 0; i < chain.contactCount(); ++i)
  {
    // Normal from ball i (B) to ball i+1 (A); the wall is A, fixed, ahead of the last ball.
    Contact contact;
    contact.normal = Eigen::RowVectorXd::Zero(balls);
    const auto b = static_cast<Eigen::Index>(i);
    contact.normal(b) = -1.0;
    if (b + 1 < balls)
    {
      contact.normal(b + 1) = 1.0;
      contact.name = "ball" + std::to_string(i) + "-ball" + std::to_string(i + 1);
    }
    else
    {
      contact.name = "ball" + std::to_string(i) + "-wall";
    }
    contact.law.stiffness = chain.stiffness[i];
    contact.law.restitution = chain.restitution[i];
    problem.contacts.push_back(contact);
  }
  return problem;
}

Expected<ImpactResult> solve(const BallChain& chain, const SolverOptions& options)
{
  auto problem = makeImpactProblem(chain);
  if (!problem)
    return problem.error();
  return solveMultipleImpact(problem.value(), options);
}

}  // namespace billiard_shot_planner

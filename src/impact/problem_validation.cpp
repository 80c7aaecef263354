#include <Eigen/Eigenvalues>
#include <cmath>
#include <string>

#include "billiard_shot_planner/core/validation.hpp"
#include "billiard_shot_planner/impact/impact_problem.hpp"

namespace billiard_shot_planner
{
namespace
{
template <class Derived>
bool allFinite(const Eigen::MatrixBase<Derived>& m)
{
  return m.size() == 0 || m.allFinite();
}

Status validateMassMatrix(const ImpactProblem& problem)
{
  const Eigen::MatrixXd& mass = problem.mass_matrix;
  if (mass.rows() == 0 || mass.rows() != mass.cols())
    return invalidArgument("mass_matrix", "must be a non-empty square matrix");
  if (!allFinite(mass))
    return invalidArgument("mass_matrix", "contains NaN or infinite entries");
  const double scale = mass.cwiseAbs().maxCoeff();
  if ((mass - mass.transpose()).cwiseAbs().maxCoeff() > 1e-12 * scale)
    return invalidArgument("mass_matrix", "must be symmetric");
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(mass, Eigen::EigenvaluesOnly);
  if (!(eigen.eigenvalues().minCoeff() > 1e-14 * scale))
    return invalidArgument("mass_matrix", "must be positive definite (every mass and inertia > 0)");
  if (problem.velocity.size() != mass.rows())
    return invalidArgument("velocity", "must have as many entries as the mass matrix has rows");
  if (!allFinite(problem.velocity))
    return invalidArgument("velocity", "contains NaN or infinite entries");
  // Finite but huge entries (1e308 m/s) overflow the energy, and every answer derived from it, into infinity.
  if (!std::isfinite(problem.velocity.dot(mass * problem.velocity)))
    return invalidArgument("velocity", "its kinetic energy overflows: the speeds or masses are beyond double range");
  return {};
}

Status validateLaw(const ContactLaw& law, const std::string& field)
{
  if (!std::isfinite(law.restitution) || law.restitution < 0.0 || law.restitution > 1.0)
    return invalidArgument(field + ".restitution", "must be in [0, 1], got " + formatNumber(law.restitution));
  if (!std::isfinite(law.stiffness) || law.stiffness <= 0.0)
    return invalidArgument(field + ".stiffness", "must be finite and > 0, got " + formatNumber(law.stiffness));
  if (!std::isfinite(law.friction) || law.friction < 0.0)
    return invalidArgument(field + ".friction", "must be finite and >= 0, got " + formatNumber(law.friction));
  if (law.friction > 0.0 && (!std::isfinite(law.eta2) || law.eta2 <= 0.0))
    return invalidArgument(field + ".eta2", "must be finite and > 0, got " + formatNumber(law.eta2));
  return validate(law.normal_law, field + ".normal_law");
}

Status validateContact(const Contact& contact, Eigen::Index dofs, const std::string& field)
{
  if (contact.normal.size() != dofs)
    return invalidArgument(field + ".normal", "must have one entry per degree of freedom");
  if (!allFinite(contact.normal))
    return invalidArgument(field + ".normal", "contains NaN or infinite entries");
  if (contact.normal.norm() == 0.0)
    return invalidArgument(field + ".normal", "has zero length");
  if (contact.hasFriction())
  {
    if (contact.tangent.cols() != dofs)
      return invalidArgument(field + ".tangent", "must have one column per degree of freedom");
    if (!allFinite(contact.tangent))
      return invalidArgument(field + ".tangent", "contains NaN or infinite entries");
    if (contact.tangent.rowwise().norm().minCoeff() == 0.0)
      return invalidArgument(field + ".tangent", "has a zero-length row");
  }
  return validateLaw(contact.law, field + ".law");
}
}  // namespace

Status validate(const ImpactProblem& problem)
{
  if (Status status = validateMassMatrix(problem); !status)
    return status;
  if (problem.contacts.empty())
    return invalidArgument("contacts", "at least one contact is needed");
  bool approaching = false;
  for (std::size_t i = 0; i < problem.contacts.size(); ++i)
  {
    const Contact& contact = problem.contacts[i];
    if (Status status = validateContact(contact, problem.mass_matrix.rows(), "contacts[" + std::to_string(i) + "]");
        !status)
      return status;
    approaching = approaching || contact.normal.dot(problem.velocity) < 0.0;
  }
  if (!approaching)
    return Error{ErrorKind::NoApproachingContact, "velocity",
                 "no contact is approaching (every normal velocity is >= 0): there is no impact"};
  return {};
}

}  // namespace billiard_shot_planner

#pragma once

#include <Eigen/Core>
#include <vector>

#include "billiard_shot_planner/core/expected.hpp"
#include "billiard_shot_planner/impact/contact.hpp"

namespace billiard_shot_planner
{
/// A simultaneous multiple-impact problem: a mechanical system with generalised velocity u (dimension d), its
/// mass matrix, and the contacts that act during the impact. Gravity and other finite forces are negligible
/// against impact forces and are not modelled (paper §2).
struct ImpactProblem
{
  Eigen::MatrixXd mass_matrix;    ///< d×d, symmetric positive definite (kg, kg·m², …)
  Eigen::VectorXd velocity;       ///< u before the impact
  std::vector<Contact> contacts;  ///< at least one must approach (normal · u < 0)
};

/// Checks every field; the error names the first bad one (e.g. "contacts[1].law.restitution").
Status validate(const ImpactProblem& problem);

}  // namespace billiard_shot_planner

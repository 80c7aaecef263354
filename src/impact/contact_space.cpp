#include "contact_space.hpp"

#include <Eigen/Cholesky>
#include <algorithm>

namespace billiard_shot_planner
{
namespace detail
{
namespace
{
Eigen::MatrixXd stackJacobian(const ImpactProblem& problem, ContactSpace& space)
{
  const auto dofs = problem.velocity.size();
  for (const Contact& contact : problem.contacts)
  {
    space.offset.push_back(space.size);
    space.dim.push_back(contact.hasFriction() ? 3 : 1);
    space.size += space.dim.back();
  }
  Eigen::MatrixXd jacobian(space.size, dofs);
  for (std::size_t i = 0; i < problem.contacts.size(); ++i)
  {
    const Contact& contact = problem.contacts[i];
    jacobian.row(space.offset[i]) = contact.normal;
    if (space.dim[i] == 3)
      jacobian.middleRows(space.offset[i] + 1, 2) = contact.tangent;
  }
  return jacobian;
}
/// Contact spaces up to this size stay dense: their products are unrolled or short (contact_dynamics.cpp).
constexpr int DENSE_SIZE_LIMIT = 12;
/// The fill below which a sparse product beats a dense one (it reads an index per entry, and vectorises less).
constexpr double SPARSE_FILL_LIMIT = 0.5;

void useSparseDelassusIfWorthIt(ContactSpace& space)
{
  if (space.size <= DENSE_SIZE_LIMIT)
    return;
  const auto nonzeros = (space.delassus.array() != 0.0).count();
  if (static_cast<double>(nonzeros) >= SPARSE_FILL_LIMIT * static_cast<double>(space.delassus.size()))
    return;
  space.sparse_delassus = space.delassus.sparseView(1.0, 0.0);  // exact zeros only: the products stay exact
}
}  // namespace

ContactSpace buildContactSpace(const ImpactProblem& problem)
{
  ContactSpace space;
  const Eigen::MatrixXd jacobian = stackJacobian(problem, space);
  const Eigen::LLT<Eigen::MatrixXd> mass(problem.mass_matrix);
  space.response = mass.solve(jacobian.transpose());
  Eigen::MatrixXd delassus = jacobian * space.response;
  Eigen::VectorXd w0 = jacobian * problem.velocity;

  double w_ref = 0.0;
  double k_ref = 0.0;
  for (std::size_t i = 0; i < problem.contacts.size(); ++i)
  {
    w_ref = std::max(w_ref, delassus(space.offset[i], space.offset[i]));
    k_ref = std::max(k_ref, problem.contacts[i].law.stiffness);
  }
  space.velocity_scale = w0.cwiseAbs().maxCoeff();
  space.stiffness_scale = k_ref;
  space.impulse_scale = space.velocity_scale / w_ref;
  space.energy_scale = space.velocity_scale * space.velocity_scale / w_ref;
  space.time_scale = 1.0 / std::sqrt(k_ref * w_ref);
  space.delassus = delassus / w_ref;
  space.w0 = w0 / space.velocity_scale;
  useSparseDelassusIfWorthIt(space);
  // Round-off of a contact at rest is not a slip: its direction is noise, and the first stick and slip decisions
  // of a contact loaded from rest, made while its forces are of the same order (1e-23), followed it. A rolling
  // ball's cushion hit integrated from the start at 1e-13 came out 0.13 m/s off (its cloth stuck).
  for (std::size_t i = 0; i < problem.contacts.size(); ++i)
  {
    auto rows = space.w0.segment(space.offset[i], space.dim[i]);
    if (rows.norm() <= VELOCITY_TOLERANCE)
      rows.setZero();
  }
  return space;
}

}  // namespace detail
}  // namespace billiard_shot_planner

#include "contact_dynamics.hpp"

namespace billiard_shot_planner
{
namespace detail
{
ContactDynamics::ContactDynamics(const ContactSpace& space, const std::vector<ContactState>& contacts)
    : space_(space), contacts_(contacts)
{
  refresh();
}

void ContactDynamics::refresh()
{
  rigid_rows_.clear();
  for (std::size_t i = 0; i < contacts_.size(); ++i)
    if (contacts_[i].phase == NormalPhase::RigidLink)
      rigid_rows_.push_back(space_.offset[i]);
  if (rigid_rows_.empty())
    return;
  const auto n = static_cast<Eigen::Index>(rigid_rows_.size());
  rigid_coupling_.resize(n, space_.size);
  Eigen::MatrixXd block(n, n);
  for (Eigen::Index a = 0; a < n; ++a)
  {
    rigid_coupling_.row(a) = space_.delassus.row(rigid_rows_[a]);
    for (Eigen::Index b = 0; b < n; ++b)
      block(a, b) = space_.delassus(rigid_rows_[a], rigid_rows_[b]);
  }
  // Redundant links (a singular block) get the least-norm constraint forces.
  rigid_solver_.compute(block);
}

Eigen::VectorXd ContactDynamics::relativeVelocity(const double* y) const
{
  return space_.w0 + space_.delassus * Eigen::Map<const Eigen::VectorXd>(y, space_.size);
}

Eigen::VectorXd ContactDynamics::forces(const double* y) const
{
  const double* s = y + space_.size;
  Eigen::VectorXd force = Eigen::VectorXd::Zero(space_.size);
  for (std::size_t i = 0; i < contacts_.size(); ++i)
  {
    const ContactState& contact = contacts_[i];
    const int row = space_.offset[i];
    if (contact.compliant())
      force(row) = -contact.stiffness * s[row];
    if (contact.active() && space_.dim[i] == 3)
    {
      force(row + 1) = -contact.kappa * s[row + 1];
      force(row + 2) = -contact.kappa * s[row + 2];
    }
  }
  if (!rigid_rows_.empty())
  {
    // Keep every rigid link's normal velocity constant (zero): W_RR F_R = −W_R· F_rest.
    const Eigen::VectorXd link_forces = rigid_solver_.solve(-(rigid_coupling_ * force));
    for (std::size_t a = 0; a < rigid_rows_.size(); ++a)
      force(rigid_rows_[a]) = link_forces(static_cast<Eigen::Index>(a));
  }
  return force;
}

double ContactDynamics::strainEnergy(std::size_t contact, const double* y) const
{
  const ContactState& state = contacts_[contact];
  const double* s = y + space_.size + space_.offset[contact];
  double energy = state.compliant() ? 0.5 * state.stiffness * s[0] * s[0] : 0.0;
  if (space_.dim[contact] == 3)
    energy += 0.5 * state.kappa * (s[1] * s[1] + s[2] * s[2]);
  return energy;
}

Eigen::Vector2d ContactDynamics::springDirection(std::size_t contact, const double* y) const
{
  const double* s = y + space_.size + space_.offset[contact];
  const Eigen::Vector2d tangential(s[1], s[2]);
  const double length = tangential.norm();
  // Below this the direction is round-off; the slip direction chosen at the transition is the right one.
  const double relaxed = 1e-14 * (1.0 + std::abs(s[0]));
  return length > relaxed ? Eigen::Vector2d(tangential / length) : contacts_[contact].slip_direction;
}

double ContactDynamics::slidingSpeed(std::size_t contact, const double* y, const Eigen::VectorXd& w) const
{
  const ContactState& state = contacts_[contact];
  const int row = space_.offset[contact];
  const Eigen::Vector2d tangential_velocity(w(row + 1), w(row + 2));
  return springDirection(contact, y).dot(tangential_velocity) + state.friction * state.eta2() * w(row);
}

void ContactDynamics::springRates(std::size_t contact, const double* y, const Eigen::VectorXd& w, double* rates) const
{
  const ContactState& state = contacts_[contact];
  const int row = space_.offset[contact];
  const int dim = space_.dim[contact];
  for (int k = 0; k < dim; ++k)
    rates[k] = 0.0;
  if (!state.active())
    return;
  rates[0] = state.compliant() ? w(row) : 0.0;
  if (dim != 3)
    return;
  rates[1] = w(row + 1);
  rates[2] = w(row + 2);
  if (state.slipping)
  {
    // Slip: the contact particle slides at speed σ along the spring direction (spec §2.6).
    const Eigen::Vector2d direction = springDirection(contact, y);
    const double sigma = slidingSpeed(contact, y, w);
    rates[1] -= sigma * direction.x();
    rates[2] -= sigma * direction.y();
  }
}

void ContactDynamics::operator()(const OdeState& y, OdeState& dydt, double /*t*/) const
{
  const Eigen::VectorXd w = relativeVelocity(y.data());
  const Eigen::VectorXd force = forces(y.data());
  for (int r = 0; r < space_.size; ++r)
    dydt[r] = force(r);
  for (std::size_t i = 0; i < contacts_.size(); ++i)
    springRates(i, y.data(), w, dydt.data() + space_.size + space_.offset[i]);
}

}  // namespace detail
}  // namespace billiard_shot_planner

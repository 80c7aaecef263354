#include "linear_phase.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>

namespace billiard_shot_planner
{
namespace detail
{
namespace
{
/// Below this phase ωτ the sines are evaluated by their series: sin(ωτ)/ω and (1 − cos ωτ)/ω² lose all digits
/// to cancellation as ω → 0 (modes of a singular Delassus matrix, which move linearly).
constexpr double SERIES_PHASE = 1e-3;

/// Position and time integral of one oscillator ẍ = −ω²x with x(0) = a, ẋ(0) = b, at time τ.
std::pair<double, double> oscillator(double a, double b, double omega, double tau)
{
  const double phase = omega * tau;
  double sin_over_omega, one_minus_cos_over_omega2;
  if (phase < SERIES_PHASE)
  {
    const double p2 = phase * phase;
    sin_over_omega = tau * (1.0 - p2 / 6.0 * (1.0 - p2 / 20.0));
    one_minus_cos_over_omega2 = tau * tau * (0.5 - p2 / 24.0 * (1.0 - p2 / 30.0));
  }
  else
  {
    sin_over_omega = std::sin(phase) / omega;
    one_minus_cos_over_omega2 = (1.0 - std::cos(phase)) / (omega * omega);
  }
  const double cos_phase = 1.0 - omega * omega * one_minus_cos_over_omega2;
  return {a * cos_phase + b * sin_over_omega, a * sin_over_omega + b * one_minus_cos_over_omega2};
}
}  // namespace

namespace
{
/// Relative size below which a value is round-off of the values it was computed from.
constexpr double ROUND_OFF = 1e-12;

/// A sliding contact keeps its direction ŝ when its tangential velocity has no part across ŝ, now or ever: the
/// rows of W G that would accelerate it across are zero (a ball alone on the table: its friction only changes the
/// tangential velocity along itself). Otherwise ŝ turns and the dynamics is not linear.
bool directionFixed(std::size_t i, const ContactSpace& space, const ContactDynamics& dynamics, const OdeState& y0,
                    const Eigen::VectorXd& velocity, const Eigen::MatrixXd& delassus_times_g)
{
  const Eigen::Vector2d direction = dynamics.springDirection(i, y0.data());
  const Eigen::Vector2d across(-direction.y(), direction.x());
  const int row = space.offset[i];
  const double velocity_across = across.dot(velocity.segment<2>(row + 1));
  const Eigen::RowVectorXd acceleration_across =
      across.x() * delassus_times_g.row(row + 1) + across.y() * delassus_times_g.row(row + 2);
  return std::abs(velocity_across) <= ROUND_OFF * velocity.lpNorm<Eigen::Infinity>() &&
         (acceleration_across.size() == 0 ||
          acceleration_across.lpNorm<Eigen::Infinity>() <= ROUND_OFF * delassus_times_g.lpNorm<Eigen::Infinity>());
}
}  // namespace

Eigen::MatrixXd LinearPhaseStepper::forceMap(const ContactSpace& space, const std::vector<ContactState>& contacts,
                                             const ContactDynamics& dynamics, std::vector<double>& stiffness)
{
  for (std::size_t i = 0; i < contacts.size(); ++i)
  {
    const ContactState& contact = contacts[i];
    const int row = space.offset[i];
    if (!contact.active())
      continue;
    if (contact.compliant())
    {
      moving_rows_.push_back(row);
      stiffness.push_back(contact.stiffness);
    }
    if (space.dim[i] == 3 && !contact.slipping)  // a sliding spring only carries its (fixed) direction
      for (int k = 1; k <= 2; ++k)
      {
        moving_rows_.push_back(row + k);
        stiffness.push_back(contact.kappa);
      }
  }
  // The forces (rigid-link forces and sliding friction included) are linear in the moving springs: F = G s_R. G is
  // read off ContactDynamics::forces one spring at a time, so the closed form uses the very force law it replaces.
  // The other springs keep their values: a sliding spring's direction sets its friction.
  const Eigen::Index n = space.size;
  const auto r = static_cast<Eigen::Index>(moving_rows_.size());
  OdeState probe = y0_;
  for (int row : moving_rows_)
    probe[static_cast<std::size_t>(n + row)] = 0.0;
  Eigen::MatrixXd force_from_s(n, r);
  Eigen::VectorXd force;
  for (Eigen::Index a = 0; a < r; ++a)
  {
    probe[static_cast<std::size_t>(n + moving_rows_[a])] = 1.0;
    dynamics.forces(probe.data(), force);
    force_from_s.col(a) = force;
    probe[static_cast<std::size_t>(n + moving_rows_[a])] = 0.0;
  }
  return force_from_s;
}

std::optional<LinearPhaseStepper> LinearPhaseStepper::tryBuild(const ContactSpace& space,
                                                               const std::vector<ContactState>& contacts,
                                                               const ContactDynamics& dynamics, const OdeState& y0,
                                                               double t0, double radians_per_step)
{
  LinearPhaseStepper stepper(y0, t0);
  std::vector<double> stiffness;
  const Eigen::MatrixXd force_from_s = stepper.forceMap(space, contacts, dynamics, stiffness);
  const Eigen::MatrixXd delassus_times_g = space.delassus * force_from_s;
  const Eigen::VectorXd velocity = dynamics.relativeVelocity(y0.data());
  bool sliding = false;
  for (std::size_t i = 0; i < contacts.size(); ++i)
  {
    if (!contacts[i].sliding())
      continue;
    if (!directionFixed(i, space, dynamics, y0, velocity, delassus_times_g))
      return std::nullopt;
    sliding = true;
  }
  // With rigid links G = Π E_R (−K), Π = 1 − B W_LL⁺ W_L, and W G = (W Π) E_R (−K) with W Π symmetric (the Schur
  // complement of the links in W) unless friction slides: then symmetry is checked, not assumed.
  const Eigen::Index n = space.size;
  const auto r = static_cast<Eigen::Index>(stepper.moving_rows_.size());
  Eigen::VectorXd sqrt_k(r);
  Eigen::MatrixXd reduced(r, r);  // (W Π)_RR
  for (Eigen::Index a = 0; a < r; ++a)
  {
    sqrt_k(a) = std::sqrt(stiffness[a]);
    for (Eigen::Index b = 0; b < r; ++b)
      reduced(a, b) = -delassus_times_g(stepper.moving_rows_[a], b) / stiffness[b];
  }
  if (sliding && r > 0 &&
      (reduced - reduced.transpose()).lpNorm<Eigen::Infinity>() > ROUND_OFF * reduced.lpNorm<Eigen::Infinity>())
    return std::nullopt;
  const Eigen::MatrixXd symmetric = sqrt_k.asDiagonal() * (0.5 * (reduced + reduced.transpose())) * sqrt_k.asDiagonal();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> modes(symmetric);
  if (sliding && r > 0 && modes.eigenvalues().minCoeff() < -ROUND_OFF * modes.eigenvalues().cwiseAbs().maxCoeff())
    return std::nullopt;  // friction could make the springs grow without bound: left to the integrator
  stepper.omega_ = modes.eigenvalues().cwiseMax(0.0).cwiseSqrt();
  stepper.spring_from_modes_ = sqrt_k.cwiseInverse().asDiagonal() * modes.eigenvectors();
  stepper.impulse_from_modes_ = force_from_s * stepper.spring_from_modes_;

  Eigen::VectorXd z(r), z_rate(r);
  for (Eigen::Index a = 0; a < r; ++a)
  {
    z(a) = sqrt_k(a) * y0[static_cast<std::size_t>(n + stepper.moving_rows_[a])];
    z_rate(a) = sqrt_k(a) * velocity(stepper.moving_rows_[a]);
  }
  stepper.modal_position_ = modes.eigenvectors().transpose() * z;
  stepper.modal_velocity_ = modes.eigenvectors().transpose() * z_rate;
  stepper.position_.resize(r);
  stepper.integral_.resize(r);
  stepper.springs_.resize(r);
  const double fastest = r > 0 ? stepper.omega_.maxCoeff() : 0.0;
  stepper.step_ = radians_per_step / (fastest > 0.0 ? fastest : 1.0);
  return stepper;
}

void LinearPhaseStepper::calc_state(double t, OdeState& y) const
{
  const double tau = t - t0_;
  const Eigen::Index r = omega_.size();
  for (Eigen::Index j = 0; j < r; ++j)
    std::tie(position_(j), integral_(j)) = oscillator(modal_position_(j), modal_velocity_(j), omega_(j), tau);
  y = y0_;
  const Eigen::Index n = impulse_from_modes_.rows();
  // Coefficient-wise products: the matrices are tiny, where Eigen's blocked kernels cost more than they save.
  Eigen::Map<Eigen::VectorXd>(y.data(), n).noalias() += impulse_from_modes_.lazyProduct(integral_);
  springs_.noalias() = spring_from_modes_.lazyProduct(position_);
  for (Eigen::Index a = 0; a < r; ++a)
    y[static_cast<std::size_t>(n + moving_rows_[a])] = springs_(a);
}

}  // namespace detail
}  // namespace billiard_shot_planner

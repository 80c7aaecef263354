#include "linear_phase.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>

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
  const Eigen::Vector2d direction = dynamics.carrierDirection(i, y0.data());
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

void LinearPhaseStepper::readForceMap(const ContactSpace& space, const std::vector<ContactState>& contacts,
                                      const ContactDynamics& dynamics)
{
  moving_rows_.clear();
  stiffness_.clear();
  for (std::size_t i = 0; i < contacts.size(); ++i)
  {
    const ContactState& contact = contacts[i];
    const int row = space.offset[i];
    if (!contact.active())
      continue;
    if (contact.compliant())
    {
      moving_rows_.push_back(row);
      stiffness_.push_back(contact.normal.stiffness);
    }
    if (space.dim[i] == 3 && !contact.tangential.slipping)  // a sliding spring only carries its (fixed) direction
      for (int k = 1; k <= 2; ++k)
      {
        moving_rows_.push_back(row + k);
        stiffness_.push_back(contact.tangential.kappa);
      }
  }
  // The forces (rigid-link forces and sliding friction included) are linear in the moving springs: F = G s_R. G is
  // read off ContactDynamics::forces one spring at a time, so the closed form uses the very force law it replaces.
  // The other springs keep their values: a sliding spring's direction sets its friction.
  const Eigen::Index n = space.size;
  const auto r = static_cast<Eigen::Index>(moving_rows_.size());
  for (int row : moving_rows_)
    base_state_[static_cast<std::size_t>(n + row)] = 0.0;
  probe_ = base_state_;
  force_from_s_.resize(n, r);
  for (Eigen::Index a = 0; a < r; ++a)
  {
    probe_[static_cast<std::size_t>(n + moving_rows_[a])] = 1.0;
    dynamics.forces(probe_.data(), probe_force_, probe_directions_, probe_scratch_);
    force_from_s_.col(a) = probe_force_;
    probe_[static_cast<std::size_t>(n + moving_rows_[a])] = 0.0;
  }
}

bool LinearPhaseStepper::slidingDirectionsFixed(const ContactSpace& space, const std::vector<ContactState>& contacts,
                                                const ContactDynamics& dynamics, const OdeState& y0,
                                                bool& any_sliding) const
{
  any_sliding = false;
  for (std::size_t i = 0; i < contacts.size(); ++i)
  {
    if (!contacts[i].sliding())
      continue;
    if (!directionFixed(i, space, dynamics, y0, start_velocity_, delassus_times_g_))
      return false;
    any_sliding = true;
  }
  return true;
}

bool LinearPhaseStepper::build(const ContactSpace& space, const std::vector<ContactState>& contacts,
                               const ContactDynamics& dynamics, const OdeState& y0, double t0, double radians_per_step)
{
  base_state_ = y0;
  t0_ = t_ = t0;
  dynamics_ = &dynamics;
  space_ = &space;
  // The closed form is that of linear springs: a phase with a spring of another law is integrated.
  if (std::any_of(contacts.begin(), contacts.end(),
                  [](const ContactState& contact) { return contact.compliant() && !contact.normal.linear; }))
    return false;
  readForceMap(space, contacts, dynamics);
  delassus_times_g_.noalias() = space.delassus * force_from_s_;
  dynamics.relativeVelocity(y0.data(), start_velocity_);
  bool sliding = false;
  if (!slidingDirectionsFixed(space, contacts, dynamics, y0, sliding))
    return false;
  any_sliding_ = sliding;
  if (sliding)
    dynamics.carrierDirections(y0.data(), directions_);
  // With rigid links G = Π E_R (−K), Π = 1 − B W_LL⁺ W_L, and W G = (W Π) E_R (−K) with W Π symmetric (the Schur
  // complement of the links in W) unless friction slides: then symmetry is checked, not assumed.
  const Eigen::Index n = space.size;
  const auto r = static_cast<Eigen::Index>(moving_rows_.size());
  sqrt_k_.resize(r);
  reduced_.resize(r, r);
  for (Eigen::Index a = 0; a < r; ++a)
  {
    sqrt_k_(a) = std::sqrt(stiffness_[a]);
    for (Eigen::Index b = 0; b < r; ++b)
      reduced_(a, b) = -delassus_times_g_(moving_rows_[a], b) / stiffness_[b];
  }
  if (sliding && r > 0 &&
      (reduced_ - reduced_.transpose()).lpNorm<Eigen::Infinity>() > ROUND_OFF * reduced_.lpNorm<Eigen::Infinity>())
    return false;
  symmetric_.noalias() = sqrt_k_.asDiagonal() * (0.5 * (reduced_ + reduced_.transpose())) * sqrt_k_.asDiagonal();
  diagonalise();
  if (sliding && r > 0 && eigenvalues_.minCoeff() < -ROUND_OFF * eigenvalues_.cwiseAbs().maxCoeff())
    return false;  // friction could make the springs grow without bound: left to the integrator
  omega_ = eigenvalues_.cwiseMax(0.0).cwiseSqrt();
  spring_from_modes_.noalias() = sqrt_k_.cwiseInverse().asDiagonal() * eigenvectors_;
  force_from_modes_.noalias() = force_from_s_ * spring_from_modes_;
  velocity_map_made_ = false;  // by the first affineGuardBounds: only the affine search uses it

  // Modal coordinates of z = K^{1/2} s_R and of its rate (z and ż held in calc_state's scratch for the moment).
  position_.resize(r);
  integral_.resize(r);
  for (Eigen::Index a = 0; a < r; ++a)
  {
    position_(a) = sqrt_k_(a) * y0[static_cast<std::size_t>(n + moving_rows_[a])];
    integral_(a) = sqrt_k_(a) * start_velocity_(moving_rows_[a]);
  }
  modal_position_.noalias() = eigenvectors_.transpose() * position_;
  modal_velocity_.noalias() = eigenvectors_.transpose() * integral_;
  modes_time_ = std::numeric_limits<double>::quiet_NaN();  // position_ and integral_ held scratch
  const double fastest = r > 0 ? omega_.maxCoeff() : 0.0;
  step_ = radians_per_step / (fastest > 0.0 ? fastest : 1.0);
  return true;
}

void LinearPhaseStepper::diagonalise()
{
  const Eigen::Index r = symmetric_.rows();
  if (r > 2)
  {
    eigen_solver_.compute(symmetric_);
    eigenvalues_ = eigen_solver_.eigenvalues();
    eigenvectors_ = eigen_solver_.eigenvectors();
    return;
  }
  eigenvalues_.resize(r);
  eigenvectors_.setIdentity(r, r);
  if (r == 1)
    eigenvalues_(0) = symmetric_(0, 0);
  if (r != 2)
    return;
  // J^T S J is diagonal for the rotation J that Eigen's Jacobi solvers apply: its columns are the eigenvectors.
  Eigen::JacobiRotation<double> rotation;
  rotation.makeJacobi(symmetric_, 0, 1);
  eigenvectors_.applyOnTheRight(0, 1, rotation);
  for (Eigen::Index k = 0; k < 2; ++k)
  {
    const Eigen::Vector2d v = eigenvectors_.col(k);
    eigenvalues_(k) = v.dot(symmetric_.topLeftCorner<2, 2>() * v);
  }
}

void LinearPhaseStepper::evaluateModes(double t) const
{
  if (t == modes_time_)
    return;  // the crossing search reads the guards at one instant in turn
  modes_time_ = t;
  const double tau = t - t0_;
  for (Eigen::Index j = 0; j < omega_.size(); ++j)
    std::tie(position_(j), integral_(j)) = oscillator(modal_position_(j), modal_velocity_(j), omega_(j), tau);
}

void LinearPhaseStepper::calc_state(double t, OdeState& y) const
{
  evaluateModes(t);
  y = base_state_;
  addModes(y, nullptr);
}

void LinearPhaseStepper::calc_kinematics(double t, OdeState& y, Kinematics& kinematics) const
{
  evaluateModes(t);
  y = base_state_;
  kinematics.y = y.data();
  kinematics.force.setZero(force_from_modes_.rows());
  addModes(y, kinematics.force.data());
  // The velocity from the impulses, not from the modes (w0 + W G K^{-1/2} Q ∫p): the same to round-off, but contacts
  // barely reached yet (the far end of a chain) have velocities of that order, and the modal sum's round-off then
  // decides their first events differently from the integrator.
  dynamics_->relativeVelocity(y.data(), kinematics.velocity);
  if (any_sliding_)
    kinematics.directions = directions_;
}

template <bool Full>
LinearPhaseStepper::GuardValue LinearPhaseStepper::affineGuard(const AffineGuard& guard) const
{
  GuardValue quantity{};
  switch (guard.quantity)
  {
    case AffineGuard::Quantity::Velocity:
      quantity = velocityAt<Full>(guard.row);
      break;
    case AffineGuard::Quantity::Spring:
      quantity = springAt<Full>(guard.row);
      break;
    case AffineGuard::Quantity::Force:
      quantity = forceAt<Full>(guard.row);
      break;
  }
  return {guard.sign * quantity.value + guard.offset, guard.sign * quantity.rate, guard.sign * quantity.acceleration};
}

void LinearPhaseStepper::makeVelocityMap() const
{
  if (!velocity_map_made_)
    velocity_from_integrals_.noalias() = space_->delassus * force_from_modes_;
  velocity_map_made_ = true;
}

LinearPhaseStepper::GuardBounds LinearPhaseStepper::affineGuardBounds(const AffineGuard& guard) const
{
  // Mode j: p = a cos ωτ + (b/ω) sin ωτ, so |ṗ| ≤ |b| + ω|a|, |p̈| = ω²|p| ≤ ω(|b| + ω|a|) and |p⃛| = ω²|ṗ|. The
  // velocity's derivatives are W F(ṗ), W F(p̈), the spring's and the force's are linear in p̈, p⃛.
  makeVelocityMap();
  GuardBounds bounds{0.0, 0.0, 0.0};
  const auto moving = std::find(moving_rows_.begin(), moving_rows_.end(), guard.row);
  for (Eigen::Index j = 0; j < omega_.size(); ++j)
  {
    const double rate_bound = std::abs(modal_velocity_(j)) + omega_(j) * std::abs(modal_position_(j));
    double coefficient = 0.0, second = 0.0;  // the map of the mode onto the guard, and its bound's order in ω
    switch (guard.quantity)
    {
      case AffineGuard::Quantity::Velocity:
        coefficient = velocity_from_integrals_(guard.row, j);
        second = rate_bound;
        break;
      case AffineGuard::Quantity::Spring:
        if (moving != moving_rows_.end())
          coefficient = spring_from_modes_(moving - moving_rows_.begin(), j);
        second = omega_(j) * rate_bound;
        break;
      case AffineGuard::Quantity::Force:
        coefficient = force_from_modes_(guard.row, j);
        second = omega_(j) * rate_bound;
        break;
    }
    double highest = std::abs(coefficient) * second;
    for (int k = 2; k < TAYLOR_ORDER; ++k)
      highest *= omega_(j);
    bounds.second += std::abs(coefficient) * second;
    bounds.third += std::abs(coefficient) * omega_(j) * second;
    bounds.highest += highest;
  }
  return bounds;
}

void LinearPhaseStepper::affineGuardDerivatives(const AffineGuard& guard, double t, double* derivatives) const
{
  evaluateModes(t);
  for (int k = 2; k < TAYLOR_ORDER; ++k)
    derivatives[k] = 0.0;
  // The guard's derivative of order k is the modes' of order k − shift: the velocity is an integral of the modes,
  // the spring and the force are the modes themselves. The modes' derivatives cycle, p⁽ᵏ⁺²⁾ = −ω²p⁽ᵏ⁾.
  const Eigen::MatrixXd* map = &force_from_modes_;
  Eigen::Index map_row = guard.row;
  int shift = 0;
  switch (guard.quantity)
  {
    case AffineGuard::Quantity::Velocity:
      map = &velocity_from_integrals_;
      shift = 1;
      break;
    case AffineGuard::Quantity::Spring:
    {
      const auto moving = std::find(moving_rows_.begin(), moving_rows_.end(), guard.row);
      if (moving == moving_rows_.end())
        return;
      map = &spring_from_modes_;
      map_row = moving - moving_rows_.begin();
      break;
    }
    case AffineGuard::Quantity::Force:
      break;
  }
  for (Eigen::Index j = 0; j < omega_.size(); ++j)
  {
    const double coefficient = guard.sign * (*map)(map_row, j);
    const double factor = -omega_(j) * omega_(j);
    double even = coefficient * position_(j), odd = coefficient * modalRate(j);  // orders shift + 2m, shift + 2m + 1
    for (int k = shift; k < TAYLOR_ORDER; k += 2)
    {
      if (k >= 2)
        derivatives[k] += even;
      if (k + 1 >= 2 && k + 1 < TAYLOR_ORDER)
        derivatives[k + 1] += odd;
      even *= factor;
      odd *= factor;
    }
  }
}

template <bool Full>
LinearPhaseStepper::GuardValue LinearPhaseStepper::velocityAt(int row) const
{
  // From the impulses, as the integrator has it: w = w0 + W I, ẇ = W F (see calc_kinematics).
  double velocity = space_->w0(row), rate = 0.0;
  for (Eigen::Index k = 0; k < space_->size; ++k)
  {
    const double coupling = space_->delassus(row, k);
    if (coupling == 0.0)
      continue;
    double impulse = base_state_[static_cast<std::size_t>(k)], force = 0.0;
    for (Eigen::Index j = 0; j < omega_.size(); ++j)
    {
      impulse += force_from_modes_(k, j) * integral_(j);
      force += force_from_modes_(k, j) * position_(j);
    }
    velocity += coupling * impulse;
    rate += coupling * force;
  }
  double acceleration = 0.0;  // ẅ = W Ḟ, with the map that affineGuardBounds made when the search started
  if constexpr (Full)
    for (Eigen::Index j = 0; j < omega_.size(); ++j)
      acceleration += velocity_from_integrals_(row, j) * modalRate(j);
  return {velocity, rate, acceleration};
}

template <bool Full>
LinearPhaseStepper::GuardValue LinearPhaseStepper::springAt(int row) const
{
  const Eigen::Index n = space_->size;
  double spring = base_state_[static_cast<std::size_t>(n + row)], rate = 0.0;
  const auto moving = std::find(moving_rows_.begin(), moving_rows_.end(), row);
  if (moving == moving_rows_.end())
    return {spring, rate, 0.0};
  const auto a = static_cast<Eigen::Index>(moving - moving_rows_.begin());
  double acceleration = 0.0;
  for (Eigen::Index j = 0; j < omega_.size(); ++j)
  {
    const double term = spring_from_modes_(a, j) * position_(j);
    spring += term;
    rate += spring_from_modes_(a, j) * modalRate(j);
    if constexpr (Full)
      acceleration -= omega_(j) * omega_(j) * term;
  }
  return {spring, rate, acceleration};
}

template <bool Full>
LinearPhaseStepper::GuardValue LinearPhaseStepper::forceAt(int row) const
{
  double force = 0.0, rate = 0.0, acceleration = 0.0;
  for (Eigen::Index j = 0; j < omega_.size(); ++j)
  {
    const double term = force_from_modes_(row, j) * position_(j);
    force += term;
    rate += force_from_modes_(row, j) * modalRate(j);
    if constexpr (Full)
      acceleration -= omega_(j) * omega_(j) * term;
  }
  return {force, rate, acceleration};
}

void LinearPhaseStepper::addModes(OdeState& y, double* force) const
{
  // Plain loops, mode by mode: the matrices are tiny (a few rows, a few modes), where Eigen's product kernels cost
  // more than they save; this runs at every guard sample.
  const Eigen::Index n = force_from_modes_.rows();
  const Eigen::Index r = omega_.size();
  double* impulses = y.data();
  double* springs = y.data() + n;
  for (Eigen::Index j = 0; j < r; ++j)
  {
    const double p = position_(j), integral = integral_(j);
    const double* force_column = force_from_modes_.col(j).data();
    for (Eigen::Index i = 0; i < n; ++i)
      impulses[i] += force_column[i] * integral;
    for (Eigen::Index a = 0; a < r; ++a)
      springs[moving_rows_[a]] += spring_from_modes_(a, j) * p;
    if (force == nullptr)
      continue;
    for (Eigen::Index i = 0; i < n; ++i)
      force[i] += force_column[i] * p;
  }
}

// The affine search's two kinds of samples.
template LinearPhaseStepper::GuardValue LinearPhaseStepper::affineGuard<true>(const AffineGuard&) const;
template LinearPhaseStepper::GuardValue LinearPhaseStepper::affineGuard<false>(const AffineGuard&) const;

}  // namespace detail
}  // namespace billiard_shot_planner

#pragma once

#include <Eigen/Core>
#include <optional>
#include <utility>
#include <vector>

#include "contact_dynamics.hpp"

namespace billiard_shot_planner
{
namespace detail
{
/// Closed-form spring dynamics for a discrete state whose dynamics is linear.
///
/// That is every state in which no active contact slides (frictionless or sticking contacts), and those in which
/// the sliding contacts cannot change their sliding direction (a ball sliding on the table alone: its tangential
/// velocity only changes along the friction force). Then every force is linear in the moving spring lengths
/// (F = −k s_n, −κ s_t, −μ F_n ŝ with ŝ fixed, and rigid-link forces that keep their normal velocities at zero), so
/// they obey s̈ = −S K s with S the Delassus matrix reduced by the rigid links (a Schur complement). Where S is
/// symmetric — always without sliding, and checked with it — z = K^{1/2} s is a set of independent oscillators; the
/// state at any instant is a sum of sines and cosines, exact to round-off. It replaces the numerical integrator in
/// these states, with the same interface as Odeint's dense-output steppers so that the guards and the root finding
/// stay the same.
class LinearPhaseStepper
{
public:
  /// The closed form of the state from y0 at t0, or nothing when the state's dynamics is not linear (a sliding
  /// direction would turn) or not symmetric. Steps span `radians_per_step` of the fastest mode's phase.
  /// `dynamics` must describe the same discrete state as `contacts` (refreshed after the last transition).
  static std::optional<LinearPhaseStepper> tryBuild(const ContactSpace& space,
                                                    const std::vector<ContactState>& contacts,
                                                    const ContactDynamics& dynamics, const OdeState& y0, double t0,
                                                    double radians_per_step);

  /// Advances by a fixed step: a fraction of the fastest period, so that guard sampling sees every crossing.
  template <class System>
  std::pair<double, double> do_step(System&& /*dynamics*/)
  {
    const double start = t_;
    t_ += step_;
    return {start, t_};
  }

  void calc_state(double t, OdeState& y) const;

private:
  LinearPhaseStepper(const OdeState& y0, double t0) : y0_(y0), t0_(t0), t_(t0), step_(0.0) {}
  /// Collects the moving springs (their rows and stiffnesses) and returns the force map G: F = G s_R.
  Eigen::MatrixXd forceMap(const ContactSpace& space, const std::vector<ContactState>& contacts,
                           const ContactDynamics& dynamics, std::vector<double>& stiffness);

  OdeState y0_;
  double t0_;
  double t_;
  double step_;
  std::vector<int> moving_rows_;    ///< rows of s that change (compliant normals, sticking tangentials)
  Eigen::VectorXd omega_;           ///< modal angular frequencies
  Eigen::VectorXd modal_position_;  ///< modal coordinates at t0
  Eigen::VectorXd modal_velocity_;
  Eigen::MatrixXd spring_from_modes_;                      ///< s_R = K^{-1/2} Q p
  Eigen::MatrixXd impulse_from_modes_;                     ///< I − I0 = G K^{-1/2} Q ∫p
  mutable Eigen::VectorXd position_, integral_, springs_;  ///< scratch of calc_state (called very often)
};

}  // namespace detail
}  // namespace billiard_shot_planner

#pragma once

#include <Eigen/Core>

namespace billiard_shot_planner
{
namespace detail
{
/// A contact's tangential Coulomb spring (docs/impact_model.md, "Coulomb friction and tangential compliance"): a
/// linear spring of stiffness κ = k̄/η̄² that sticks while its force is inside the friction cone μF_n and slips on
/// the cone, and its mode — sticking or slipping, and along which direction.
struct TangentialSpring
{
  /// κ; never changes, not even at an end of compression.
  double kappa = 1.0;
  double friction = 0.0;  ///< μ
  bool slipping = false;
  Eigen::Vector2d slip_direction = Eigen::Vector2d::UnitX();  ///< used while the spring is relaxed
  /// Set when a slip starts from relaxed springs (read through ContactState::followsSlip()): the slip direction then
  /// follows the tangential velocity with its quasi-steady lag instead of being integrated, because the cone's spring
  /// ρ = μF_n/κ is so short that the direction relaxes far faster than anything else moves (|v_t|/ρ), a stiff
  /// equation. Released once its relaxation time ρ/|v_t| reaches the quasi-steady limit
  /// (ContactDynamics::relaxationRatio).
  bool quasi_steady = false;

  /// A sticking spring's force −κ s_t.
  Eigen::Vector2d force(double s1, double s2) const { return -kappa * Eigen::Vector2d(s1, s2); }
  /// Its rate −κ ṡ_t.
  Eigen::Vector2d forceRate(const Eigen::Vector2d& rate) const { return -kappa * rate; }
  /// A sticking spring's energy ½κ|s_t|².
  double energy(double s1, double s2) const { return 0.5 * kappa * (s1 * s1 + s2 * s2); }
  /// Length of the spring on the friction cone under a normal force F_n, ρ = μF_n/κ (dimensionless).
  double coneLength(double normal_force) const { return friction * normal_force / kappa; }
  /// The energy of a spring stretched to the cone's length ρ, ½κρ².
  double coneEnergy(double cone_length) const { return 0.5 * kappa * cone_length * cone_length; }
};

}  // namespace detail
}  // namespace billiard_shot_planner

#pragma once

#include <Eigen/Core>

#include "billiard_shot_planner/impact/contact.hpp"
#include "contact_space.hpp"

namespace billiard_shot_planner
{
namespace detail
{
/// Normal phase of one contact in the state transition diagram.
enum class NormalPhase
{
  Inactive,     ///< not touching, or touching without force; springs relaxed
  Compression,  ///< loaded, normal velocity approaching
  Restitution,  ///< loaded, normal velocity separating
  RigidLink,    ///< limit of infinite stiffness (chattering or e = 0): zero normal velocity, force by constraint
};

/// The discrete part of a contact's state plus its current stiffnesses (dimensionless).
struct ContactState
{
  NormalPhase phase = NormalPhase::Inactive;
  bool slipping = false;
  bool rigid = false;      ///< stiffness is infinite: activation makes a rigid link
  bool chattered = false;  ///< rigid because an infinite sequence was cut at its limit
  /// A rigid link that jammed: its slip would start with a negative sliding speed or a pulling force (Painlevé's
  /// inconsistency), so it sticks, and stays stuck until it lets go (see jammedLink).
  bool jammed = false;
  /// Approach (dimensionless) beyond which an inactive contact reactivates: round-off, VELOCITY_TOLERANCE, or the
  /// round-off of its velocity from the impulses where those are large (set when it stops touching).
  double reactivation_speed = VELOCITY_TOLERANCE;
  int ends_of_compression = 0;
  double stiffness = 1.0;  ///< current k = k̄ / e^{2j}
  double original_stiffness = 1.0;
  /// Tangential stiffness κ = k̄ / η̄²; never changes, not even at an end of compression (docs/impact_model.md,
  /// Coulomb friction and tangential compliance).
  double kappa = 1.0;
  /// The restitution of the current (or last) compression, as normal_law gives it at its end (see restituteAt).
  double restitution = 1.0;
  double low_speed_restitution = 1.0;  ///< the law's e0: ContactLaw::restitution
  NormalLaw normal_law;
  double friction = 0.0;
  Eigen::Vector2d slip_direction = Eigen::Vector2d::UnitX();  ///< used while the tangential spring is relaxed
  /// Set when a slip starts from relaxed springs (read through followsSlip()): the slip direction then follows the
  /// tangential velocity with its quasi-steady lag instead of being integrated, because the cone's spring
  /// ρ = μF_n/κ is so short that the direction relaxes far faster than anything else moves (|v_t|/ρ), a stiff
  /// equation. Released once its relaxation time ρ/|v_t| reaches the quasi-steady limit
  /// (ContactDynamics::relaxationRatio).
  bool quasi_steady = false;

  /// The linear normal spring's force F = −k s, its energy ½ k s² and its rate −k ṡ (dimensionless): the one place
  /// the spring's law is written (every NormalLaw keeps the spring linear and sets only how k grows).
  double normalForce(double deformation) const { return -stiffness * deformation; }
  double normalEnergy(double deformation) const { return 0.5 * stiffness * deformation * deformation; }
  double normalForceRate(double deformation_rate) const { return -stiffness * deformation_rate; }
  /// Sets `restitution` to the law's for a compression whose energy-equivalent approach speed is `impact_speed`
  /// (m/s), and returns it.
  double restituteAt(double impact_speed)
  {
    restitution = restitutionOf(normal_law, low_speed_restitution, impact_speed);
    return restitution;
  }

  bool active() const { return phase != NormalPhase::Inactive; }
  bool compliant() const { return phase == NormalPhase::Compression || phase == NormalPhase::Restitution; }
  /// Touching and sliding (only contacts with tangential rows ever slip).
  bool sliding() const { return active() && slipping; }
  /// Sliding with its direction following the slip (see quasi_steady).
  bool followsSlip() const { return sliding() && quasi_steady; }
  /// Sliding while its normal spring relaxes: the cone shrinks toward a separation (see SeparationClockStepper).
  bool slidingInRestitution() const { return slipping && phase == NormalPhase::Restitution; }
  /// Length of the tangential spring on the friction cone under a normal force F_n, ρ = μF_n/κ (dimensionless).
  double coneLength(double normal_force) const { return friction * normal_force / kappa; }
  /// Rate of that length as the normal spring deforms at `normal_rate` (v_n): ρ̇ = μη²ṡ_n, and likewise for its
  /// higher derivatives.
  double coneRate(double normal_rate) const { return friction * eta2() * normal_rate; }
  /// Current η² = k/κ; grows by 1/e² with k at every end of compression (docs/impact_model.md, Coulomb friction
  /// and tangential compliance).
  double eta2() const { return stiffness / kappa; }
};

inline ContactState initialContactState(const ContactLaw& law, double stiffness_scale)
{
  ContactState state;
  state.original_stiffness = law.stiffness / stiffness_scale;
  state.stiffness = state.original_stiffness;
  state.kappa = state.original_stiffness / law.eta2;
  state.restitution = law.restitution;
  state.low_speed_restitution = law.restitution;
  state.normal_law = law.normal_law;
  state.friction = law.friction;
  return state;
}

}  // namespace detail
}  // namespace billiard_shot_planner

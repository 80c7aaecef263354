#pragma once

#include <Eigen/Core>

#include "billiard_shot_planner/impact/contact.hpp"
#include "contact_space.hpp"
#include "normal_spring.hpp"
#include "tangential_spring.hpp"

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

/// The discrete part of a contact's state: its phase in the state diagram, its normal spring (the law and its
/// current stiffness) and its tangential Coulomb spring (the friction and the slip's mode).
struct ContactState
{
  NormalPhase phase = NormalPhase::Inactive;
  bool rigid = false;      ///< stiffness is infinite: activation makes a rigid link
  bool chattered = false;  ///< rigid because an infinite sequence was cut at its limit
  /// A rigid link that jammed: its slip would start with a negative sliding speed or a pulling force (Painlevé's
  /// inconsistency), so it sticks, and stays stuck until it lets go (see jammedLink).
  bool jammed = false;
  /// Approach (dimensionless) beyond which an inactive contact reactivates: round-off, VELOCITY_TOLERANCE, or the
  /// round-off of its velocity from the impulses where those are large (set when it stops touching).
  double reactivation_speed = VELOCITY_TOLERANCE;
  int ends_of_compression = 0;
  NormalSpring normal;
  TangentialSpring tangential;

  bool active() const { return phase != NormalPhase::Inactive; }
  bool compliant() const { return phase == NormalPhase::Compression || phase == NormalPhase::Restitution; }
  /// Touching and sliding (only contacts with tangential rows ever slip).
  bool sliding() const { return active() && tangential.slipping; }
  /// Sliding with its direction following the slip (see TangentialSpring::quasi_steady).
  bool followsSlip() const { return sliding() && tangential.quasi_steady; }
  /// Sliding while its normal spring relaxes: the cone shrinks toward a separation (see SeparationClockStepper).
  bool slidingInRestitution() const { return tangential.slipping && phase == NormalPhase::Restitution; }
  /// Rate of the cone's length ρ = μF_n/κ as the normal spring deforms at `normal_rate` (v_n) from `deformation`:
  /// ρ̇ = μ η² ṡ_n with η² = k_t/κ, k_t the normal spring's tangent stiffness (k for a linear spring, which grows by
  /// 1/e² at every end of compression: docs/impact_model.md, Coulomb friction and tangential compliance), and
  /// likewise for its higher derivatives.
  double coneRate(double normal_rate, double deformation) const
  {
    return tangential.friction * (normal.stiffnessAt(deformation) / tangential.kappa) * normal_rate;
  }
};

inline ContactState initialContactState(const ContactLaw& law, double stiffness_scale)
{
  ContactState state;
  state.normal.original_stiffness = law.stiffness / stiffness_scale;
  state.normal.stiffness = state.normal.original_stiffness;
  state.normal.restitution = law.restitution;
  state.normal.low_speed_restitution = law.restitution;
  state.normal.law = law.normal_law;
  state.normal.linear = isLinear(law.normal_law);
  state.tangential.kappa = state.normal.original_stiffness / law.eta2;
  state.tangential.friction = law.friction;
  return state;
}

}  // namespace detail
}  // namespace billiard_shot_planner

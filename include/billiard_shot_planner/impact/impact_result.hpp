#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

namespace billiard_shot_planner
{
/// Events of the state transition diagram (paper §3; docs/impact_model.md, Normal compliance and the state
/// transition diagram).
enum class ContactEventType
{
  EndOfCompression,      ///< normal velocity turns separating: k ← k/e², E ← e²E
  RestartOfCompression,  ///< approach again during restitution (paper §3.2); k kept
  Separation,            ///< the normal spring relaxes in restitution: the contact becomes inactive
  Reactivation,          ///< an inactive contact approaches again; k kept
  StickToSlip,           ///< the tangential spring force reaches the friction cone
  SlipToStick,           ///< the sliding speed of the contact particle falls to zero
  RigidLink,             ///< a chattering (or plastic, e = 0) contact becomes a rigid link (limit of the sequence)
  LinkRelease,           ///< a rigid link's force would turn tensile: the contact becomes inactive
};

const char* toString(ContactEventType type);

/// Impulse of one contact in its frame (t̂1, t̂2, n̂), on body A.
struct ContactImpulse
{
  double normal = 0.0;
  Eigen::Vector2d tangential = Eigen::Vector2d::Zero();
};

/// A snapshot of the collision; times are in the solver's normalised time unit (only ratios of stiffnesses are
/// physical, so absolute time is not).
struct ImpactSnapshot
{
  double time = 0.0;
  Eigen::VectorXd normal_impulses;  ///< per contact
  Eigen::VectorXd velocity;         ///< generalised velocity u
  Eigen::VectorXd strain_energies;  ///< per contact, normal plus tangential springs
  double kinetic_energy = 0.0;
  double total_energy() const { return kinetic_energy + strain_energies.sum(); }
};

struct ContactEvent
{
  ContactEventType type;
  std::size_t contact;
  ImpactSnapshot at;
};

/// One state of the diagram: the set of active contacts (S1 = {0, 1}, S2 = {1}, … for ball–ball–table) and the
/// values at its start.
struct ImpactState
{
  std::vector<std::size_t> active;
  ImpactSnapshot start;
};

struct ImpactResult
{
  Eigen::VectorXd velocity;              ///< generalised velocity after the impact
  std::vector<ContactImpulse> impulses;  ///< total impulse per contact
  std::vector<int> ends_of_compression;  ///< per contact
  /// Per contact: tangential mode at the first instant (docs/impact_model.md, Coulomb friction and tangential
  /// compliance, and Resting contacts).
  std::vector<bool> initially_slipping;
  std::vector<ImpactState> states;      ///< the state sequence, terminal state (no active contact) last
  std::vector<ContactEvent> events;     ///< every contact event in order
  std::vector<ImpactSnapshot> samples;  ///< impulse curve, when SolverOptions::record_samples
  double initial_kinetic_energy = 0.0;
  double final_kinetic_energy = 0.0;
  /// True when a contact chattered (an infinite state sequence) and the result is that sequence's limit.
  bool converged = false;
};

}  // namespace billiard_shot_planner

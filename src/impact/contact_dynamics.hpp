#pragma once

#include <Eigen/Core>
#include <Eigen/QR>
#include <vector>

#include "contact_space.hpp"
#include "contact_state.hpp"

namespace billiard_shot_planner
{
namespace detail
{
using OdeState = std::vector<double>;

/// The continuous dynamics of the virtual springs between events (spec §4.3), in contact space.
///
/// The ODE state is [I, s]: accumulated contact impulses and spring deformations, both of length
/// ContactSpace::size. Forces follow from the springs (F = −k s_n, −κ s_t), except at rigid links whose normal
/// force is the constraint force keeping their normal velocity at zero. A sliding contact's friction is
/// −μ F_n ŝ: its tangential spring then carries the slip direction ŝ (spec §2.6). Holds references: the owner keeps the
/// space and the contact states alive and calls refresh() after every discrete transition.
class ContactDynamics
{
public:
  /// `quasi_steady_relaxation`: the longest relaxation time ε = ρ/|v_t| of a slip direction that follows its slip
  /// quasi-steadily (see relaxationRatio).
  ContactDynamics(const ContactSpace& space, const std::vector<ContactState>& contacts, double quasi_steady_relaxation);

  /// Recomputes what depends on the discrete state (which contacts are rigid links).
  void refresh();

  Eigen::VectorXd relativeVelocity(const double* y) const;
  Eigen::VectorXd forces(const double* y) const;
  /// The same into existing vectors (no allocation once they have the size: guards are sampled very often).
  void relativeVelocity(const double* y, Eigen::VectorXd& velocity) const;
  void forces(const double* y, Eigen::VectorXd& force) const;
  /// Normal plus tangential strain energy of contact i (dimensionless).
  double strainEnergy(std::size_t contact, const double* y) const;
  /// Sliding speed σ = ŝ·v_t + μη²v_n of a slipping contact's particle (spec §2.6); for a rigid link, whose
  /// v_n = 0, σ = ŝ·v_t − μḟ/κ. w and F are the contact velocities and forces at y.
  double slidingSpeed(std::size_t contact, const double* y, const Eigen::VectorXd& w,
                      const Eigen::VectorXd& force) const;
  /// Rate ḟ of a rigid link's normal force, with w and F the contact velocities and forces at the same instant.
  double linkForceRate(std::size_t contact, const Eigen::VectorXd& w, const Eigen::VectorXd& force) const;
  /// Slip direction ŝ of a sliding contact: its carrier's, or the quasi-steady one while it follows the slip.
  Eigen::Vector2d springDirection(std::size_t contact, const double* y) const;
  /// A sliding contact's slip direction relaxes onto its slip in the time ε = ρ/|v_t| (ρ = μF_n/κ, its spring on
  /// the friction cone): this over the quasi-steady limit. Below 1 the direction may follow its slip; at 1 it is
  /// released to the integrator. |v_t| is floored at round-off, so a slip of round-off never counts as fast.
  double relaxationRatio(std::size_t contact, const Eigen::VectorXd& w, const Eigen::VectorXd& force) const;

  /// Right-hand side for Boost.Odeint.
  void operator()(const OdeState& y, OdeState& dydt, double /*t*/) const { rates(y.data(), dydt.data()); }
  /// The same on raw arrays. Returns Σ ρ̇/ρ over the sliding contacts in restitution, the relative rate at which
  /// their spring length on the friction cone, ρ = μF_n/κ, shrinks: about 1/τ, τ the time left to their
  /// separation (see SeparationClockStepper).
  double rates(const double* y, double* dydt) const;

private:
  /// w = w0 + W I for a contact space of N rows.
  template <int N>
  void addImpulseResponse(const double* y, Eigen::VectorXd& velocity) const;
  /// Rates of contact i's springs; cone_length is its coneLength() when it slides.
  void springRates(std::size_t contact, const double* y, const Eigen::VectorXd& w, double cone_length,
                   double* rates) const;
  /// Spring length of a sliding contact on its friction cone, ρ = μF_n/κ, bounded below (smoothly) where the
  /// spring vanishes.
  double coneLength(std::size_t contact, const Eigen::VectorXd& force) const;
  /// Unit direction of the tangential spring, or the stored slip direction while it is relaxed.
  Eigen::Vector2d carrierDirection(std::size_t contact, const double* y) const;
  /// Every sliding contact's direction in directions_ from its carrier at y (followSlip overrides the followed ones).
  void useCarrierDirections(const double* y) const;
  /// Sets directions_ of the contacts that follow their slip (ContactState::quasi_steady); force is scratch.
  void followSlip(const double* y, Eigen::VectorXd& force) const;
  /// A followed contact's first-order quasi-steady lag and relaxation time at one state.
  struct SlipLag
  {
    double angle = 0.0;       ///< δ, by which the slip direction trails the slip velocity's
    double relaxation = 0.0;  ///< ε = ρ/|v_t|
  };
  /// First-order lags sin δ = εψ̇ of the followed contacts at y (velocities w) into `lags`, with the forces of
  /// directions along the slip into `force` (ψ̇ is the turning rate of v_t under them).
  void firstOrderLags(const double* y, const Eigen::VectorXd& w, Eigen::VectorXd& force,
                      std::vector<SlipLag>& lags) const;
  /// Adds the second-order term to lags_ (first order at y, with `force` its forces): −εδ̇.
  void addLagRates(const double* y, const Eigen::VectorXd& force) const;
  /// Forces with the sliding contacts' friction along directions_.
  void forcesAlongDirections(const double* y, Eigen::VectorXd& force) const;
  /// Forces of the springs alone (rigid-link normals and sliding-link friction left at zero).
  void springForces(const double* y, Eigen::VectorXd& force) const;
  void addLinkForces(Eigen::VectorXd& force) const;
  /// Columns B of the rigid links' forces (F = F_s + B f) and the rows W_L of their normal velocities.
  Eigen::MatrixXd linkBasis() const;
  Eigen::MatrixXd linkRows() const;
  /// Part of a contact's tangential velocity across its slip direction ŝ = `direction`, (I − ŝŝᵀ)v_t.
  Eigen::Vector2d acrossSlip(std::size_t contact, const Eigen::Vector2d& direction, const Eigen::VectorXd& w) const;
  /// Turning rate of a sliding contact's slip direction ŝ = `direction`.
  Eigen::Vector2d directionRate(std::size_t contact, const Eigen::Vector2d& direction, const Eigen::VectorXd& w,
                                const Eigen::VectorXd& force) const;

  const ContactSpace& space_;
  const std::vector<ContactState>& contacts_;
  std::vector<std::size_t> rigid_contacts_;
  bool any_quasi_steady_ = false;
  double quasi_steady_relaxation_;
  mutable std::vector<SlipLag> lags_, shifted_lags_;  ///< scratch of followSlip
  mutable OdeState shifted_state_;
  mutable Eigen::VectorXd shifted_velocity_, shifted_force_;
  mutable std::vector<Eigen::Vector2d> directions_;  ///< slip directions of the last force evaluation
  mutable Eigen::VectorXd follow_velocity_;          ///< scratch of followSlip
  mutable Eigen::VectorXd follow_force_;             ///< scratch of springDirection and strainEnergy
  mutable Eigen::VectorXd velocity_scratch_;         ///< for operator(), called by the integrator
  mutable Eigen::VectorXd force_scratch_;
};

}  // namespace detail
}  // namespace billiard_shot_planner

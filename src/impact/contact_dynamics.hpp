#pragma once

#include <Eigen/Core>
#include <Eigen/QR>
#include <cstddef>
#include <limits>
#include <vector>

#include "contact_space.hpp"
#include "contact_state.hpp"

namespace billiard_shot_planner
{
namespace detail
{
using OdeState = std::vector<double>;

/// Slip directions ŝ by contact, as one force evaluation used them (meaningful for the sliding contacts only).
using SlipDirections = std::vector<Eigen::Vector2d>;

/// A followed contact's quasi-steady lag and relaxation time at one state.
struct SlipLag
{
  double angle = 0.0;       ///< δ, by which the slip direction trails the slip velocity's
  double relaxation = 0.0;  ///< ε = ρ/|v_t|
};

/// Storage that the quasi-steady lag's evaluation reuses from one force evaluation to the next (the integrator
/// evaluates thousands per solve): scratch, its contents meaningless between evaluations.
struct LagScratch
{
  Eigen::VectorXd velocity;  ///< w at the evaluated state, when forces() or a followed direction computes it
  std::vector<SlipLag> lags, shifted_lags;
  OdeState shifted_state;
  Eigen::VectorXd shifted_velocity, shifted_force;
  SlipDirections shifted_directions;
};

/// The contact velocities, forces and slip directions at one state, with the storage their evaluation reuses. Owned
/// by the caller: one ContactDynamics serves the integrator, the guard samples and the closed form, and evaluating
/// it changes nothing in it.
struct ForceEvaluation
{
  Eigen::VectorXd velocity;   ///< relative contact velocity w
  Eigen::VectorXd force;      ///< contact forces F
  SlipDirections directions;  ///< slip direction ŝ of each sliding contact's friction in `force`
  LagScratch lag;
};

/// The continuous dynamics of the virtual springs between events (docs/engine.md, "Formulation"), in contact space.
///
/// The ODE state is [I, s]: accumulated contact impulses and spring deformations, both of length
/// ContactSpace::size. Forces follow from the springs (F = −k s_n, −κ s_t), except at rigid links whose normal
/// force is the constraint force keeping their normal velocity at zero. A sliding contact's friction is
/// −μ F_n ŝ: its tangential spring then carries the slip direction ŝ (docs/impact_model.md, "Coulomb friction and
/// tangential compliance"). Holds references: the owner keeps the space and the contact states alive and calls
/// refresh() after every discrete transition. Every evaluation writes into storage its caller owns.
class ContactDynamics
{
public:
  /// `quasi_steady_relaxation`: the longest relaxation time ε = ρ/|v_t| of a slip direction that follows its slip
  /// quasi-steadily (see relaxationRatio).
  ContactDynamics(const ContactSpace& space, const std::vector<ContactState>& contacts, double quasi_steady_relaxation);

  /// Recomputes what depends on the discrete state (which contacts are rigid links, whether any follows its slip).
  void refresh();

  Eigen::VectorXd relativeVelocity(const double* y) const;
  /// The same into an existing vector (no allocation once it has the size: guards are sampled very often).
  void relativeVelocity(const double* y, Eigen::VectorXd& velocity) const;
  /// Forces at y (allocating: for the rare evaluation that keeps nothing).
  Eigen::VectorXd forces(const double* y) const;
  /// Forces at y, and the slip directions their friction acts along, into existing storage.
  void forces(const double* y, Eigen::VectorXd& force, SlipDirections& directions, LagScratch& scratch) const;
  /// Velocities, forces and slip directions at y.
  void evaluate(const double* y, ForceEvaluation& at) const;
  /// Normal plus tangential strain energy of contact i (dimensionless); `scratch` holds the forces of a sliding
  /// rigid link, whose cone is set by its constraint force.
  double strainEnergy(std::size_t contact, const double* y, ForceEvaluation& scratch) const;
  /// Sliding speed σ = ŝ·v_t + μη²v_n of a slipping contact's particle (docs/impact_model.md, "Coulomb friction and
  /// tangential compliance"); for a rigid link, whose v_n = 0, σ = ŝ·v_t − μḟ/κ. `at`: the evaluation at the state y.
  double slidingSpeed(std::size_t contact, const double* y, const ForceEvaluation& at) const;
  /// Rate ḟ of a rigid link's normal force at the state y, from the evaluation `at` there.
  double linkForceRate(std::size_t contact, const double* y, const ForceEvaluation& at) const;
  /// Slip direction ŝ of a sliding contact at y: its carrier's, or the quasi-steady one (evaluated into `scratch`)
  /// while it follows the slip.
  Eigen::Vector2d slipDirection(std::size_t contact, const double* y, ForceEvaluation& scratch) const;
  /// The slip direction that a sliding contact whose direction is integrated would have at y if it followed its slip
  /// (evaluated into `scratch`): what switching it would give, the contact left as it is.
  Eigen::Vector2d followedSlipDirection(std::size_t contact, const double* y, ForceEvaluation& scratch) const;
  /// Unit direction of a contact's tangential spring, or the stored slip direction while it is relaxed.
  Eigen::Vector2d carrierDirection(std::size_t contact, const double* y) const;
  /// Every sliding contact's direction from its carrier at y: the directions of forces() where no contact follows
  /// its slip.
  void carrierDirections(const double* y, SlipDirections& directions) const;
  /// A sliding contact's slip direction relaxes onto its slip in the time ε = ρ/|v_t| (ρ = μF_n/κ, its spring on
  /// the friction cone): this over the quasi-steady limit. Below 1 the direction may follow its slip; at 1 it is
  /// released to the integrator. |v_t| is floored at round-off, so a slip of round-off never counts as fast.
  double relaxationRatio(std::size_t contact, const Eigen::VectorXd& w, const Eigen::VectorXd& force) const;

  /// Right-hand side of the ODE on raw arrays, evaluated in `at`. Returns Σ ρ̇/ρ over the sliding contacts in
  /// restitution, the relative rate at which their spring length on the friction cone, ρ = μF_n/κ, shrinks: about
  /// 1/τ, τ the time left to their separation (see SeparationClockStepper).
  double rates(const double* y, double* dydt, ForceEvaluation& at) const;

private:
  /// No contact beyond those that follow their slip (an `also_following` that names none).
  static constexpr std::size_t NO_CONTACT = std::numeric_limits<std::size_t>::max();

  /// Whether contact i's direction follows its slip in an evaluation that takes `also_following` to follow too.
  bool follows(std::size_t contact, std::size_t also_following) const;
  /// w = w0 + W I for a contact space of N rows.
  template <int N>
  void addImpulseResponse(const double* y, Eigen::VectorXd& velocity) const;
  /// (W F) on the two tangent rows that follow normal row `row`: the tangential acceleration of a contact.
  Eigen::Vector2d tangentialResponse(int row, const Eigen::VectorXd& force) const;
  /// Rates of contact i's springs; cone_length is its coneLength() when it slides. The carrier of a direction that
  /// follows its slip (with `also_following`) waits.
  void springRates(std::size_t contact, const double* y, const Eigen::VectorXd& w, double cone_length,
                   std::size_t also_following, double* rates) const;
  /// Spring length of a sliding contact on its friction cone, ρ = μF_n/κ, bounded below (smoothly) where the
  /// spring vanishes.
  double coneLength(std::size_t contact, const Eigen::VectorXd& force) const;
  /// forces() with the velocities w at y given (at least on the rows of the active contacts).
  void forcesWithVelocity(const double* y, const Eigen::VectorXd& w, Eigen::VectorXd& force, SlipDirections& directions,
                          LagScratch& scratch) const;
  /// w on the rows of the active contacts (the others left as they are) when W̃ is sparse; all of w otherwise.
  void activeRelativeVelocity(const double* y, Eigen::VectorXd& velocity) const;
  /// Sets `directions` of the contacts that follow their slip (with `also_following`) and their forces, from the
  /// velocities w at y (read on the rows of the active contacts).
  void followSlip(const double* y, const Eigen::VectorXd& w, std::size_t also_following, Eigen::VectorXd& force,
                  SlipDirections& directions, LagScratch& scratch) const;
  /// First-order lags sin δ = εψ̇ of the followed contacts at y (velocities w) into `lags`, with `directions` along
  /// their slip and the forces of those directions into `force` (ψ̇ is the turning rate of v_t under them).
  void firstOrderLags(const double* y, const Eigen::VectorXd& w, std::size_t also_following, Eigen::VectorXd& force,
                      SlipDirections& directions, std::vector<SlipLag>& lags) const;
  /// Adds the second-order term −εδ̇ to scratch.lags (first order at y, with `force` their forces).
  void addLagRates(const double* y, const Eigen::VectorXd& w, const Eigen::VectorXd& force, std::size_t also_following,
                   LagScratch& scratch) const;
  /// Forces with the sliding contacts' friction along `directions`.
  void forcesAlongDirections(const double* y, const SlipDirections& directions, Eigen::VectorXd& force) const;
  /// Forces of the springs alone (rigid-link normals and sliding-link friction left at zero).
  void springForces(const double* y, const SlipDirections& directions, Eigen::VectorXd& force) const;
  void addLinkForces(const SlipDirections& directions, Eigen::VectorXd& force) const;
  /// The rigid links' forces f (F = F_s + B f, B their columns) that keep W_L F = 0 for the other forces `rates`
  /// (F_s, or with its rate, ḟ from Ḟ_s).
  Eigen::VectorXd solveLinks(const SlipDirections& directions, const Eigen::VectorXd& rates) const;
  /// (W_L B) at (link, by): how link `by`'s force moves link `link`'s normal velocity (indices into
  /// rigid_contacts_).
  double linkCoupling(std::size_t link, std::size_t by, const SlipDirections& directions) const;
  /// Part of a contact's tangential velocity across its slip direction ŝ = `direction`, (I − ŝŝᵀ)v_t.
  Eigen::Vector2d acrossSlip(std::size_t contact, const Eigen::Vector2d& direction, const Eigen::VectorXd& w) const;
  /// Turning rate of a sliding contact's slip direction ŝ = `direction`.
  Eigen::Vector2d directionRate(std::size_t contact, const Eigen::Vector2d& direction, const Eigen::VectorXd& w,
                                const Eigen::VectorXd& force) const;

  const ContactSpace& space_;
  const std::vector<ContactState>& contacts_;
  std::vector<std::size_t> rigid_contacts_;
  /// The rigid links' normal rows of W̃, W_L (one a link), set by refresh().
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> link_rows_;
  bool any_quasi_steady_ = false;
  double quasi_steady_relaxation_;
};

/// ContactDynamics as Boost.Odeint's system: its right-hand side, with the storage its evaluations reuse.
class SpringSystem
{
public:
  explicit SpringSystem(const ContactDynamics& dynamics) : dynamics_(&dynamics) {}

  void operator()(const OdeState& y, OdeState& dydt, double /*t*/) { rates(y.data(), dydt.data()); }
  /// ContactDynamics::rates.
  double rates(const double* y, double* dydt) { return dynamics_->rates(y, dydt, evaluation_); }

private:
  const ContactDynamics* dynamics_;
  ForceEvaluation evaluation_;
};

}  // namespace detail
}  // namespace billiard_shot_planner

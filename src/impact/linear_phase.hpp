#pragma once

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <utility>
#include <vector>

#include "contact_dynamics.hpp"
#include "state_transitions.hpp"

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
/// these states, with the same interface as Odeint's dense-output steppers so that the sampled guard search stays
/// the same; where every guard is affine it also gives their values, rates and curvature bounds from the modes
/// alone, for AffineCrossingSearch.
///
/// One stepper serves a whole solve and is rebuilt at every state: its storage is kept, so that a rebuild
/// allocates nothing once the sizes have been seen (a frictionless collision is a handful of short states).
class LinearPhaseStepper
{
public:
  /// Builds the closed form of the state from y0 at t0; false when the state's dynamics is not linear (a loaded
  /// spring whose law is not linear, a sliding direction that would turn) or not symmetric. Steps span
  /// `radians_per_step` of the fastest mode's phase. `dynamics` must describe the same discrete state as `contacts`
  /// (refreshed after the last transition), in which no slip direction follows its slip
  /// (TangentialSpring::quasi_steady): the closed form holds the directions fixed.
  bool build(const ContactSpace& space, const std::vector<ContactState>& contacts, const ContactDynamics& dynamics,
             const OdeState& y0, double t0, double radians_per_step);

  /// Advances by a fixed step: a fraction of the fastest period, so that guard sampling sees every crossing.
  template <class System>
  std::pair<double, double> do_step(System&& /*dynamics*/)
  {
    const double start = t_;
    t_ += step_;
    return {start, t_};
  }

  void calc_state(double t, OdeState& y) const;
  /// Moves the modes to t, for affineGuard (calc_state and calc_kinematics move them too).
  void moveTo(double t) const { evaluateModes(t); }
  /// An affine guard's value and its first two time derivatives at one instant.
  struct GuardValue
  {
    double value;
    double rate;
    double acceleration;
  };
  /// Value and time derivatives of an affine guard where the modes were last moved: a few products of the modes,
  /// far cheaper than the state and its kinematics, with the rate for the root finding. After affineGuardBounds
  /// (the search asks for the bounds first). Without Full, only the value and the rate (the root finding's).
  template <bool Full>
  GuardValue affineGuard(const AffineGuard& guard) const;
  /// Order of the Taylor expansions of affineGuardDerivatives: the derivatives below it are exact, the one of this
  /// order is bounded (GuardBounds::highest).
  static constexpr int TAYLOR_ORDER = 10;
  /// Bounds on an affine guard's time derivatives over the whole state.
  struct GuardBounds
  {
    double second;
    double third;
    double highest;  ///< of order TAYLOR_ORDER
  };
  /// Bounds on the affine guard's time derivatives over the whole state (from the modes' amplitudes): with its
  /// values and derivatives at both ends they prove an interval free of crossings (see AffineCrossingSearch).
  GuardBounds affineGuardBounds(const AffineGuard& guard) const;
  /// The affine guard's time derivatives of the orders 2 … TAYLOR_ORDER − 1 at t, into `derivatives` from index 2
  /// (the modes are moved to t). After affineGuardBounds.
  void affineGuardDerivatives(const AffineGuard& guard, double t, double* derivatives) const;
  /// Length of a step (a fixed fraction of the fastest period).
  double step() const { return step_; }
  /// The state at t with its kinematics, the forces read off the modes and the slip directions off their (fixed)
  /// carriers: what calc_state followed by evaluateKinematics gives, without the force law (guards are sampled, and
  /// their roots found, with it).
  void calc_kinematics(double t, OdeState& y, Kinematics& kinematics) const;

private:
  /// Collects the moving springs (rows and stiffnesses) and reads the force map G (F = G s_R) into force_from_s_.
  void readForceMap(const ContactSpace& space, const std::vector<ContactState>& contacts,
                    const ContactDynamics& dynamics);
  /// Whether every sliding contact keeps its direction; `any_sliding` tells if there is one.
  bool slidingDirectionsFixed(const ContactSpace& space, const std::vector<ContactState>& contacts,
                              const ContactDynamics& dynamics, const OdeState& y0, bool& any_sliding) const;
  /// Eigenvalues and orthonormal eigenvectors of symmetric_: one Jacobi rotation for up to two springs (the states
  /// of one or two contacts, most of a frictionless collision), Eigen's solver beyond.
  void diagonalise();
  /// Modal positions p and their time integrals ∫p at t, into position_ and integral_.
  void evaluateModes(double t) const;
  /// Rate of mode j at the instant of the modes: ṗ = ṗ0 − ω²∫p.
  double modalRate(Eigen::Index j) const { return modal_velocity_(j) - omega_(j) * omega_(j) * integral_(j); }
  /// Value, rate and acceleration of the relative velocity, the spring and the force of a row, from the modes
  /// (without Full, value and rate only).
  template <bool Full>
  GuardValue velocityAt(int row) const;
  template <bool Full>
  GuardValue springAt(int row) const;
  template <bool Full>
  GuardValue forceAt(int row) const;

  /// Adds the modes' part (in position_ and integral_) to a state that holds base_state_, and to the forces.
  void addModes(OdeState& y, double* force) const;

  const ContactDynamics* dynamics_ = nullptr;  ///< of the state built (the solver keeps it alive)
  const ContactSpace* space_ = nullptr;
  OdeState base_state_;  ///< the state at t0 with the moving springs at zero: what the modes add to
  double t0_ = 0.0;
  double t_ = 0.0;
  double step_ = 0.0;
  std::vector<int> moving_rows_;  ///< rows of s that change (compliant normals, sticking tangentials)
  std::vector<double> stiffness_;
  Eigen::VectorXd omega_;           ///< modal angular frequencies
  Eigen::VectorXd modal_position_;  ///< modal coordinates at t0
  Eigen::VectorXd modal_velocity_;
  Eigen::MatrixXd spring_from_modes_;                ///< s_R = K^{-1/2} Q p
  Eigen::MatrixXd force_from_modes_;                 ///< F = G K^{-1/2} Q p, so I − I0 = G K^{-1/2} Q ∫p
  mutable Eigen::MatrixXd velocity_from_integrals_;  ///< W G K^{-1/2} Q (w − w0 = W G K^{-1/2} Q ∫p), made on demand
  mutable bool velocity_map_made_ = false;
  /// Makes velocity_from_integrals_ once per state: only the affine search uses it.
  void makeVelocityMap() const;
  Eigen::VectorXd start_velocity_;  ///< w at t0

  // Scratch of build, kept for its storage.
  Eigen::MatrixXd force_from_s_;      ///< G
  Eigen::MatrixXd delassus_times_g_;  ///< W G
  Eigen::MatrixXd reduced_;           ///< (W Π)_RR
  Eigen::VectorXd sqrt_k_;
  Eigen::MatrixXd symmetric_;                                    ///< K^{1/2} (W Π)_RR K^{1/2}
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen_solver_;  ///< for three moving springs or more
  Eigen::VectorXd eigenvalues_;
  Eigen::MatrixXd eigenvectors_;  ///< Q
  OdeState probe_;
  Eigen::VectorXd probe_force_;
  SlipDirections probe_directions_;
  LagScratch probe_scratch_;
  bool any_sliding_ = false;                     ///< some contact slides in the state built
  SlipDirections directions_;                    ///< their (fixed) slip directions
  mutable Eigen::VectorXd position_, integral_;  ///< modes at the last evaluated instant
  mutable double modes_time_ = 0.0;              ///< that instant (NaN when they hold something else)
};

}  // namespace detail
}  // namespace billiard_shot_planner

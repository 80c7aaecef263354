#pragma once

#include <algorithm>
#include <functional>
#include <utility>

#include "contact_dynamics.hpp"
#include "dense_stepper.hpp"

namespace billiard_shot_planner
{
namespace detail
{
/// Integrates the spring dynamics on a clock u that slows down as sliding contacts approach separation.
///
/// Why: as a sliding contact separates, its spring length on the friction cone, ρ = μF_n/κ, falls linearly to zero
/// while its slip direction keeps turning toward the tangential velocity at up to |v_t|/ρ. The direction's lag then
/// behaves like τ^c, τ the time left and c = |v_t|τ/ρ (small in practice): a weak singularity that any fixed-order
/// method follows only with steps shrinking in proportion to τ, ten or more per decade of τ down to the separation
/// (two hundred of the massé strike's 260 steps). On the logarithmic clock dt/du = g = 1/(1 + Σρ̇/ρ) over the sliding
/// contacts in restitution (a Sundman transformation) τ ≈ e^{−u}, the lag ≈ e^{−cu} and every other state is smooth
/// in u, so the approach takes a few steps of order one. Time is carried as one more state.
///
/// Same interface as Odeint's dense-output steppers, in u: the solver samples its guards and finds their roots in
/// u, and asks timeAt(u) for the physical instant.
class SeparationClockStepper
{
public:
  SeparationClockStepper(const ContactDynamics& dynamics, double absolute_tolerance, double relative_tolerance)
      : system_{SpringSystem(dynamics)}, stepper_(absolute_tolerance, relative_tolerance)
  {
  }

  /// Starts at (y0, t0) with physical time t = u; the steps in u are unbounded (the solver subdivides long ones).
  void restart(const OdeState& y0, double t0, double first_step)
  {
    extended_.assign(y0.begin(), y0.end());
    extended_.push_back(t0);
    stepper_.restart(extended_, t0, 0.0, first_step);
  }

  template <class System>
  std::pair<double, double> do_step(System&& /*dynamics: the clocked system is used instead*/)
  {
    return stepper_.do_step(std::ref(system_));
  }

  void calc_state(double u, OdeState& y) const
  {
    stepper_.calc_state(u, extended_);
    std::copy(extended_.begin(), extended_.end() - 1, y.begin());
  }

  double timeAt(double u) const
  {
    stepper_.calc_state(u, extended_);
    return extended_.back();
  }

private:
  /// d[y, t]/du = g [f(y), 1].
  struct ClockedSystem
  {
    SpringSystem springs;
    void operator()(const OdeState& x, OdeState& dxdu, double /*u*/)
    {
      const double g = 1.0 / (1.0 + springs.rates(x.data(), dxdu.data()));
      for (std::size_t k = 0; k + 1 < x.size(); ++k)
        dxdu[k] *= g;
      dxdu.back() = g;
    }
  };

  ClockedSystem system_;
  DenseStepper stepper_;
  mutable OdeState extended_;
};

/// The physical time of a stepper's own clock: the identity except on the separation clock.
template <class Stepper>
double physicalTime(const Stepper& /*stepper*/, double t)
{
  return t;
}

inline double physicalTime(const SeparationClockStepper& stepper, double u)
{
  return stepper.timeAt(u);
}

}  // namespace detail
}  // namespace billiard_shot_planner

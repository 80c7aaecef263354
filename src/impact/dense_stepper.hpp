#pragma once

#include "fast_binomial.hpp"  // before Odeint

#include <boost/numeric/odeint.hpp>

#include "contact_dynamics.hpp"

namespace billiard_shot_planner
{
namespace detail
{
/// Bulirsch–Stoer extrapolation with dense output: between events the spring dynamics is smooth (analytic), so a
/// high-order method reaches 1e-12 in far fewer steps than a fifth-order Runge–Kutta.
///
/// Restartable without allocating: Odeint's stepper holds some 250 small vectors (its extrapolation tableau), and
/// constructing one per state cost up to a sixth of the massé strike. A restart keeps the tableau's storage and the
/// extrapolation order the last state settled on (Odeint offers no way to reset it; a fresh stepper starts at 4).
class DenseStepper : public boost::numeric::odeint::bulirsch_stoer_dense_out<OdeState>
{
  using Base = boost::numeric::odeint::bulirsch_stoer_dense_out<OdeState>;

public:
  /// The tolerances are fixed for the stepper's life; the step bound and first step are set at each restart.
  DenseStepper(double absolute_tolerance, double relative_tolerance)
      : Base(absolute_tolerance, relative_tolerance, 1.0, 1.0, 0.0, /*control_interpolation=*/true)
  {
  }

  /// Starts a new integration at (y0, t0) with steps bounded by max_step (0: unbounded). The state's size must
  /// stay the same (Odeint sizes its storage once).
  void restart(const OdeState& y0, double t0, double max_step, double first_step)
  {
    m_max_dt = max_step;
    initialize(y0, t0, first_step);
  }
};

}  // namespace detail
}  // namespace billiard_shot_planner

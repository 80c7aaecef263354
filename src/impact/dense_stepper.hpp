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
using DenseStepper = boost::numeric::odeint::bulirsch_stoer_dense_out<OdeState>;

/// Settings shared by the numerical steppers of one state.
struct IntegrationSettings
{
  double absolute_tolerance;
  double relative_tolerance;
  double max_step;
  double first_step;
};

inline DenseStepper makeDenseStepper(const IntegrationSettings& settings)
{
  return DenseStepper(settings.absolute_tolerance, settings.relative_tolerance, 1.0, 1.0, settings.max_step,
                      /*control_interpolation=*/true);
}

}  // namespace detail
}  // namespace billiard_shot_planner

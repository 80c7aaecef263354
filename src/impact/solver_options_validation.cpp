#include <limits>
#include <sstream>
#include <string>

#include "billiard_shot_planner/core/validation.hpp"
#include "billiard_shot_planner/impact/solver_options.hpp"

namespace billiard_shot_planner
{
namespace
{
/// Tolerances of 1e-2 and above would let the integrator step across whole contact phases; such results carry no
/// digit, so they are refused rather than computed.
constexpr double LOOSEST_TOLERANCE = 1e-2;

/// A value as written in the options (std::to_string would print a tolerance of 1e-20 as 0.000000).
std::string written(double value)
{
  std::ostringstream text;
  text << value;
  return text.str();
}

Status requireTolerance(double value, const std::string& field)
{
  if (!(value > 0.0 && value < LOOSEST_TOLERANCE))
    return invalidArgument(field, "must be in (0, 0.01), got " + written(value));
  return {};
}

/// A relative tolerance finer than a double's precision cannot be met: the integrator's steps would shrink until
/// it failed, after up to max_steps of them.
Status requireAttainable(double relative_tolerance, const std::string& field)
{
  const double precision = std::numeric_limits<double>::epsilon();
  if (relative_tolerance < precision)
    return invalidArgument(
        field, "must be at least a double's precision, " + written(precision) + ", got " + written(relative_tolerance));
  return {};
}

Status requireGrowth(double value, const std::string& field)
{
  if (!(value > 1.0))
    return invalidArgument(field, "must be > 1 (infinity: no cut by growth), got " + written(value));
  return {};
}

Status requireCount(std::size_t value, const std::string& field)
{
  if (value == 0)
    return invalidArgument(field, "must be > 0");
  return {};
}
}  // namespace

Status validate(const SolverOptions& options, const std::string& field)
{
  const std::string prefix = field + ".";
  return firstError({
      requireTolerance(options.relative_tolerance, prefix + "relative_tolerance"),
      requireAttainable(options.relative_tolerance, prefix + "relative_tolerance"),
      requireTolerance(options.absolute_tolerance, prefix + "absolute_tolerance"),
      requireNonNegative(options.chatter_energy_fraction, prefix + "chatter_energy_fraction"),
      requireGrowth(options.chatter_stiffness_growth, prefix + "chatter_stiffness_growth"),
      requireNonNegative(options.chatter_resolution, prefix + "chatter_resolution"),
      requireCount(options.max_events, prefix + "max_events"),
      requireCount(options.max_steps, prefix + "max_steps"),
  });
}

}  // namespace billiard_shot_planner

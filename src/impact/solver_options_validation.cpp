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

/// A relative tolerance finer than a double's precision cannot be met: the integrator's steps would shrink until
/// it failed, after up to max_steps of them.
constexpr double FINEST_RELATIVE_TOLERANCE = std::numeric_limits<double>::epsilon();

/// A value as written in the options (std::to_string would print a tolerance of 1e-20 as 0.000000).
std::string written(double value)
{
  std::ostringstream text;
  text << value;
  return text.str();
}

/// The options are checked at every solve: the messages, and the field names, are built only for a failed check.
class OptionCheck
{
public:
  explicit OptionCheck(const std::string& field) : field_(field) {}

  Status tolerance(double value, double finest, const char* option) const
  {
    if (value >= finest && value > 0.0 && value < LOOSEST_TOLERANCE)
      return {};
    const std::string range = finest > 0.0 ? "[" + written(finest) + ", " : "(0, ";
    return invalidArgument(name(option),
                           "must be in " + range + written(LOOSEST_TOLERANCE) + "), got " + written(value));
  }

  Status nonNegative(double value, const char* option) const
  {
    if (value >= 0.0 && value < std::numeric_limits<double>::infinity())
      return {};
    return invalidArgument(name(option), "must be finite and >= 0 (0: no such cut), got " + written(value));
  }

  Status growth(double value, const char* option) const
  {
    if (value > 1.0)
      return {};
    return invalidArgument(name(option), "must be > 1 (infinity: no cut by growth), got " + written(value));
  }

  Status count(std::size_t value, const char* option) const
  {
    if (value > 0)
      return {};
    return invalidArgument(name(option), "must be > 0");
  }

private:
  std::string name(const char* option) const { return field_ + "." + option; }

  const std::string& field_;
};
}  // namespace

Status validate(const SolverOptions& options, const std::string& field)
{
  const OptionCheck check(field);
  return firstError({
      check.tolerance(options.relative_tolerance, FINEST_RELATIVE_TOLERANCE, "relative_tolerance"),
      check.tolerance(options.absolute_tolerance, 0.0, "absolute_tolerance"),
      check.nonNegative(options.chatter_energy_fraction, "chatter_energy_fraction"),
      check.growth(options.chatter_stiffness_growth, "chatter_stiffness_growth"),
      check.nonNegative(options.chatter_resolution, "chatter_resolution"),
      check.count(options.max_events, "max_events"),
      check.count(options.max_steps, "max_steps"),
  });
}

}  // namespace billiard_shot_planner

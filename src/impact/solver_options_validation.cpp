#include <limits>
#include <string>

#include "billiard_shot_planner/core/validation.hpp"
#include "billiard_shot_planner/impact/solver_options.hpp"

namespace billiard_shot_planner
{
namespace
{
/// A relative tolerance finer than a double's precision cannot be met: the integrator's steps would shrink until
/// it failed, after up to max_steps of them. Coarser than 1e-3 the results carry no digit worth the name (at 1e-3,
/// 300 random strikes are within 1.1e-3 of the cue speed of the default's answer).
constexpr double FINEST_RELATIVE_TOLERANCE = std::numeric_limits<double>::epsilon();
constexpr double LOOSEST_RELATIVE_TOLERANCE = 1e-3;

/// The normalised state is of order one: an absolute tolerance below round-off cannot be met (at 1e-300 the
/// integrator's error norm overflowed into NaN), and above 1e-8 the cut of chattering contacts, 100 absolute
/// tolerances (chatter_resolution), drops energy that is not negligible: on 300 random strikes, none gains energy
/// up to 1e-8, one gains 10 % at 1e-6, and 51 gain up to ×5 at 0.009.
constexpr double FINEST_ABSOLUTE_TOLERANCE = 1e-16;  // the loosest: LOOSEST_ABSOLUTE_TOLERANCE (solver_options.hpp)

/// The longest wall-clock budget of one solve: a minute.
constexpr double MAX_SECONDS = 60.0;

/// The options are checked at every solve: the messages, and the field names, are built only for a failed check.
class OptionCheck
{
public:
  explicit OptionCheck(const std::string& field) : field_(field) {}

  Status tolerance(double value, double finest, double loosest, const char* option) const
  {
    if (value >= finest && value <= loosest)
      return {};
    return invalidArgument(name(option), "must be in [" + formatNumber(finest) + ", " + formatNumber(loosest) +
                                             "], got " + formatNumber(value));
  }

  Status nonNegative(double value, const char* option) const
  {
    if (value >= 0.0 && value < std::numeric_limits<double>::infinity())
      return {};
    return invalidArgument(name(option), "must be finite and >= 0 (0: no such cut), got " + formatNumber(value));
  }

  Status growth(double value, const char* option) const
  {
    if (value > 1.0)
      return {};
    return invalidArgument(name(option), "must be > 1 (infinity: no cut by growth), got " + formatNumber(value));
  }

  Status seconds(double value, const char* option) const
  {
    if (value > 0.0 && value <= MAX_SECONDS)
      return {};
    return invalidArgument(name(option),
                           "must be in (0, " + formatNumber(MAX_SECONDS) + "] s, got " + formatNumber(value));
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
      check.tolerance(options.relative_tolerance, FINEST_RELATIVE_TOLERANCE, LOOSEST_RELATIVE_TOLERANCE,
                      "relative_tolerance"),
      check.tolerance(options.absolute_tolerance, FINEST_ABSOLUTE_TOLERANCE, LOOSEST_ABSOLUTE_TOLERANCE,
                      "absolute_tolerance"),
      check.nonNegative(options.chatter_energy_fraction, "chatter_energy_fraction"),
      check.growth(options.chatter_stiffness_growth, "chatter_stiffness_growth"),
      check.nonNegative(options.chatter_resolution, "chatter_resolution"),
      check.count(options.max_events, "max_events"),
      check.count(options.max_steps, "max_steps"),
      check.seconds(options.max_seconds, "max_seconds"),
  });
}

}  // namespace billiard_shot_planner

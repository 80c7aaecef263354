#include "billiard_shot_planner/calibration/fit_parameter_bounds.hpp"

#include <limits>
#include <tuple>
#include <utility>

namespace billiard_shot_planner
{
namespace
{
constexpr double INF = std::numeric_limits<double>::infinity();

bool endsWith(const std::string& name, const std::string& suffix)
{
  return name.size() >= suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0;
}

/// A constant of no known kind that is positive may range over two decades either side of its start.
std::pair<double, double> boundsOf(const std::string& name, double start)
{
  if (endsWith(name, "restitution"))
    return {0.0, 1.0};
  if (endsWith(name, "friction"))
    return {0.0, 2.0};
  if (endsWith(name, "eta2"))
    return {0.05, 100.0};
  if (endsWith(name, "stiffness_ratio"))
    return {1e-3, 1e3};
  if (start > 0.0)
    return {start / 100.0, start * 100.0};
  return {-INF, INF};
}
}  // namespace

Expected<FitParameter> fitParameterFor(const ShotConfiguration& configuration, const std::string& name,
                                       const std::string& field)
{
  ShotConfiguration copy = configuration;  // numericParameters() points into the configuration it is given
  for (const NamedParameter& parameter : numericParameters(copy))
    if (name == parameter.name)
    {
      FitParameter fitted{name, *parameter.value, 0.0, 0.0};
      std::tie(fitted.lower, fitted.upper) = boundsOf(name, fitted.start);
      return fitted;
    }
  return invalidArgument(field, "is not the name of a physical parameter that can be fitted");
}

}  // namespace billiard_shot_planner

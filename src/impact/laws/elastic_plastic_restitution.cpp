#include "billiard_shot_planner/impact/laws/elastic_plastic_restitution.hpp"

#include <algorithm>
#include <cmath>

#include "billiard_shot_planner/core/validation.hpp"

namespace billiard_shot_planner
{
Status ElasticPlasticRestitution::validate(const std::string& field) const
{
  return requirePositive(yield_speed, field + ".yield_speed");
}

double ElasticPlasticRestitution::restitution(double low_speed_restitution, double impact_speed) const
{
  if (!(impact_speed > yield_speed))
    return low_speed_restitution;
  const double x = yield_speed / impact_speed;
  const double x2 = x * x;
  const double lead = std::sqrt(6.0 * std::sqrt(3.0) / 5.0);
  const double thornton =
      lead * std::sqrt(1.0 - x2 / 6.0) * std::pow(x / (x + 2.0 * std::sqrt(6.0 / 5.0 - x2 / 5.0)), 0.25);
  // The closed form is 1 at x = 1 up to round-off; the law never gives back more than the elastic contact would.
  return low_speed_restitution * std::min(thornton, 1.0);
}

}  // namespace billiard_shot_planner

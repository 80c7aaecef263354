#include "starting_points.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace billiard_shot_planner
{
namespace detail
{
namespace
{
/// k written in base `base`, its digits mirrored after the point: the Halton sequence's coordinate in that base.
double radicalInverse(int k, int base)
{
  double value = 0.0, digit_weight = 1.0 / base;
  for (; k > 0; k /= base, digit_weight /= base)
    value += (k % base) * digit_weight;
  return value;
}

int prime(std::size_t index)
{
  static constexpr std::array<int, 16> PRIMES = {2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41, 43, 47, 53};
  if (index < PRIMES.size())
    return PRIMES[index];
  int candidate = PRIMES.back();
  for (std::size_t found = PRIMES.size() - 1; found < index;)
  {
    candidate += 2;
    bool is_prime = true;
    for (int d = 3; d * d <= candidate && is_prime; d += 2)
      is_prime = candidate % d != 0;
    found += is_prime ? 1 : 0;
  }
  return candidate;
}

double spread(const FitParameter& parameter, double u)
{
  const double lo = parameter.lower, hi = parameter.upper;
  if (!std::isfinite(lo) || !std::isfinite(hi))
    return parameter.start;
  if (lo > 0.0 && hi > 10.0 * lo)
    return std::exp(std::log(lo) + u * (std::log(hi) - std::log(lo)));
  return lo + u * (hi - lo);
}
}  // namespace

std::vector<std::vector<double>> startingPoints(const std::vector<FitParameter>& parameters, int count)
{
  std::vector<std::vector<double>> points;
  std::vector<double> start(parameters.size());
  std::transform(parameters.begin(), parameters.end(), start.begin(), [](const FitParameter& p) { return p.start; });
  points.push_back(start);
  for (int k = 1; k < count; ++k)
  {
    std::vector<double> point;
    for (std::size_t i = 0; i < parameters.size(); ++i)
      point.push_back(spread(parameters[i], radicalInverse(k, prime(i))));
    points.push_back(point);
  }
  return points;
}

}  // namespace detail
}  // namespace billiard_shot_planner

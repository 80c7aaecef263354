#pragma once

// Boost 1.74 (Debian 12) computes binomial_coefficient<double> from a constexpr table of 171 long double
// factorials that is a local variable of unchecked_factorial<long double>, so every call copies the whole table
// onto the stack. Odeint's Bulirsch–Stoer dense output asks for a few dozen binomial coefficients per step:
// measured with perf, a quarter of the time of an impact with sliding contacts (the massé strike). Boost itself
// specialises this function for float; this does it for double with the product formula, exact where Odeint uses
// it (n ≤ 30: every intermediate value is an integer below 2^53). Include before Boost.Math and Odeint, in the
// one file using them.
#include <boost/math/policies/policy.hpp>
#include <boost/math/special_functions/math_fwd.hpp>

namespace boost
{
namespace math
{
template <>
inline double binomial_coefficient<double, policies::policy<>>(unsigned n, unsigned k, const policies::policy<>&)
{
  if (k > n || n > 30)  // Boost's own algorithm (and its domain error for k > n), reached through another policy
    return binomial_coefficient<double>(n, k, policies::policy<policies::promote_double<false>>());
  k = k < n - k ? k : n - k;
  double result = 1.0;
  for (unsigned i = 1; i <= k; ++i)
    result = result * static_cast<double>(n - k + i) / static_cast<double>(i);  // C(n−k+i, i) at each step
  return result;
}
}  // namespace math
}  // namespace boost

#include <boost/math/special_functions/binomial.hpp>  // after the specialisation, which its float version uses

// The double binomial coefficients that replace Boost 1.74's slow ones in Odeint's dense output
// (src/impact/fast_binomial.hpp): exactly Pascal's triangle where Odeint uses them, Boost's own answers elsewhere.
#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "../../src/impact/fast_binomial.hpp"

TEST(FastBinomial, ExactlyPascalsTriangleUpToThirty)
{
  std::vector<double> row{1.0};
  for (unsigned n = 1; n <= 30; ++n)
  {
    std::vector<double> next(n + 1, 1.0);
    for (unsigned k = 1; k < n; ++k)
      next[k] = row[k - 1] + row[k];
    row = next;
    for (unsigned k = 0; k <= n; ++k)
      EXPECT_EQ(boost::math::binomial_coefficient<double>(n, k), row[k]) << n << " choose " << k;
  }
}

TEST(FastBinomial, OutsideItsRangeBoostAnswers)
{
  EXPECT_NEAR(boost::math::binomial_coefficient<double>(40, 20), 137846528820.0, 1.0);
  EXPECT_THROW(boost::math::binomial_coefficient<double>(3, 5), std::domain_error);
}

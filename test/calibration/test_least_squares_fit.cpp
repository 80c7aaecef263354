// The fitter against linear least squares, whose optimum and covariance have a closed form: the normal equations.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>

#include "billiard_shot_planner/calibration/least_squares_fit.hpp"

namespace bsp = billiard_shot_planner;

namespace
{
/// Observations y_k = 0.3 + 1.7 x_k − 0.4 x_k² + noise of σ = 0.05 at x_k = k/10.
struct Quadratic
{
  Eigen::VectorXd x, y;
  double sigma = 0.05;

  explicit Quadratic(unsigned seed, int count = 30)
  {
    std::mt19937 rng(seed);
    std::normal_distribution<double> noise(0.0, sigma);
    x = Eigen::VectorXd::LinSpaced(count, 0.0, 0.1 * (count - 1));
    y = (0.3 + 1.7 * x.array() - 0.4 * x.array().square()).matrix();
    for (Eigen::Index k = 0; k < y.size(); ++k)
      y(k) += noise(rng);
  }

  Eigen::MatrixXd design() const
  {
    Eigen::MatrixXd a(x.size(), 3);
    a.col(0).setOnes();
    a.col(1) = x;
    a.col(2) = x.array().square().matrix();
    return a / sigma;
  }
};
}  // namespace

TEST(LeastSquaresFit, AgreesWithTheNormalEquationsOnALinearModel)
{
  const Quadratic data(7);
  const bsp::ResidualFunction residuals = [&](const std::vector<double>& p, Eigen::VectorXd& r)
  {
    r = ((p[0] + p[1] * data.x.array() + p[2] * data.x.array().square()).matrix() - data.y) / data.sigma;
    return true;
  };
  const auto fit = bsp::fitLeastSquares({{"c0", 1.0, -10.0, 10.0}, {"c1", 1.0, -10.0, 10.0}, {"c2", 1.0, -10.0, 10.0}},
                                        static_cast<int>(data.x.size()), residuals);
  ASSERT_TRUE(fit.ok()) << fit.error().describe();
  const Eigen::MatrixXd a = data.design();
  const Eigen::VectorXd best = (a.transpose() * a).ldlt().solve(a.transpose() * data.y / data.sigma);
  const Eigen::MatrixXd covariance = (a.transpose() * a).inverse();
  EXPECT_TRUE(fit->converged) << fit->message;
  for (int i = 0; i < 3; ++i)
  {
    const bsp::FittedParameter& p = fit->parameters[i];
    EXPECT_TRUE(p.identifiable) << p.name;
    EXPECT_NEAR(p.value, best(i), 1e-3 * std::sqrt(covariance(i, i))) << p.name;
    EXPECT_NEAR(p.sigma, std::sqrt(covariance(i, i)), 1e-4 * std::sqrt(covariance(i, i))) << p.name;
    for (int j = 0; j < 3; ++j)
      EXPECT_NEAR(fit->correlation(i, j), covariance(i, j) / std::sqrt(covariance(i, i) * covariance(j, j)), 1e-4);
  }
}

TEST(LeastSquaresFit, OneSigmaHoldsTheTruthTwoThirdsOfTheTime)
{
  // Over 200 data sets, |fit − truth| ≤ σ for 68.3 % of the estimates: 600 Bernoulli trials, ±3 standard deviations
  // (±5.7 %) around it.
  int within = 0, total = 0;
  const double truth[] = {0.3, 1.7, -0.4};
  for (unsigned seed = 0; seed < 200; ++seed)
  {
    const Quadratic data(seed, 12);
    const bsp::ResidualFunction residuals = [&](const std::vector<double>& p, Eigen::VectorXd& r)
    {
      r = ((p[0] + p[1] * data.x.array() + p[2] * data.x.array().square()).matrix() - data.y) / data.sigma;
      return true;
    };
    const auto fit = bsp::fitLeastSquares({{"c0", 0.0}, {"c1", 0.0}, {"c2", 0.0}}, 12, residuals);
    ASSERT_TRUE(fit.ok()) << fit.error().describe();
    for (int i = 0; i < 3; ++i, ++total)
      within += std::abs(fit->parameters[i].value - truth[i]) <= fit->parameters[i].sigma;
  }
  EXPECT_NEAR(static_cast<double>(within) / total, 0.683, 0.057);
}

// A residual that jumps by 30 σ just beyond the optimum, within the difference step (as a track does when a
// constant decides whether a ball catches a jaw): the central difference spans the jump and would claim a σ some
// 10⁵ times too small. σ comes from the smooth side instead: the normal equations' σ, exactly for a linear model.
TEST(LeastSquaresFit, ASigmaIsNotTakenAcrossAJumpInTheResiduals)
{
  const Quadratic data(7);
  const Eigen::MatrixXd a = data.design();
  const Eigen::VectorXd best = (a.transpose() * a).ldlt().solve(a.transpose() * data.y / data.sigma);
  const Eigen::MatrixXd covariance = (a.transpose() * a).inverse();
  const bsp::FitOptions options;
  const double jump = best(0) + 0.3 * options.relative_step * std::abs(best(0));
  const int n = static_cast<int>(data.x.size());
  const bsp::ResidualFunction residuals = [&](const std::vector<double>& p, Eigen::VectorXd& r)
  {
    r.resize(n + 1);
    r.head(n) = ((p[0] + p[1] * data.x.array() + p[2] * data.x.array().square()).matrix() - data.y) / data.sigma;
    r(n) = p[0] > jump ? 30.0 : 0.0;
    return true;
  };
  const auto fit = bsp::fitLeastSquares({{"c0", 1.0, -10.0, 10.0}, {"c1", 1.0, -10.0, 10.0}, {"c2", 1.0, -10.0, 10.0}},
                                        n + 1, residuals, options);
  ASSERT_TRUE(fit.ok()) << fit.error().describe();
  ASSERT_LT(fit->parameters[0].value, jump);
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(fit->parameters[i].sigma, std::sqrt(covariance(i, i)), 1e-3 * std::sqrt(covariance(i, i)))
        << fit->parameters[i].name;
  EXPECT_NE(fit->message.find("jump within the difference step of c0"), std::string::npos) << fit->message;
  EXPECT_EQ(fit->message.find("of c1"), std::string::npos) << fit->message;
}

TEST(LeastSquaresFit, ParametersTheDataCannotSeparateAreReportedNotFitted)
{
  // y depends on a + b only: one of them is undetermined, and stays at its start; the other one carries the sum.
  // A third parameter the residuals ignore altogether is undetermined too.
  const Quadratic data(3);
  const bsp::ResidualFunction residuals = [&](const std::vector<double>& p, Eigen::VectorXd& r)
  {
    r = ((p[0] + p[1] + p[2] * data.x.array()).matrix() - data.y) / data.sigma;
    return true;
  };
  const auto fit = bsp::fitLeastSquares(
      {{"a", 0.2, -10.0, 10.0}, {"b", 0.1, -10.0, 10.0}, {"slope", 1.0}, {"unused", 5.0, 0.0, 10.0}},
      static_cast<int>(data.x.size()),
      [&](const std::vector<double>& p, Eigen::VectorXd& r) {
        return residuals({p[0], p[1], p[2]}, r);
      });
  ASSERT_TRUE(fit.ok()) << fit.error().describe();
  const auto& p = fit->parameters;
  EXPECT_NE(p[0].identifiable, p[1].identifiable);
  const bsp::FittedParameter& held = p[0].identifiable ? p[1] : p[0];
  EXPECT_EQ(held.value, held.name == "a" ? 0.2 : 0.1);
  EXPECT_TRUE(std::isinf(held.sigma));
  EXPECT_TRUE(p[2].identifiable);
  EXPECT_FALSE(p[3].identifiable);
  EXPECT_EQ(p[3].value, 5.0);
  // The sum and slope are the straight line's least-squares fit.
  Eigen::MatrixXd a(data.x.size(), 2);
  a.col(0).setOnes();
  a.col(1) = data.x;
  const Eigen::VectorXd line = (a.transpose() * a).ldlt().solve(a.transpose() * data.y);
  EXPECT_NEAR(p[0].value + p[1].value, line(0), 1e-6);
  EXPECT_NEAR(p[2].value, line(1), 1e-6);
}

TEST(LeastSquaresFit, DataThatDetermineNothingLeaveEveryParameterAtItsStart)
{
  // Residuals that no parameter moves: none is identifiable, each keeps its start with an infinite σ. (The fuzzer
  // found a calibrate input whose four track points determined neither of its two parameters: the covariance of no
  // parameter at all asked Eigen for the SVD of an empty matrix.)
  const Quadratic data(4);
  const auto fit =
      bsp::fitLeastSquares({{"a", 0.2, -10.0, 10.0}, {"b", 3.0, 0.0, 10.0}}, static_cast<int>(data.x.size()),
                           [&](const std::vector<double>&, Eigen::VectorXd& r)
                           {
                             r = data.y / data.sigma;
                             return true;
                           });
  ASSERT_TRUE(fit.ok()) << fit.error().describe();
  for (const bsp::FittedParameter& p : fit->parameters)
  {
    EXPECT_FALSE(p.identifiable) << p.name;
    EXPECT_TRUE(std::isinf(p.sigma)) << p.name;
  }
  EXPECT_EQ(fit->parameters[0].value, 0.2);
  EXPECT_EQ(fit->parameters[1].value, 3.0);
  EXPECT_TRUE(std::isnan(fit->correlation(0, 1)));
}

TEST(LeastSquaresFit, BoundsHoldAndAreReported)
{
  const Quadratic data(5);
  const bsp::ResidualFunction residuals = [&](const std::vector<double>& p, Eigen::VectorXd& r)
  {
    r = ((p[0] + p[1] * data.x.array()).matrix() - data.y) / data.sigma;
    return true;
  };
  const auto fit =
      bsp::fitLeastSquares({{"c0", 0.5, 0.0, 0.6}, {"c1", 1.0, 0.0, 5.0}}, static_cast<int>(data.x.size()), residuals);
  ASSERT_TRUE(fit.ok()) << fit.error().describe();
  // A line fitted to the concave quadratic on [0, L] (L = 2.9) crosses x = 0 at 0.3 + 0.4 L²/6 = 0.86: the bound 0.6
  // holds it.
  EXPECT_EQ(fit->parameters[0].value, 0.6);
  EXPECT_TRUE(fit->parameters[0].at_bound);
  EXPECT_FALSE(fit->parameters[1].at_bound);
}

TEST(LeastSquaresFit, BadInputIsRefusedNamingTheField)
{
  const bsp::ResidualFunction zero = [](const std::vector<double>&, Eigen::VectorXd& r)
  {
    r = Eigen::VectorXd::Zero(4);
    return true;
  };
  const auto field = [&](const std::vector<bsp::FitParameter>& parameters, int count)
  {
    const auto fit = bsp::fitLeastSquares(parameters, count, zero);
    return fit.ok() ? std::string("accepted") : fit.error().field;
  };
  EXPECT_EQ(field({{"a", NAN}}, 4), "a");
  EXPECT_EQ(field({{"a", 0.0, 1.0, -1.0}}, 4), "a");
  EXPECT_EQ(field({{"a", 2.0, 0.0, 1.0}}, 4), "a");
  EXPECT_EQ(field({{"a", 0.0}, {"a", 1.0}}, 4), "a");
  EXPECT_EQ(field({{"", 0.0}}, 4), "parameters[0]");
  EXPECT_EQ(field({}, 4), "parameters");
  EXPECT_EQ(field({{"a", 0.0}, {"b", 0.0}, {"c", 0.0}}, 2), "residual_count");
  // Each option is named by its own field, for the front ends to map to theirs.
  const std::pair<void (*)(bsp::FitOptions&), const char*> options[] = {
      {[](bsp::FitOptions& o) { o.starts = 0; }, "starts"},
      {[](bsp::FitOptions& o) { o.starts = bsp::MAX_FIT_STARTS + 1; }, "starts"},
      {[](bsp::FitOptions& o) { o.threads = bsp::MAX_FIT_THREADS + 1; }, "threads"},
      {[](bsp::FitOptions& o) { o.max_seconds = 0.0; }, "max_seconds"},
      {[](bsp::FitOptions& o) { o.max_seconds = NAN; }, "max_seconds"},
      {[](bsp::FitOptions& o) { o.robust_loss_sigmas = -1.0; }, "robust_loss_sigmas"},
      {[](bsp::FitOptions& o) { o.identifiable_relative_sigma = 0.0; }, "identifiable_relative_sigma"},
      {[](bsp::FitOptions& o) { o.max_iterations = 0; }, "max_iterations"},
      {[](bsp::FitOptions& o) { o.relative_step = 0.5; }, "relative_step"},
  };
  for (const auto& [spoil, name] : options)
  {
    bsp::FitOptions spoilt;
    spoil(spoilt);
    const auto fit = bsp::fitLeastSquares({{"a", 0.0}}, 4, zero, spoilt);
    ASSERT_FALSE(fit.ok()) << name;
    EXPECT_EQ(fit.error().field, name);
  }
  const auto failing =
      bsp::fitLeastSquares({{"a", 0.0}}, 4, [](const std::vector<double>&, Eigen::VectorXd&) { return false; });
  ASSERT_FALSE(failing.ok());
  EXPECT_EQ(failing.error().code, bsp::ErrorKind::NumericalFailure);
}

// A fit reports each iteration and stops when asked, with the best point so far: the exponential decay
// y = 2 exp(-1.5 x) fitted from (1, 0.2) takes several iterations, each no worse than the one before (the
// Levenberg–Marquardt iterate moves only on a step that lowers the cost); stopped after its second report, no other
// starting point is tried and the answer is that report's point, not converged.
TEST(LeastSquaresFit, ReportsEachIterationAndStopsWithTheBestPointSoFar)
{
  const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(40, 0.0, 3.9);
  const Eigen::VectorXd y = (2.0 * (-1.5 * x.array()).exp()).matrix();
  const bsp::ResidualFunction residuals = [&](const std::vector<double>& p, Eigen::VectorXd& r)
  {
    r = ((p[0] * (-p[1] * x.array()).exp()).matrix() - y) / 0.01;
    return true;
  };
  const std::vector<bsp::FitParameter> parameters = {{"amplitude", 1.0, 0.0, 10.0}, {"rate", 0.2, 0.0, 10.0}};
  bsp::FitOptions options;
  options.starts = 8;
  std::vector<bsp::FitProgress> reports;
  options.progress = [&](const bsp::FitProgress& progress) { reports.push_back(progress); };
  const auto whole = bsp::fitLeastSquares(parameters, static_cast<int>(x.size()), residuals, options);
  ASSERT_TRUE(whole.ok()) << whole.error().describe();
  EXPECT_TRUE(whole->converged) << whole->message;
  ASSERT_GE(reports.size(), 3u);
  for (std::size_t k = 1; k < reports.size(); ++k)
  {
    if (reports[k].local_fits == reports[k - 1].local_fits)
    {
      EXPECT_LE(reports[k].cost, reports[k - 1].cost * (1.0 + 1e-12)) << k;
    }
  }
  EXPECT_NEAR(whole->parameters[1].value, 1.5, 1e-6);

  reports.clear();
  options.stop = [&] { return reports.size() >= 2; };
  const auto stopped = bsp::fitLeastSquares(parameters, static_cast<int>(x.size()), residuals, options);
  ASSERT_TRUE(stopped.ok()) << stopped.error().describe();
  EXPECT_FALSE(stopped->converged);
  EXPECT_EQ(stopped->message.rfind("stopped on request", 0), 0u) << stopped->message;
  ASSERT_EQ(reports.size(), 2u);
  EXPECT_EQ(reports.back().local_fits, 1);
  EXPECT_NEAR(stopped->final_cost, reports.back().cost, 1e-9 * reports.back().cost);
  EXPECT_GT(stopped->final_cost, whole->final_cost);
}

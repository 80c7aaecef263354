#include "parameter_sensitivity.hpp"

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace billiard_shot_planner
{
namespace detail
{
namespace
{
constexpr double INFINITE = std::numeric_limits<double>::infinity();

/// Columns `columns` of J, each multiplied by its scale.
Eigen::MatrixXd scaledColumns(const Eigen::MatrixXd& jacobian, const std::vector<int>& columns,
                              const std::vector<double>& scales)
{
  Eigen::MatrixXd scaled(jacobian.rows(), static_cast<Eigen::Index>(columns.size()));
  for (std::size_t k = 0; k < columns.size(); ++k)
    scaled.col(static_cast<Eigen::Index>(k)) = jacobian.col(columns[k]) * scales[columns[k]];
  return scaled;
}

/// (JᵀJ)⁻¹ through J's singular values; a parameter with a part in the null space (a singular value below round-off
/// of the largest) gets an infinite variance.
Eigen::MatrixXd inverseNormalMatrix(const Eigen::MatrixXd& jacobian)
{
  const Eigen::Index n = jacobian.cols();
  if (n == 0 || jacobian.rows() == 0)
  {
    // No parameter, or no residual: nothing is determined (and Eigen's SVD needs a matrix with entries).
    Eigen::MatrixXd inverse = Eigen::MatrixXd::Zero(n, n);
    inverse.diagonal().setConstant(INFINITE);
    return inverse;
  }
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(jacobian, Eigen::ComputeFullV);
  const Eigen::VectorXd& singular = svd.singularValues();
  const double largest = singular.size() > 0 ? singular(0) : 0.0;
  const double round_off = 1e-12 * largest * static_cast<double>(std::max(jacobian.rows(), n));
  Eigen::MatrixXd inverse = Eigen::MatrixXd::Zero(n, n);
  std::vector<bool> undetermined(static_cast<std::size_t>(n), false);
  for (Eigen::Index k = 0; k < n; ++k)
  {
    const Eigen::VectorXd direction = svd.matrixV().col(k);
    const double value = k < singular.size() ? singular(k) : 0.0;
    if (value > round_off && largest > 0.0)
    {
      inverse += direction * direction.transpose() / (value * value);
      continue;
    }
    for (Eigen::Index j = 0; j < n; ++j)
      if (std::abs(direction(j)) > 1e-9)
        undetermined[static_cast<std::size_t>(j)] = true;
  }
  for (Eigen::Index j = 0; j < n; ++j)
    if (undetermined[static_cast<std::size_t>(j)])
      inverse(j, j) = INFINITE;
  return inverse;
}
}  // namespace

std::vector<double> parameterScales(const std::vector<FitParameter>& parameters, const std::vector<double>& values)
{
  std::vector<double> scales;
  for (std::size_t i = 0; i < parameters.size(); ++i)
  {
    const double width = parameters[i].upper - parameters[i].lower;
    scales.push_back(values[i] != 0.0 ? std::abs(values[i]) : std::isfinite(width) && width > 0.0 ? 0.5 * width : 1.0);
  }
  return scales;
}

std::vector<int> identifiableParameters(const Eigen::MatrixXd& jacobian, const std::vector<double>& scales,
                                        double threshold, std::vector<int> candidates)
{
  if (candidates.empty())
  {
    candidates.resize(static_cast<std::size_t>(jacobian.cols()));
    std::iota(candidates.begin(), candidates.end(), 0);
  }
  while (!candidates.empty())
  {
    const Eigen::VectorXd relative_variance =
        inverseNormalMatrix(scaledColumns(jacobian, candidates, scales)).diagonal();
    Eigen::Index worst = 0;
    if (relative_variance.maxCoeff(&worst) <= threshold * threshold)
      break;
    candidates.erase(candidates.begin() + worst);
  }
  return candidates;
}

Covariance::Covariance(const Eigen::MatrixXd& covariance, std::vector<int> free)
    : covariance_(covariance), free_(std::move(free))
{
}

int Covariance::indexOf(int parameter) const
{
  const auto at = std::find(free_.begin(), free_.end(), parameter);
  return at == free_.end() ? -1 : static_cast<int>(at - free_.begin());
}

double Covariance::sigma(int parameter) const
{
  const int k = indexOf(parameter);
  return k < 0 ? INFINITE : std::sqrt(covariance_(k, k));
}

double Covariance::correlation(int a, int b) const
{
  const int i = indexOf(a), j = indexOf(b);
  if (i < 0 || j < 0)
    return std::numeric_limits<double>::quiet_NaN();
  return covariance_(i, j) / std::sqrt(covariance_(i, i) * covariance_(j, j));
}

Covariance covarianceOf(const Eigen::MatrixXd& jacobian, const std::vector<int>& free)
{
  // Scaled to unit columns first, so that parameters of very different sizes do not spoil the decomposition.
  std::vector<double> norms(static_cast<std::size_t>(jacobian.cols()), 1.0);
  for (int j : free)
    norms[static_cast<std::size_t>(j)] = jacobian.col(j).norm() > 0.0 ? 1.0 / jacobian.col(j).norm() : 1.0;
  const Eigen::MatrixXd scaled = inverseNormalMatrix(scaledColumns(jacobian, free, norms));
  Eigen::MatrixXd covariance(scaled.rows(), scaled.cols());
  for (Eigen::Index i = 0; i < scaled.rows(); ++i)
    for (Eigen::Index j = 0; j < scaled.cols(); ++j)
      covariance(i, j) = scaled(i, j) * norms[free[i]] * norms[free[j]];
  return Covariance(covariance, free);
}

}  // namespace detail
}  // namespace billiard_shot_planner

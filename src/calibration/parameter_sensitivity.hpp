#pragma once

#include <Eigen/Core>
#include <vector>

#include "billiard_shot_planner/calibration/least_squares_fit.hpp"

namespace billiard_shot_planner
{
namespace detail
{
/// The size each parameter's uncertainty is measured against: |value|, or half its bounds' width at zero, or 1 when
/// those are infinite.
std::vector<double> parameterScales(const std::vector<FitParameter>& parameters, const std::vector<double>& values);

/// Of `candidates` (all the Jacobian's columns when empty), those the residuals determine: the one least determined
/// (largest standard deviation relative to its scale, from (JᵀJ)⁻¹) is dropped while it exceeds `threshold`, and
/// the rest examined again without it. A direction in the Jacobian's null space is undetermined.
std::vector<int> identifiableParameters(const Eigen::MatrixXd& jacobian, const std::vector<double>& scales,
                                        double threshold, std::vector<int> candidates = {});

/// (JᵀJ)⁻¹ of the residuals in standard deviations, over the columns `free`: the parameters' covariance at a
/// least-squares optimum. The others have infinite σ and no correlation (NaN).
class Covariance
{
public:
  Covariance(const Eigen::MatrixXd& covariance, std::vector<int> free);
  double sigma(int parameter) const;
  double correlation(int a, int b) const;

private:
  /// Position of a parameter among the free ones, or −1.
  int indexOf(int parameter) const;

  Eigen::MatrixXd covariance_;
  std::vector<int> free_;
};

Covariance covarianceOf(const Eigen::MatrixXd& jacobian, const std::vector<int>& free);

}  // namespace detail
}  // namespace billiard_shot_planner

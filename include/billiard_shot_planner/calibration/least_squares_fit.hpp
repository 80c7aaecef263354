#pragma once

#include <Eigen/Core>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "billiard_shot_planner/core/expected.hpp"

namespace billiard_shot_planner
{
/// One unknown of a fit: its name, where the search starts and the bounds physics puts on it.
struct FitParameter
{
  std::string name;
  double start = 0.0;
  double lower = -std::numeric_limits<double>::infinity();
  double upper = std::numeric_limits<double>::infinity();
};

/// Where a fit is, for a caller that reports it (FitOptions::progress).
struct FitProgress
{
  int local_fits = 0;  ///< local fits begun so far (each from one starting point)
  int iterations = 0;  ///< of the current local fit
  double cost = 0.0;   ///< ½ Σ r² of the current local fit's iterate, residuals in standard deviations
  double best_cost = std::numeric_limits<double>::infinity();  ///< of the best local fit ended so far
  double seconds = 0.0;                                        ///< since the fit began
};

/// How a fit searches and what it calls determined.
struct FitOptions
{
  /// A parameter is identifiable when the data pin it to better than this fraction of its own size (its standard
  /// deviation over max(|value|, scale)); the others are held at their start and reported as not identifiable.
  double identifiable_relative_sigma = 0.5;
  /// Huber's loss beyond this many standard deviations (outliers count linearly); 0 for plain least squares.
  double robust_loss_sigmas = 0.0;
  /// Points the search may start from: the parameters' own start and starts − 1 more spread over the bounds (a
  /// Halton sequence, on a log scale where a positive range spans more than a factor of ten; a parameter with an
  /// infinite bound keeps its start). The local fit runs from the best few by cost, and the best end is the answer:
  /// the residuals of an impact are not convex in its constants. When the best end does not explain the data (its
  /// χ² far above its degrees of freedom, FitResult::explains_data), the search goes on from at least
  /// ESCALATED_STARTS points within the budget.
  int starts = 1;
  /// Whether a fit that does not explain its data searches on from ESCALATED_STARTS points (above). False: the
  /// answer is the best end of `starts` local fits, however far it leaves the data (a quick look, or a study of the
  /// local minima themselves).
  bool escalate = true;
  int max_iterations = 50;  ///< of each local fit
  /// Threads that evaluate the residual blocks side by side (fitLeastSquares with blocks), at most 64.
  int threads = 1;
  /// Wall-clock budget of the whole fit, s, in (0, 3600]: past it no new start is tried and the local fit stops, and
  /// the best point so far is the answer (converged false).
  double max_seconds = 60.0;
  /// Central differences with this step relative to max(|value|, scale): the residuals come from an integration
  /// with its own tolerance, so the step stays well above it.
  double relative_step = 1e-4;
  /// Asked between the fit's steps: true ends it as a spent budget does, with the best point so far (converged
  /// false; an action's preemption). Empty: never.
  std::function<bool()> stop;
  /// Called after each iteration of a local fit (an action's feedback), on the fitting thread. Empty: not called.
  std::function<void(const FitProgress&)> progress;
};

/// The starting points a fit that does not explain its data searches from at least (FitOptions::starts).
constexpr int ESCALATED_STARTS = 32;
/// The bounds of FitOptions that validate() holds.
constexpr int MAX_FIT_STARTS = 10000;
constexpr int MAX_FIT_THREADS = 64;
constexpr double MAX_FIT_SECONDS = 3600.0;

/// The options checked, each error naming its own field ("starts", "threads", "max_seconds",
/// "robust_loss_sigmas", "identifiable_relative_sigma", "max_iterations", "relative_step"): the one check every
/// front end relies on, mapping the names to its own ("budget_ms").
Status validate(const FitOptions& options);

struct FittedParameter
{
  std::string name;
  double value = 0.0;
  /// Standard deviation from the curvature of the fit, (JᵀJ)⁻¹ with the residuals in standard deviations, times
  /// √(χ²/dof) where the fit does not explain the data (FitResult::explains_data false: the precision the curvature
  /// claims is scaled to what the residuals show, Birge's ratio); infinite for a parameter that is not identifiable.
  double sigma = std::numeric_limits<double>::infinity();
  bool identifiable = false;
  bool at_bound = false;  ///< the best point lies on one of its bounds
};

struct FitResult
{
  std::vector<FittedParameter> parameters;  ///< in the order asked
  /// Correlations of the identifiable parameters (rows and columns in the order asked, NaN for the others).
  Eigen::MatrixXd correlation;
  Eigen::VectorXd residuals;   ///< at the best point, in standard deviations
  double initial_cost = 0.0;   ///< ½ Σ r² at the start
  double final_cost = 0.0;     ///< ½ Σ r² at the best point
  int degrees_of_freedom = 0;  ///< residuals less the parameters fitted
  double chi2_per_dof = 0.0;   ///< Σ r² / degrees_of_freedom: about 1 when the model explains the data to their noise
  /// Σ r² lies within three standard deviations of a χ² of degrees_of_freedom (dof + 3√(2 dof)): the fit explains
  /// the data as well as their noise allows. False: the best point found still leaves residuals the noise does not
  /// (a model or a start that does not fit; the message says so).
  bool explains_data = false;
  bool converged = false;
  std::string message;  ///< the optimiser's report in one line
  int iterations = 0;
};

/// The residuals of a fit at given parameter values, each in standard deviations of its observation (so that
/// Σ r² is a χ²). Returns false where the model cannot be evaluated (the point is then refused).
using ResidualFunction = std::function<bool(const std::vector<double>& values, Eigen::VectorXd& residuals)>;

/// A group of residuals computed together (one observed shot's, say): how many, and the function that computes
/// them. Blocks may be evaluated on different threads at once: each function must allow that.
struct ResidualBlock
{
  int count = 0;
  ResidualFunction residuals;
};

/// Bounded nonlinear least squares (Ceres' trust region, central differences) from one or several starts. A
/// parameter the curvature at the best point leaves undetermined (FitOptions::identifiable_relative_sigma) goes back
/// to its start and the others are fitted again; each value is reported with its standard deviation and the
/// correlations. Errors: InvalidArgument naming the parameter (NaN, lower > upper, start outside its bounds,
/// duplicate name) or `residual_count` (fewer residuals than parameters), NumericalFailure when the residuals
/// cannot be evaluated at the start.
Expected<FitResult> fitLeastSquares(const std::vector<FitParameter>& parameters, int residual_count,
                                    const ResidualFunction& residuals, const FitOptions& options = {});

/// The same over residual blocks, their residuals in the order of the blocks; also InvalidArgument naming a block
/// ("blocks[2]") without residuals or function.
Expected<FitResult> fitLeastSquares(const std::vector<FitParameter>& parameters,
                                    const std::vector<ResidualBlock>& blocks, const FitOptions& options = {});

}  // namespace billiard_shot_planner

#include "billiard_shot_planner/calibration/least_squares_fit.hpp"

#include <ceres/ceres.h>

#include <Eigen/SVD>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <set>
#include <string>

#include "billiard_shot_planner/core/validation.hpp"
#include "parameter_sensitivity.hpp"
#include "starting_points.hpp"

namespace billiard_shot_planner
{
namespace
{
/// The user's residual function as Ceres' dynamic cost functor over one block of all the parameters.
class ResidualFunctor
{
public:
  ResidualFunctor(const ResidualFunction& residuals, int parameter_count, int residual_count)
      : residuals_(residuals), values_(static_cast<std::size_t>(parameter_count)), residual_count_(residual_count)
  {
  }

  bool operator()(double const* const* parameters, double* out) const
  {
    std::copy(parameters[0], parameters[0] + values_.size(), values_.begin());
    if (!residuals_(values_, scratch_) || scratch_.size() != residual_count_ || !scratch_.allFinite())
      return false;
    std::copy(scratch_.data(), scratch_.data() + residual_count_, out);
    return true;
  }

private:
  const ResidualFunction& residuals_;
  mutable std::vector<double> values_;
  mutable Eigen::VectorXd scratch_;
  int residual_count_;
};

using CostFunction = ceres::DynamicNumericDiffCostFunction<ResidualFunctor, ceres::CENTRAL>;

std::unique_ptr<CostFunction> makeCost(const ResidualFunction& residuals, int parameter_count, int residual_count,
                                       const FitOptions& options)
{
  ceres::NumericDiffOptions difference;
  difference.relative_step_size = options.relative_step;
  auto cost = std::make_unique<CostFunction>(new ResidualFunctor(residuals, parameter_count, residual_count),
                                             ceres::TAKE_OWNERSHIP, difference);
  cost->AddParameterBlock(parameter_count);
  cost->SetNumResiduals(residual_count);
  return cost;
}

/// What a fit minimises: its residual blocks, their total count, and how.
struct Model
{
  const std::vector<ResidualBlock>& blocks;
  int residual_count;
  const FitOptions& options;
  std::chrono::steady_clock::time_point began;
  std::chrono::steady_clock::time_point deadline;
  FitProgress* progress;  ///< where the fit is, reported through options.progress

  bool stopRequested() const { return options.stop && options.stop(); }
  /// None once the budget is spent or a stop is asked for: every place that checks the budget checks both.
  double secondsLeft() const
  {
    if (stopRequested())
      return 0.0;
    return std::chrono::duration<double>(deadline - std::chrono::steady_clock::now()).count();
  }
  double seconds() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count(); }
};

/// Reports each iteration of a local fit and ends it, keeping its best point, when a stop is asked for.
class ReportAndStop : public ceres::IterationCallback
{
public:
  explicit ReportAndStop(const Model& model) : model_(model) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& summary) override
  {
    model_.progress->iterations = summary.iteration;
    model_.progress->cost = summary.cost;
    model_.progress->seconds = model_.seconds();
    if (model_.options.progress)
      model_.options.progress(*model_.progress);
    return model_.stopRequested() ? ceres::SOLVER_TERMINATE_SUCCESSFULLY : ceres::SOLVER_CONTINUE;
  }

private:
  const Model& model_;
};

/// Each block as a residual block of its own on the one parameter block `values` (so that Ceres may evaluate them
/// on several threads).
void addBlocks(ceres::Problem& problem, const Model& model, double* values, int parameter_count,
               ceres::LossFunction* loss = nullptr)
{
  for (const ResidualBlock& block : model.blocks)
    problem.AddResidualBlock(makeCost(block.residuals, parameter_count, block.count, model.options).release(), loss,
                             values);
}

Status validate(const std::vector<FitParameter>& parameters, int residual_count, const FitOptions& options)
{
  std::set<std::string> names;
  for (std::size_t i = 0; i < parameters.size(); ++i)
  {
    const FitParameter& p = parameters[i];
    const std::string field = p.name.empty() ? "parameters[" + std::to_string(i) + "]" : p.name;
    if (p.name.empty())
      return invalidArgument(field, "has no name");
    if (!names.insert(p.name).second)
      return invalidArgument(field, "is fitted twice");
    if (!std::isfinite(p.start) || std::isnan(p.lower) || std::isnan(p.upper))
      return invalidArgument(field, "start must be finite and its bounds numbers");
    if (p.lower > p.upper)
      return invalidArgument(field, "lower bound above its upper bound");
    if (p.start < p.lower || p.start > p.upper)
      return invalidArgument(field, "start outside its bounds");
  }
  if (parameters.empty())
    return invalidArgument("parameters", "nothing to fit");
  if (residual_count < static_cast<int>(parameters.size()))
    return invalidArgument("residual_count", "fewer observations (" + std::to_string(residual_count) +
                                                 ") than parameters (" + std::to_string(parameters.size()) + ")");
  return validate(options);
}

/// The residuals at `values`, and their Jacobian when `jacobian` is given; false where they cannot be evaluated.
bool evaluate(const Model& model, std::vector<double> values, Eigen::VectorXd& r, Eigen::MatrixXd* jacobian = nullptr)
{
  ceres::Problem problem;
  addBlocks(problem, model, values.data(), static_cast<int>(values.size()));
  ceres::Problem::EvaluateOptions evaluation;
  evaluation.num_threads = model.options.threads;
  ceres::CRSMatrix crs;
  std::vector<double> out;
  double cost = 0.0;
  if (!problem.Evaluate(evaluation, &cost, &out, nullptr, jacobian ? &crs : nullptr))
    return false;
  r = Eigen::Map<const Eigen::VectorXd>(out.data(), static_cast<Eigen::Index>(out.size()));
  if (!jacobian)
    return r.allFinite();
  *jacobian = Eigen::MatrixXd::Zero(crs.num_rows, crs.num_cols);
  for (int row = 0; row < crs.num_rows; ++row)
    for (int k = crs.rows[row]; k < crs.rows[row + 1]; ++k)
      (*jacobian)(row, crs.cols[k]) = crs.values[k];
  return r.allFinite() && jacobian->allFinite();
}

/// Fits the parameters not in `held` from `values`, in place; returns the optimiser's summary.
ceres::Solver::Summary fitFree(const Model& model, const std::vector<FitParameter>& parameters,
                               const std::vector<int>& held, std::vector<double>& values)
{
  const FitOptions& options = model.options;
  const int n = static_cast<int>(values.size());
  ceres::Problem problem;
  ceres::LossFunction* loss =
      options.robust_loss_sigmas > 0.0 ? new ceres::HuberLoss(options.robust_loss_sigmas) : nullptr;
  addBlocks(problem, model, values.data(), n, loss);
  for (int i = 0; i < n; ++i)
  {
    if (std::isfinite(parameters[i].lower))
      problem.SetParameterLowerBound(values.data(), i, parameters[i].lower);
    if (std::isfinite(parameters[i].upper))
      problem.SetParameterUpperBound(values.data(), i, parameters[i].upper);
  }
  if (static_cast<int>(held.size()) == n)
    problem.SetParameterBlockConstant(values.data());
  else if (!held.empty())
    problem.SetManifold(values.data(), new ceres::SubsetManifold(n, held));
  ceres::Solver::Options solver;
  solver.linear_solver_type = ceres::DENSE_QR;
  solver.max_num_iterations = options.max_iterations;
  solver.num_threads = options.threads;
  solver.max_solver_time_in_seconds = std::max(model.secondsLeft(), 1e-3);
  solver.logging_type = ceres::SILENT;
  solver.minimizer_progress_to_stdout = false;
  // The residuals come from integrations at a relative tolerance near 1e-8: a tighter stop would chase their noise.
  solver.function_tolerance = 1e-8;
  solver.parameter_tolerance = 1e-8;
  ReportAndStop report_and_stop(model);
  solver.callbacks.push_back(&report_and_stop);
  ceres::Solver::Summary summary;
  ceres::Solve(solver, &problem, &summary);
  return summary;
}

std::vector<int> complement(const std::vector<int>& free, int n)
{
  std::vector<int> held;
  for (int i = 0; i < n; ++i)
    if (std::find(free.begin(), free.end(), i) == free.end())
      held.push_back(i);
  return held;
}

/// A local fit from one point: the values it ends at, which of them it fitted, and its residuals and Jacobian there.
struct LocalFit
{
  std::vector<double> values;
  std::vector<int> free;
  Eigen::VectorXd residuals;
  Eigen::MatrixXd jacobian;
  ceres::Solver::Summary summary;
  double cost() const { return 0.5 * residuals.squaredNorm(); }
};

/// Fits from `values`: every parameter the residuals depend on at all is fitted; where the curvature at the best
/// point leaves one undetermined, it goes back to its own start and the others are fitted again. (Far from the
/// data the curvature may understate what the data determine, so the decision waits for the best point.)
bool fitFrom(const Model& model, const std::vector<FitParameter>& parameters, std::vector<double> values, LocalFit& fit)
{
  const int n = static_cast<int>(parameters.size());
  if (!evaluate(model, values, fit.residuals, &fit.jacobian))
    return false;
  fit.free.clear();
  for (int i = 0; i < n; ++i)
    if (fit.jacobian.col(i).squaredNorm() > 0.0)
      fit.free.push_back(i);
  // Each round that does not end the loop drops at least one parameter, so there are at most n + 1.
  bool evaluated_here = true;
  for (int round = 0; !fit.free.empty() && (round == 0 || model.secondsLeft() > 0.0); ++round)
  {
    fit.summary = fitFree(model, parameters, complement(fit.free, n), values);
    if (!evaluate(model, values, fit.residuals, &fit.jacobian))
      return false;
    evaluated_here = true;
    const std::vector<int> still = detail::identifiableParameters(
        fit.jacobian, detail::parameterScales(parameters, values), model.options.identifiable_relative_sigma, fit.free);
    if (still.size() == fit.free.size())
      break;
    for (int i : fit.free)
      if (std::find(still.begin(), still.end(), i) == still.end())
        values[i] = parameters[i].start;
    fit.free = still;
    evaluated_here = false;
  }
  // The residuals and curvature reported are those of the values returned.
  if (!evaluated_here && !evaluate(model, values, fit.residuals, &fit.jacobian))
    return false;
  fit.values = values;
  return true;
}

/// The starting points in order of their cost, those where the model fails left out; the first point, the
/// parameters' own start, has `start_cost` (Σr², already evaluated).
std::vector<std::vector<double>> rankedStarts(const Model& model, const std::vector<FitParameter>& parameters,
                                              double start_cost, int count)
{
  std::vector<std::vector<double>> candidates = detail::startingPoints(parameters, count);
  std::vector<std::pair<double, std::vector<double>>> ranked = {{start_cost, candidates.front()}};
  Eigen::VectorXd r;
  for (std::size_t k = 1; k < candidates.size() && model.secondsLeft() > 0.0; ++k)
    if (evaluate(model, candidates[k], r))
      ranked.emplace_back(r.squaredNorm(), candidates[k]);
  std::stable_sort(ranked.begin(), ranked.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::vector<double>> points;
  points.reserve(ranked.size());
  for (auto& entry : ranked)
    points.push_back(std::move(entry.second));
  return points;
}

/// One-sided differences whose gap exceeds this fraction of the smaller: the residuals jump between them.
constexpr double JUMP_RATIO = 0.5;

/// Replaces each free column of the central-difference Jacobian by the smaller one-sided difference where the two
/// disagree: the residuals jump within the step there (a track crosses an event — a jaw caught or missed, a cushion
/// just reached), the central difference spans the jump and claims a precision the data do not hold. Returns the
/// names of the parameters so treated. A parameter whose step would cross a bound keeps its central difference, as
/// does every one once the budget is spent.
std::vector<std::string> smoothSideCurvature(const Model& model, const std::vector<FitParameter>& parameters,
                                             LocalFit& fit)
{
  std::vector<std::string> jumped;
  Eigen::VectorXd ahead, behind;
  for (int i : fit.free)
  {
    const double step = model.options.relative_step * (fit.values[i] != 0.0 ? std::abs(fit.values[i]) : 1.0);
    std::vector<double> plus = fit.values, minus = fit.values;
    plus[i] += step;
    minus[i] -= step;
    if (model.secondsLeft() <= 0.0)
      break;
    if (plus[i] > parameters[i].upper || minus[i] < parameters[i].lower || !evaluate(model, plus, ahead) ||
        !evaluate(model, minus, behind))
      continue;
    const Eigen::VectorXd forward = (ahead - fit.residuals) / step, backward = (fit.residuals - behind) / step;
    if ((forward - backward).norm() <= JUMP_RATIO * std::min(forward.norm(), backward.norm()))
      continue;
    fit.jacobian.col(i) = forward.norm() < backward.norm() ? forward : backward;
    jumped.push_back(parameters[i].name);
  }
  return jumped;
}

int degreesOfFreedom(const LocalFit& fit)
{
  return std::max(static_cast<int>(fit.residuals.size() - fit.free.size()), 1);
}

/// Whether Σr² lies within three standard deviations of a χ² of its degrees of freedom: the data's noise explains
/// what is left.
bool explainsData(const LocalFit& fit)
{
  const double dof = degreesOfFreedom(fit);
  return fit.residuals.squaredNorm() <= dof + 3.0 * std::sqrt(2.0 * dof);
}

FitResult report(const std::vector<FitParameter>& parameters, const LocalFit& fit)
{
  const int n = static_cast<int>(parameters.size());
  const detail::Covariance covariance = detail::covarianceOf(fit.jacobian, fit.free);
  const int dof = degreesOfFreedom(fit);
  const double chi2_per_dof = fit.residuals.squaredNorm() / dof;
  // Residuals that the stated noise cannot explain make the curvature's precision too optimistic by √(χ²/dof);
  // within the noise's own scatter of χ² the stated noise stands (scaling there would overstate σ).
  const double birge = explainsData(fit) ? 1.0 : std::sqrt(chi2_per_dof);
  FitResult result;
  result.correlation = Eigen::MatrixXd::Constant(n, n, std::numeric_limits<double>::quiet_NaN());
  for (int i = 0; i < n; ++i)
  {
    FittedParameter fitted;
    fitted.name = parameters[i].name;
    fitted.value = fit.values[i];
    fitted.identifiable = std::find(fit.free.begin(), fit.free.end(), i) != fit.free.end();
    fitted.sigma = birge * covariance.sigma(i);
    fitted.at_bound = fit.values[i] <= parameters[i].lower || fit.values[i] >= parameters[i].upper;
    result.parameters.push_back(fitted);
    for (int j = 0; j < n; ++j)
      result.correlation(i, j) = covariance.correlation(i, j);
  }
  result.residuals = fit.residuals;
  result.final_cost = fit.cost();
  result.converged = fit.free.empty() || fit.summary.termination_type == ceres::CONVERGENCE;
  result.message = fit.free.empty() ? "nothing the data determine" : fit.summary.BriefReport();
  result.iterations = static_cast<int>(fit.summary.iterations.size());
  result.degrees_of_freedom = dof;
  result.chi2_per_dof = chi2_per_dof;
  result.explains_data = explainsData(fit);
  if (!result.explains_data)
    result.message += " The best fit does not explain the data: chi2/dof = " + std::to_string(chi2_per_dof) +
                      " where their noise gives 1 +- " + std::to_string(std::sqrt(2.0 / dof)) +
                      " (a model that does not fit them, or their noise understated); sigmas scaled by " +
                      std::to_string(birge) + ".";
  return result;
}

/// Local fits from this many of the best starting points.
constexpr std::size_t LOCAL_FITS = 3;

/// Local fits from the best LOCAL_FITS of `points` not tried yet, keeping the best end in `best`; stops once a fit
/// explains the data or the budget is spent.
void localFits(const Model& model, const std::vector<FitParameter>& parameters,
               const std::vector<std::vector<double>>& points, std::vector<std::vector<double>>& tried,
               std::optional<LocalFit>& best)
{
  LocalFit candidate;
  std::size_t fits = 0;
  for (const std::vector<double>& point : points)
  {
    if (fits == LOCAL_FITS || (best && (explainsData(*best) || model.secondsLeft() <= 0.0)))
      return;
    if (std::find(tried.begin(), tried.end(), point) != tried.end())
      continue;
    tried.push_back(point);
    ++fits;
    ++model.progress->local_fits;
    if (fitFrom(model, parameters, point, candidate) && (!best || candidate.cost() < best->cost()))
    {
      best = candidate;
      model.progress->best_cost = best->cost();
    }
  }
}

}  // namespace

Status validate(const FitOptions& options)
{
  if (!(options.max_seconds > 0.0 && options.max_seconds <= MAX_FIT_SECONDS))
    return invalidArgument("max_seconds", "must be in (0, " + formatNumber(MAX_FIT_SECONDS) + "] s, got " +
                                              formatNumber(options.max_seconds));
  return firstError(
      {requireWithin(options.starts, 1, MAX_FIT_STARTS, "starts", "starting points of the search"),
       requireWithin(options.threads, 1, MAX_FIT_THREADS, "threads", "threads evaluating the residuals"),
       requireWithin(options.robust_loss_sigmas, 0.0, std::numeric_limits<double>::max(), "robust_loss_sigmas",
                     "0: plain least squares"),
       requireWithin(options.identifiable_relative_sigma, std::numeric_limits<double>::min(),
                     std::numeric_limits<double>::max(), "identifiable_relative_sigma", "a fraction > 0"),
       requireWithin(options.max_iterations, 1, std::numeric_limits<int>::max(), "max_iterations", "of each local fit"),
       requireWithin(options.relative_step, std::numeric_limits<double>::min(), 0.1, "relative_step",
                     "of the central differences")});
}

Expected<FitResult> fitLeastSquares(const std::vector<FitParameter>& parameters, int residual_count,
                                    const ResidualFunction& residuals, const FitOptions& options)
{
  return fitLeastSquares(parameters, std::vector<ResidualBlock>{{residual_count, residuals}}, options);
}

Expected<FitResult> fitLeastSquares(const std::vector<FitParameter>& parameters,
                                    const std::vector<ResidualBlock>& blocks, const FitOptions& options)
{
  int residual_count = 0;
  for (std::size_t b = 0; b < blocks.size(); ++b)
  {
    if (blocks[b].count < 1 || !blocks[b].residuals)
      return invalidArgument("blocks[" + std::to_string(b) + "]", "needs at least one residual and a function");
    residual_count += blocks[b].count;
  }
  if (Status status = validate(parameters, residual_count, options); !status)
    return status.error();
  const auto now = std::chrono::steady_clock::now();
  FitProgress progress;
  const Model model{blocks,
                    residual_count,
                    options,
                    now,
                    now + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                              std::chrono::duration<double>(options.max_seconds)),
                    &progress};
  std::vector<double> start(parameters.size());
  std::transform(parameters.begin(), parameters.end(), start.begin(), [](const FitParameter& p) { return p.start; });
  Eigen::VectorXd r;
  if (!evaluate(model, start, r))
    return Error{ErrorKind::NumericalFailure, "parameters", "the model cannot be evaluated at the start"};

  // A fit whose χ² is within three standard deviations of its expectation explains the data to their noise: no
  // other start can do meaningfully better. One that does not searches on from more points, unless outliers are
  // expected (a robust loss), where χ² says nothing of the fit.
  std::optional<LocalFit> best;
  std::vector<std::vector<double>> tried;
  localFits(model, parameters, rankedStarts(model, parameters, r.squaredNorm(), options.starts), tried, best);
  if (best && options.escalate && !explainsData(*best) && options.robust_loss_sigmas == 0.0 &&
      options.starts < ESCALATED_STARTS && model.secondsLeft() > 0.0)
    localFits(model, parameters, rankedStarts(model, parameters, r.squaredNorm(), ESCALATED_STARTS), tried, best);
  if (!best)
    return Error{ErrorKind::NumericalFailure, "parameters", "the model cannot be evaluated along the fit"};
  const bool stopped = model.stopRequested();
  const bool out_of_time = model.secondsLeft() <= 0.0;
  const std::vector<std::string> jumped = smoothSideCurvature(model, parameters, *best);
  FitResult result = report(parameters, *best);
  result.initial_cost = 0.5 * r.squaredNorm();
  for (const std::string& name : jumped)
    result.message += " The residuals jump within the difference step of " + name +
                      " (a track crosses an event there): its sigma is taken from the smoother side.";
  if (out_of_time)
  {
    result.converged = false;
    result.message = std::string(stopped ? "stopped on request" : "the wall-clock budget ran out") +
                     "; the best point so far. " + result.message;
  }
  return result;
}

}  // namespace billiard_shot_planner

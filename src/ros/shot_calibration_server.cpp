#include "shot_calibration_server.hpp"

#include <cmath>
#include <string>
#include <utility>

#include "billiard_shot_planner/calibration/fit_parameter_bounds.hpp"
#include "billiard_shot_planner/io/calibration_overlay.hpp"
#include "error_codes.hpp"
#include "parameter_names.hpp"
#include "request_fields.hpp"

namespace billiard_shot_planner
{
namespace
{
constexpr double DEFAULT_POSITION_NOISE = 0.002;  // m, a camera tracker's typical error
constexpr double DEFAULT_BUDGET = 60.0;           // s
constexpr double FEEDBACK_RATE = 10.0;            // Hz, at most

template <class Response>
bool failWith(const Error& error, const char* service, Response& response)
{
  response.success = false;
  response.message = error.describe();
  response.error_code = errorCodeOf(error);
  ROS_WARN("%s: %s", service, response.message.c_str());
  return true;  // a refused request is an answer, not a failed call
}

Expected<std::vector<FitParameter>> fitParameters(const std::vector<std::string>& names,
                                                  const ShotConfiguration& configuration)
{
  if (names.empty())
    return invalidArgument("fit", "is empty: name the parameters to fit, e.g. motion/sliding_friction");
  std::vector<FitParameter> parameters;
  for (std::size_t i = 0; i < names.size(); ++i)
  {
    auto parameter = fitParameterFor(configuration, configurationPath(names[i]), "fit[" + std::to_string(i) + "]");
    if (!parameter)
      return parameter.error();
    parameters.push_back(parameter.value());
  }
  return parameters;
}

Status readFitOptions(const FitCalibrationGoal& request, int threads, double& position_noise, FitOptions& options)
{
  position_noise = request.position_noise == 0.0 ? DEFAULT_POSITION_NOISE : request.position_noise;
  if (!(std::isfinite(position_noise) && position_noise > 0.0))
    return invalidArgument("position_noise", "must be > 0 m (0: 0.002 m)");
  // 0 asks for the default; the core checks the ranges (validate(FitOptions)), its max_seconds being the goal's budget.
  options.starts = request.starts == 0 ? 1 : request.starts;
  options.max_seconds = request.budget == 0.0 ? DEFAULT_BUDGET : request.budget;
  options.robust_loss_sigmas = request.robust_loss_sigmas;
  options.threads = threads;
  if (Status status = validate(options); !status)
  {
    Error error = status.error();
    if (error.field == "max_seconds")
      error.field = "budget";
    return error;
  }
  return {};
}

/// A fit's error in the service's terms: parameters by their node names, the noise by its field.
Error inRequestTerms(Error error)
{
  if (error.field == "position_sigma")
    error.field = "position_noise";
  else if (error.field.rfind("shots", 0) != 0)
    error.field = parameterName(error.field);
  return error;
}

/// The balls' centres on the table, by id: what a sighting and a shot's table keep of them.
std::vector<std::pair<std::string, Eigen::Vector2d>> centres(const std::vector<TableBall>& balls)
{
  std::vector<std::pair<std::string, Eigen::Vector2d>> placed;
  placed.reserve(balls.size());
  for (const TableBall& ball : balls)
    placed.emplace_back(ball.id, ball.state.position.head<2>());
  return placed;
}

void fillAnswer(const TrackFit& fitted, std::size_t shots, FitCalibrationResult& response)
{
  const FitResult& fit = fitted.fit;
  for (const FittedParameter& p : fit.parameters)
  {
    response.names.push_back(parameterName(p.name));
    response.values.push_back(p.value);
    response.sigmas.push_back(p.sigma);  // infinite when not identifiable
    response.identifiable.push_back(p.identifiable);
    response.at_bound.push_back(p.at_bound);
  }
  // Eigen stores by column: the transpose's storage is the matrix row by row (a correlation is symmetric anyway).
  const Eigen::MatrixXd rows = fit.correlation.transpose();
  response.correlation.assign(rows.data(), rows.data() + rows.size());
  response.residuals = fitted.shot_rms;
  response.chi2 = 2.0 * fit.final_cost;
  response.observations = static_cast<uint32_t>(fit.residuals.size());
  response.degrees_of_freedom = static_cast<uint32_t>(fit.degrees_of_freedom);
  response.chi2_per_dof = fit.chi2_per_dof;
  response.explains_data = fit.explains_data;
  response.converged = fit.converged;
  response.shots = static_cast<uint32_t>(shots);
  response.overlay_yaml = calibrationOverlayYaml(fit, "fitted by shot_predictor ~fit_calibration");
  response.success = true;
  response.message = fit.message;
  response.error_code = errorCode(ErrorCode::SUCCESS);
}
}  // namespace

ShotCalibrationServer::ShotCalibrationServer(ros::NodeHandle& private_node, NodeAccess access,
                                             const RecorderLimits& limits, int threads)
    : access_(std::move(access)),
      threads_(threads),
      recorder_(limits),
      action_server_(
          private_node, "fit_calibration", [this](const FitCalibrationGoal& goal) { return check(goal); },
          [this](const FitCalibrationGoalConstPtr& goal, FitJob& job) { execute(goal, job); })
{
  record_service_ = private_node.advertiseService("record_shot", &ShotCalibrationServer::recordShot, this);
  fit_service_ = private_node.advertiseService("fit_calibration_now", &ShotCalibrationServer::fitNow, this);
  clear_service_ = private_node.advertiseService("clear_shots", &ShotCalibrationServer::clearShots, this);
}

void ShotCalibrationServer::observe(const TableState& table)
{
  // No wait for tf: the node hands over only sightings tf can place (its message filter held them until then).
  auto balls = access_.place_table(table, false);
  if (!balls)
  {
    ROS_WARN_THROTTLE(10.0, "table_state not recorded for calibration: %s", balls.error().describe().c_str());
    return;
  }
  TableSighting sighting;
  sighting.time = table.header.stamp.isZero() ? ros::Time::now().toSec() : table.header.stamp.toSec();
  sighting.balls = centres(balls.value());
  std::lock_guard<std::mutex> lock(recorder_mutex_);
  recorder_.observe(sighting);
}

Expected<ObservedShot> ShotCalibrationServer::executedShot(const RecordShot::Request& request, double strike_time)
{
  std::vector<std::pair<std::string, Eigen::Vector2d>> balls;
  if (!request.table.balls.empty())
  {
    auto placed = access_.place_table(request.table, true);
    if (!placed)
      return placed.error();
    balls = centres(placed.value());
  }
  else
  {
    std::lock_guard<std::mutex> lock(recorder_mutex_);
    const TableSighting* before = recorder_.sightingAtOrBefore(strike_time);
    if (!before)
      return invalidArgument("table", "is empty and no TableState stamped at or before strike_time was received");
    balls = before->balls;
  }
  auto cue = access_.place_cue(request.cue_pose, request.cue_speed);
  if (!cue)
    return cue.error();
  ObservedShot shot;
  BallOrigins origins;
  for (std::size_t i = 0; i < balls.size(); ++i)
  {
    const auto& [id, position] = balls[i];
    if (id == CUE_BALL_ID)
    {
      cue.value().ball = position;
      origins.cue_ball = i;
      continue;
    }
    TableBall ball{id, {}};
    ball.state.position = Eigen::Vector3d(position.x(), position.y(), 0.0);
    shot.others.push_back(ball);
    origins.others.push_back(i);
  }
  if (!origins.cue_ball)
    return invalidArgument("table.balls", "has no ball with id \"cue\": the cue ball's place before the strike");
  shot.cue = cue.value();
  // A shot the model cannot play (the cue misses its ball, balls overlap) would only fail the fit later.
  auto predicted = predictShot(shot.cue, access_.configuration(), shot.others);
  if (!predicted)
    return inRequestTerms(predicted.error(), origins);
  return shot;
}

bool ShotCalibrationServer::recordShot(RecordShot::Request& request, RecordShot::Response& response)
{
  const ros::Time strike = !request.strike_time.isZero()             ? request.strike_time
                           : !request.cue_pose.header.stamp.isZero() ? request.cue_pose.header.stamp
                                                                     : ros::Time::now();
  auto shot = executedShot(request, strike.toSec());
  if (!shot)
    return failWith(shot.error(), "record_shot", response);
  std::lock_guard<std::mutex> lock(recorder_mutex_);
  auto index = recorder_.record(shot.value(), strike.toSec());
  if (!index)
    return failWith(index.error(), "record_shot", response);
  response.success = true;
  response.message = "ok";
  response.error_code = errorCode(ErrorCode::SUCCESS);
  response.shot_index = static_cast<uint32_t>(index.value());
  response.shots_recorded = static_cast<uint32_t>(recorder_.shots().size());
  return true;
}

Expected<ShotCalibrationServer::FitJob> ShotCalibrationServer::prepare(const FitCalibrationGoal& goal)
{
  FitJob job;
  job.configuration = access_.configuration();
  auto parameters = fitParameters(goal.fit, job.configuration);
  if (!parameters)
    return parameters.error();
  job.parameters = parameters.value();
  if (Status status = readFitOptions(goal, threads_, job.position_noise, job.options); !status)
    return status.error();
  {
    std::lock_guard<std::mutex> lock(recorder_mutex_);
    job.shots = recorder_.shots();
  }
  if (job.shots.empty())
    return invalidArgument("shots", "none recorded: record executed shots with ~record_shot first");
  return job;
}

FitCalibrationResult ShotCalibrationServer::fit(FitJob& job, const FitHooks& hooks)
{
  FitCalibrationResult result;
  job.options.stop = hooks.stop;
  job.options.progress = hooks.progress;
  auto fitted = fitTracks(job.configuration, job.parameters, job.shots, job.position_noise, job.options);
  if (!fitted)
  {
    failWith(inRequestTerms(fitted.error()), "fit_calibration", result);
    return result;
  }
  fillAnswer(fitted.value(), job.shots.size(), result);
  return result;
}

std::variant<ShotCalibrationServer::FitJob, FitCalibrationResult> ShotCalibrationServer::check(
    const FitCalibrationGoal& goal)
{
  const ros::WallTime start = ros::WallTime::now();
  auto job = prepare(goal);
  if (job)
    return std::move(job.value());
  FitCalibrationResult refused;
  failWith(job.error(), "fit_calibration: rejected", refused);
  if (access_.record)
    access_.record("fit_calibration", (ros::WallTime::now() - start).toSec(), refused.error_code, refused.message);
  return refused;
}

void ShotCalibrationServer::execute(const FitCalibrationGoalConstPtr& /*goal*/, FitJob& job)
{
  FitHooks hooks;
  ros::WallTime last_feedback;
  hooks.progress = [this, &last_feedback](const FitProgress& progress)
  {
    // At most FEEDBACK_RATE messages a second: a fast model iterates far more often than a client reads.
    const ros::WallTime now = ros::WallTime::now();
    if ((now - last_feedback).toSec() < 1.0 / FEEDBACK_RATE)
      return;
    last_feedback = now;
    FitCalibrationFeedback feedback;
    feedback.local_fits = static_cast<uint32_t>(progress.local_fits);
    feedback.iterations = static_cast<uint32_t>(progress.iterations);
    feedback.chi2 = 2.0 * progress.cost;
    feedback.best_chi2 = 2.0 * progress.best_cost;
    feedback.elapsed = progress.seconds;
    action_server_.publishFeedback(feedback);
  };
  hooks.stop = [this]() { return action_server_.isPreemptRequested() || !ros::ok(); };
  const FitCalibrationResult result = recordedCall(access_.record, "fit_calibration", [&] { return fit(job, hooks); });
  action_server_.finish(result, result.success);
}

bool ShotCalibrationServer::fitNow(FitCalibrationNow::Request& request, FitCalibrationNow::Response& response)
{
  response.result = recordedCall(access_.record, "fit_calibration_now",
                                 [&]
                                 {
                                   auto job = prepare(request.goal);
                                   if (job)
                                     return fit(job.value(), FitHooks{});
                                   FitCalibrationResult refused;
                                   failWith(job.error(), "fit_calibration_now", refused);
                                   return refused;
                                 });
  return true;  // a goal that cannot be fitted is an answer, not a failed call
}

bool ShotCalibrationServer::clearShots(std_srvs::Trigger::Request& /*request*/, std_srvs::Trigger::Response& response)
{
  std::lock_guard<std::mutex> lock(recorder_mutex_);
  const std::size_t shots = recorder_.shots().size();
  recorder_.clear();
  response.success = true;
  response.message = "cleared " + std::to_string(shots) + " recorded shots";
  return true;
}

}  // namespace billiard_shot_planner

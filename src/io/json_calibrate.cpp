// The calibrate problem: the model's constants fitted to the tracks of executed shots.
#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "billiard_shot_planner/calibration/fit_parameter_bounds.hpp"
#include "billiard_shot_planner/calibration/track_fit.hpp"
#include "billiard_shot_planner/core/error_fields.hpp"
#include "billiard_shot_planner/core/validation.hpp"
#include "billiard_shot_planner/io/calibration_overlay.hpp"
#include "billiard_shot_planner/planning/stroke.hpp"
#include "billiard_shot_planner/shot/configuration_fields.hpp"
#include "json_configuration.hpp"
#include "json_fields.hpp"
#include "json_table.hpp"

namespace billiard_shot_planner
{
namespace json_io
{
namespace
{
/// Bounds on a request's work: shots and track points (a fit's time is bounded by its budget_ms).
constexpr std::size_t MAX_CALIBRATION_SHOTS = 200;
constexpr std::size_t MAX_TRACK_POINTS = 200000;

/// "fit": the names (the node's, with '/') or {"name", "start", "lower", "upper"}; the start defaults to the
/// request's value, the bounds to fitParameterFor()'s.
Expected<std::vector<FitParameter>> fitParameters(const json& request, const ShotConfiguration& configuration)
{
  if (!request.contains("fit") || !request.at("fit").is_array() || request.at("fit").empty())
    return invalidArgument("fit",
                           "is required: the names of the parameters to fit, e.g. [\"motion/sliding_friction\"]");
  std::vector<FitParameter> parameters;
  const json& list = request.at("fit");
  for (std::size_t i = 0; i < list.size(); ++i)
  {
    const std::string field = "fit[" + std::to_string(i) + "]";
    const json& entry = list[i];
    const json* name = entry.is_string()                             ? &entry
                       : entry.is_object() && entry.contains("name") ? &entry["name"]
                                                                     : nullptr;
    if (!name || !name->is_string())
      return invalidArgument(field, "must be a parameter's name or {\"name\", \"start\", \"lower\", \"upper\"}");
    auto found = fitParameterFor(configuration, configurationPath(name->get<std::string>()), field);
    if (!found)
      return found.error();
    FitParameter parameter = found.value();
    if (entry.is_object())
      if (Status status = readNumbers(
              entry, {{"start", &parameter.start}, {"lower", &parameter.lower}, {"upper", &parameter.upper}}, field);
          !status)
        return status.error();
    parameters.push_back(parameter);
  }
  return parameters;
}

/// "tracks": {id: [[t, x, y], …]}, the cue ball's track filed under CUE_BALL_ID.
Expected<std::map<std::string, std::vector<TrackPoint>>> tracks(const json& shot, const std::string& prefix,
                                                                const std::string& cue_ball)
{
  if (!shot.contains("tracks") || !shot.at("tracks").is_object())
    return invalidArgument(prefix + ".tracks", "is required: {ball id: [[t, x, y], …]}");
  std::map<std::string, std::vector<TrackPoint>> read;
  for (const auto& [id, points] : shot.at("tracks").items())
  {
    std::string field = prefix;
    field += ".tracks.";
    field += id;
    if (!points.is_array())
      return invalidArgument(field, "must be an array of [t, x, y]");
    std::vector<TrackPoint>& track = read[id == cue_ball ? std::string(CUE_BALL_ID) : id];
    for (std::size_t j = 0; j < points.size(); ++j)
    {
      const json& p = points[j];
      if (!p.is_array() || p.size() != 3 || !p[0].is_number() || !p[1].is_number() || !p[2].is_number())
        return invalidArgument(field + "[" + std::to_string(j) + "]", "must be [t, x, y] in s and m");
      track.push_back({p[0].get<double>(), {p[1].get<double>(), p[2].get<double>()}});
    }
  }
  return read;
}

/// The cue as a stroke, "cue": {"phi_deg", "theta_deg", "speed", "a", "b", "convention"}, placed at the cue ball.
Expected<CuePlacement> strokeCue(const json& shot, const std::string& prefix, const Eigen::Vector2d& ball,
                                 double radius)
{
  auto fields = object(shot, "cue", true);
  if (!fields)
    return nested(prefix, fields.error());
  auto stroke = strokeFromJson(fields.value(), prefix + ".cue", radius);
  if (!stroke)
    return stroke.error();
  auto cue = placeStroke(stroke.value(), ball, radius);
  if (!cue)
    return nested(prefix + ".cue", cue.error());
  return cue;
}

/// How a request's shot names its balls: the cue ball's id and its index in the shot's "balls".
struct CueBallOfShot
{
  std::string id;
  std::size_t index = 0;
};

Expected<ObservedShot> observedShot(const json& shot, std::size_t k, double radius, CueBallOfShot& cue_ball)
{
  const std::string prefix = "shots[" + std::to_string(k) + "]";
  if (!shot.is_object())
    return invalidArgument(prefix, "must be an object {\"balls\", \"cue\", \"tracks\"}");
  auto balls = tableBalls(shot, radius);
  if (!balls)
    return nested(prefix, balls.error());
  auto cue_index = cueBallIndex(shot, balls.value());
  if (!cue_index)
    return nested(prefix, cue_index.error());
  cue_ball = {balls.value()[cue_index.value()].id, cue_index.value()};
  ObservedShot observed;
  auto cue = strokeCue(shot, prefix, balls.value()[cue_index.value()].state.position.head<2>(), radius);
  if (!cue)
    return cue.error();
  observed.cue = cue.value();
  for (std::size_t i = 0; i < balls.value().size(); ++i)
    if (i != cue_index.value())
      observed.others.push_back(balls.value()[i]);
  auto read = tracks(shot, prefix, cue_ball.id);
  if (!read)
    return read.error();
  observed.tracks = read.value();
  return observed;
}

/// The core's name of a shot's input ("cue.ball", "others[2].position", "tracks.cue[3].t") in the request's: the
/// balls at their places in the shot's "balls", the cue ball's track under its own id, the cue's fields as "cue".
std::string shotField(const std::string& field, const CueBallOfShot& cue_ball)
{
  if (const auto rest = restUnder(field, "cue.ball"))
    return "balls[" + std::to_string(cue_ball.index) + "]" + (rest->empty() ? ".position" : *rest);
  if (restUnder(field, "cue"))
    return "cue";
  if (const auto other = elementOf(field, "others"))
  {
    const std::size_t j = other->index;
    return "balls[" + std::to_string(j < cue_ball.index ? j : j + 1) + "]" + other->rest;
  }
  if (const auto rest = restUnder(field, std::string("tracks.") + CUE_BALL_ID))
    return "tracks." + cue_ball.id + *rest;
  return field;
}

/// A fit's error in the request's names: a shot's input as shotField(), parameters with '/'.
Error inRequestTerms(Error error, const std::vector<CueBallOfShot>& cue_balls)
{
  if (const auto shot = elementOf(error.field, "shots"))
  {
    if (shot->index < cue_balls.size() && shot->rest.size() > 1 && shot->rest.front() == '.')
      error.field =
          "shots[" + std::to_string(shot->index) + "]." + shotField(shot->rest.substr(1), cue_balls[shot->index]);
  }
  else if (error.field == "position_sigma")
    error.field = "position_noise";
  else
    error.field = parameterNameOfField(error.field);
  return error;
}

json answerJson(const TrackFit& fitted)
{
  const FitResult& fit = fitted.fit;
  json parameters = json::object(), correlation = json::array();
  for (std::size_t i = 0; i < fit.parameters.size(); ++i)
  {
    const FittedParameter& p = fit.parameters[i];
    parameters[parameterName(p.name)] = {{"value", p.value},
                                         {"sigma", std::isfinite(p.sigma) ? json(p.sigma) : json(nullptr)},
                                         {"identifiable", p.identifiable},
                                         {"at_bound", p.at_bound}};
    json row = json::array();
    for (std::size_t j = 0; j < fit.parameters.size(); ++j)
    {
      const double c = fit.correlation(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
      row.push_back(std::isfinite(c) ? json(c) : json(nullptr));
    }
    correlation.push_back(row);
  }
  return json{{"parameters", parameters},
              {"correlation", correlation},
              {"residuals", fitted.shot_rms},
              {"chi2", 2.0 * fit.final_cost},
              {"observations", fit.residuals.size()},
              {"degrees_of_freedom", fit.degrees_of_freedom},
              {"chi2_per_dof", fit.chi2_per_dof},
              {"explains_data", fit.explains_data},
              {"converged", fit.converged},
              {"iterations", fit.iterations},
              {"message", fit.message},
              {"overlay_yaml", calibrationOverlayYaml(fit, "fitted by impact_solve calibrate")}};
}

Status readFitOptions(const json& request, double& position_noise, FitOptions& options)
{
  double starts = options.starts, threads = options.threads, budget_ms = options.max_seconds * 1e3;
  if (Status status = readNumbers(request, {{"position_noise", &position_noise},
                                            {"starts", &starts},
                                            {"threads", &threads},
                                            {"budget_ms", &budget_ms},
                                            {"robust_loss_sigmas", &options.robust_loss_sigmas}});
      !status)
    return status;
  // JSON numbers are doubles: a count must be a whole one, and in int's range before it is converted; the core
  // checks the ranges (validate(FitOptions)), its max_seconds being this request's budget_ms.
  for (auto [name, count] : {std::pair{"starts", starts}, std::pair{"threads", threads}})
    if (!(count == std::floor(count) && std::abs(count) <= 1e9))
      return invalidArgument(name, "must be a whole number, got " + formatNumber(count));
  options.starts = static_cast<int>(starts);
  options.threads = static_cast<int>(threads);
  options.max_seconds = budget_ms * 1e-3;
  if (Status status = validate(options); !status)
  {
    if (status.error().field == "max_seconds")
      return invalidArgument("budget_ms", "must be in (0, " + formatNumber(MAX_FIT_SECONDS * 1e3) + "] ms");
    return status;
  }
  return {};
}
}  // namespace

Expected<json> solveCalibrate(const json& request, const SolverOptions& options)
{
  auto configuration = configurationOf(request, options);
  if (!configuration)
    return configuration.error();
  auto parameters = fitParameters(request, configuration.value());
  if (!parameters)
    return parameters.error();
  double position_noise = 0.002;
  FitOptions fit_options;
  fit_options.max_seconds = 60.0;
  if (Status status = readFitOptions(request, position_noise, fit_options); !status)
    return status.error();
  if (!request.contains("shots") || !request.at("shots").is_array())
    return invalidArgument("shots", "is required: an array of {\"balls\", \"cue\", \"tracks\"}");
  std::vector<ObservedShot> shots;
  std::vector<CueBallOfShot> cue_balls;
  std::size_t points = 0;
  for (std::size_t k = 0; k < request.at("shots").size() && k <= MAX_CALIBRATION_SHOTS; ++k)
  {
    CueBallOfShot cue_ball;
    auto shot = observedShot(request.at("shots")[k], k, configuration.value().ball_radius, cue_ball);
    if (!shot)
      return shot.error();
    for (const auto& entry : shot.value().tracks)
      points += entry.second.size();
    if (points > MAX_TRACK_POINTS)
      return invalidArgument("shots", "at most " + std::to_string(MAX_TRACK_POINTS) + " track points in all");
    shots.push_back(shot.value());
    cue_balls.push_back(cue_ball);
  }
  if (shots.size() > MAX_CALIBRATION_SHOTS)
    return invalidArgument("shots", "at most " + std::to_string(MAX_CALIBRATION_SHOTS) + " shots");
  auto fitted = fitTracks(configuration.value(), parameters.value(), shots, position_noise, fit_options);
  if (!fitted)
    return inRequestTerms(fitted.error(), cue_balls);
  return answerJson(fitted.value());
}

}  // namespace json_io
}  // namespace billiard_shot_planner

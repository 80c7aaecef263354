#include "billiard_shot_planner/calibration/track_fit.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "fitted_values.hpp"

namespace billiard_shot_planner
{
namespace
{
Status validate(const std::vector<TrackPoint>& track, const std::string& field)
{
  for (std::size_t j = 0; j < track.size(); ++j)
  {
    const std::string point = field + "[" + std::to_string(j) + "]";
    if (!std::isfinite(track[j].t) || track[j].t < 0.0)
      return invalidArgument(point + ".t", "must be a finite time ≥ 0 s after the strike");
    if (j > 0 && track[j].t <= track[j - 1].t)
      return invalidArgument(point + ".t", "must come after the point before it");
    if (!track[j].position.allFinite())
      return invalidArgument(point + ".position", "must be finite");
  }
  return {};
}

/// The index of each tracked ball among the prediction's balls (the cue ball first, then the others in order).
Expected<std::vector<std::size_t>> trackedBalls(const ObservedShot& shot, const std::string& field)
{
  std::vector<std::size_t> indices;
  for (const auto& entry : shot.tracks)
  {
    const std::string& id = entry.first;
    std::string track_field = field;
    track_field += ".tracks.";
    track_field += id;
    std::size_t index = 0;
    if (id != CUE_BALL_ID)
    {
      const auto found =
          std::find_if(shot.others.begin(), shot.others.end(), [&](const TableBall& ball) { return ball.id == id; });
      if (found == shot.others.end())
        return invalidArgument(track_field, "no ball of the shot has this id");
      index = 1 + static_cast<std::size_t>(found - shot.others.begin());
    }
    if (Status status = validate(entry.second, track_field); !status)
      return status.error();
    indices.push_back(index);
  }
  return indices;
}

/// Whether the strike (strikeBall) reads the named parameter: the cue, the ball, the cloth and the solver do; the
/// motion on the table does not, nor do the cushions and the table's size unless the struck ball touches a ball or
/// a cushion (a lone strike has only the cue's and the cloth's contacts).
bool strikeReads(const std::string& name, const CueStrikeResult& strike)
{
  const auto starts = [&](const char* prefix) { return name.rfind(prefix, 0) == 0; };
  if (strike.contacts.size() > 2)
    return !starts("motion.");
  return starts("table.cloth.") || !(starts("motion.") || starts("table."));
}

/// Every track point's predicted minus observed position of one shot, in position_sigma, into `out` from `row`;
/// `struck` is the shot's strike under `c` when the fit does not change it, else null.
bool shotResiduals(const ObservedShot& shot, const std::vector<std::size_t>& balls, const CueStrikeResult* struck,
                   const ShotConfiguration& c, double position_sigma, Eigen::VectorXd& out, Eigen::Index& row)
{
  const auto outcome =
      struck ? predictShotAfter(shot.cue, *struck, c, shot.others) : predictShot(shot.cue, c, shot.others);
  if (!outcome)
    return false;
  std::size_t k = 0;
  for (const auto& [id, track] : shot.tracks)
  {
    const BallTrajectory& path = outcome->table.balls[balls[k++]];
    for (const TrackPoint& point : track)
    {
      out.segment<2>(row) = (path.at(point.t).position.head<2>() - point.position) / position_sigma;
      row += 2;
    }
  }
  return true;
}

std::vector<double> rmsPerShot(const std::vector<ObservedShot>& shots, const Eigen::VectorXd& residuals,
                               double position_sigma)
{
  std::vector<double> rms;
  Eigen::Index row = 0;
  for (const ObservedShot& shot : shots)
  {
    double sum = 0.0;
    Eigen::Index points = 0;
    for (const auto& entry : shot.tracks)
      for (std::size_t j = 0; j < entry.second.size(); ++j, ++points, row += 2)
        sum += residuals.segment<2>(row).squaredNorm();
    rms.push_back(points > 0 ? position_sigma * std::sqrt(sum / static_cast<double>(points)) : 0.0);
  }
  return rms;
}
}  // namespace

Expected<TrackFit> fitTracks(const ShotConfiguration& configuration, const std::vector<FitParameter>& parameters,
                             const std::vector<ObservedShot>& shots, double position_sigma, const FitOptions& options)
{
  if (!(position_sigma > 0.0 && std::isfinite(position_sigma)))
    return invalidArgument("position_sigma", "must be finite and > 0");
  auto checked = checkedNames(configuration, parameters);
  if (!checked)
    return checked.error();
  const std::vector<std::string> names = checked.value();
  if (shots.empty())
    return invalidArgument("shots", "no observed shot");
  std::vector<std::vector<std::size_t>> balls;
  std::vector<CueStrikeResult> strikes;
  int residual_count = 0;
  for (std::size_t k = 0; k < shots.size(); ++k)
  {
    const std::string field = "shots[" + std::to_string(k) + "]";
    auto tracked = trackedBalls(shots[k], field);
    if (!tracked)
      return tracked.error();
    balls.push_back(tracked.value());
    for (const auto& entry : shots[k].tracks)
      residual_count += 2 * static_cast<int>(entry.second.size());
    const auto predicted = predictShot(shots[k].cue, configuration, shots[k].others);
    if (!predicted)
    {
      Error error = predicted.error();
      error.field = field + (error.field.empty() ? "" : "." + error.field);
      return error;
    }
    strikes.push_back(predicted->strike);
  }
  if (residual_count < static_cast<int>(parameters.size()))
    return invalidArgument("shots", std::to_string(residual_count / 2) + " track points cannot fit " +
                                        std::to_string(parameters.size()) + " parameters");
  // One residual block a shot: Ceres may evaluate the shots on several threads.
  std::vector<ResidualBlock> blocks;
  for (std::size_t k = 0; k < shots.size(); ++k)
  {
    int count = 0;
    for (const auto& entry : shots[k].tracks)
      count += 2 * static_cast<int>(entry.second.size());
    if (count == 0)
      continue;
    const bool strike_changes =
        std::any_of(names.begin(), names.end(), [&](const std::string& name) { return strikeReads(name, strikes[k]); });
    const CueStrikeResult* struck = strike_changes ? nullptr : &strikes[k];
    blocks.push_back({count, [&, k, count, struck](const std::vector<double>& values, Eigen::VectorXd& out)
                      {
                        ShotConfiguration changed = configuration;
                        if (!applyValues(changed, names, values))
                          return false;
                        out.resize(count);
                        Eigen::Index row = 0;
                        return shotResiduals(shots[k], balls[k], struck, changed, position_sigma, out, row);
                      }});
  }
  auto fit = fitLeastSquares(parameters, blocks, options);
  if (!fit)
    return fit.error();
  TrackFit result{fit.value(), rmsPerShot(shots, fit->residuals, position_sigma)};
  return result;
}

}  // namespace billiard_shot_planner

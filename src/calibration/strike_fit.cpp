#include "billiard_shot_planner/calibration/strike_fit.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <string>
#include <vector>

#include "fitted_values.hpp"

namespace billiard_shot_planner
{
namespace
{
/// The unknowns the strike fit applies itself, to the cue's direction.
const std::vector<std::string> CUE_TURNS = {CUE_YAW, CUE_PITCH};

Status validate(const ObservedStrike& strike, const std::string& field)
{
  if (!strike.velocity.allFinite())
    return invalidArgument(field + ".velocity", "must be finite");
  if (!strike.angular_velocity.allFinite())
    return invalidArgument(field + ".angular_velocity", "must be finite");
  if (!(strike.velocity_sigma > 0.0 && std::isfinite(strike.velocity_sigma)))
    return invalidArgument(field + ".velocity_sigma", "must be finite and > 0");
  if (!(strike.angular_velocity_sigma > 0.0 && std::isfinite(strike.angular_velocity_sigma)))
    return invalidArgument(field + ".angular_velocity_sigma", "must be finite and > 0");
  return {};
}

/// Residuals of every observed strike under the named values, in standard deviations: four a strike.
bool strikeResiduals(const ShotConfiguration& configuration, const std::vector<std::string>& names,
                     const std::vector<ObservedStrike>& strikes, const std::vector<double>& values,
                     Eigen::VectorXd& residuals)
{
  residuals.resize(4 * static_cast<Eigen::Index>(strikes.size()));
  for (std::size_t k = 0; k < strikes.size(); ++k)
  {
    ShotConfiguration changed = configuration;
    CuePlacement cue = strikes[k].cue;
    if (!applyFitted(names, values, changed, cue))
      return false;
    const auto struck = strikeBall(cue, changed);
    if (!struck)
      return false;
    const ObservedStrike& seen = strikes[k];
    const auto row = 4 * static_cast<Eigen::Index>(k);
    residuals.segment<2>(row) = (struck->velocity.head<2>() - seen.velocity) / seen.velocity_sigma;
    residuals.segment<2>(row + 2) =
        (struck->angular_velocity.head<2>() - seen.angular_velocity) / seen.angular_velocity_sigma;
  }
  return true;
}
}  // namespace

Expected<CuePlacement> turnedCue(const CuePlacement& cue, double yaw, double pitch, double ball_radius)
{
  const Eigen::Vector3d centre(cue.ball.x(), cue.ball.y(), ball_radius);
  const auto normal = hitNormal(cue.tip, cue.direction, centre, ball_radius);
  if (!normal)
    return normal.error();
  const Eigen::Vector3d hit = centre + ball_radius * normal.value();
  const Eigen::Vector3d direction = cue.direction.normalized();
  Eigen::Vector3d across = Eigen::Vector3d::UnitZ().cross(direction);
  // A vertical cue has no horizontal line across it of its own: the table's y axis stands in.
  across = across.norm() > 1e-12 ? across.normalized() : Eigen::Vector3d::UnitY();
  // A turn about ẑ × ĉ by +pitch tips the direction down: the cue's elevation grows by `pitch`.
  const Eigen::Matrix3d turn =
      (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(pitch, across)).toRotationMatrix();
  CuePlacement turned = cue;
  turned.direction = turn * direction;
  turned.tip = hit + turn * (cue.tip - hit);
  return turned;
}

Status applyFitted(const std::vector<std::string>& names, const std::vector<double>& values,
                   ShotConfiguration& configuration, CuePlacement& cue)
{
  if (Status status = applyValues(configuration, names, values, CUE_TURNS); !status)
    return status;
  double yaw = 0.0, pitch = 0.0;
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == CUE_YAW)
      yaw = values[i];
    else if (names[i] == CUE_PITCH)
      pitch = values[i];
  if (yaw == 0.0 && pitch == 0.0)
    return {};
  auto turned = turnedCue(cue, yaw, pitch, configuration.ball_radius);
  if (!turned)
    return turned.error();
  cue = turned.value();
  return {};
}

Expected<FitResult> fitStrikes(const ShotConfiguration& configuration, const std::vector<FitParameter>& parameters,
                               const std::vector<ObservedStrike>& strikes, const FitOptions& options)
{
  auto checked = checkedNames(configuration, parameters, CUE_TURNS);
  if (!checked)
    return checked.error();
  const std::vector<std::string> names = checked.value();
  if (strikes.empty())
    return invalidArgument("strikes", "no observed strike");
  if (4 * strikes.size() < parameters.size())
    return invalidArgument("strikes", std::to_string(strikes.size()) + " strikes (4 observations each) cannot fit " +
                                          std::to_string(parameters.size()) + " parameters");
  for (std::size_t k = 0; k < strikes.size(); ++k)
  {
    const std::string field = "strikes[" + std::to_string(k) + "]";
    if (Status status = validate(strikes[k], field); !status)
      return status.error();
    // A cue that misses its ball, or a configuration the strike refuses, is the observation's error, named.
    if (const auto struck = strikeBall(strikes[k].cue, configuration); !struck)
    {
      Error error = struck.error();
      error.field = field + ".cue" + (error.field.empty() ? "" : "." + error.field);
      return error;
    }
  }
  const ResidualFunction residuals = [&](const std::vector<double>& values, Eigen::VectorXd& out)
  { return strikeResiduals(configuration, names, strikes, values, out); };
  return fitLeastSquares(parameters, 4 * static_cast<int>(strikes.size()), residuals, options);
}

}  // namespace billiard_shot_planner

#include "billiard_shot_planner/calibration/cushion_rebound_fit.hpp"

#include <cmath>

#include "named_values.hpp"

#include "billiard_shot_planner/impact/laws/normal_law.hpp"
#include "billiard_shot_planner/scenarios/cushion_impact.hpp"

namespace billiard_shot_planner
{
namespace
{
/// Every fittable number of the table by its name, the cushion law's parameters as that law declares them.
template <class Visitor>
void visitReboundValues(CushionReboundTable& table, Visitor&& visit)
{
  visit("cushion.restitution", table.cushion.restitution);
  visit("cushion.friction", table.cushion.friction);
  visit("cushion.eta2", table.cushion.eta2);
  visit("cushion_stiffness_ratio", table.cushion_stiffness_ratio);
  visitLawParameters(table.cushion.normal_law,
                     [&](const char* name, double& value) { visit(std::string("cushion.law.") + name, value); });
}

}  // namespace

std::vector<std::string> reboundParameters(const CushionReboundTable& table)
{
  return namedValues(table, [](CushionReboundTable& model, auto&& visit) { visitReboundValues(model, visit); });
}

Status applyReboundValues(const std::vector<std::string>& names, const std::vector<double>& values,
                          CushionReboundTable& table)
{
  return applyNamedValues(
      names, values, table, [](CushionReboundTable& model, auto&& visit) { visitReboundValues(model, visit); },
      "is not a parameter of a cushion rebound (the cushion's constants, its law's "
      "and cushion_stiffness_ratio)");
}

Expected<double> predictRebound(const CushionReboundTable& table, double speed_in, const SolverOptions& options)
{
  const double r = table.ball_radius;
  if (!(table.contact_height > r && table.contact_height < 2.0 * r))
    return invalidArgument("contact_height", "must lie between the ball's centre and its top, in (R, 2R)");
  if (!(speed_in > 0.0) || !std::isfinite(speed_in))
    return invalidArgument("speed_in", "must be finite and > 0");
  // The cushion at +x touches the ball above its centre: the normal from the nose to the centre points back and down.
  const double rise = (table.contact_height - r) / r;
  CushionImpact hit;
  hit.mass = table.ball_mass;
  hit.radius = r;
  hit.velocity = Eigen::Vector3d(speed_in, 0.0, 0.0);
  hit.angular_velocity = Eigen::Vector3d(0.0, speed_in / r, 0.0);  // rolling: v + ω × (−R ẑ) = 0
  hit.cushion_normal = Eigen::Vector3d(-std::sqrt(1.0 - rise * rise), 0.0, -rise);
  hit.cushion = table.cushion;
  hit.cloth = table.cloth;
  hit.stiffness_ratio = table.cushion_stiffness_ratio;
  auto result = solve(hit, options);
  if (!result)
    return result.error();
  return -result.value().velocity.x();
}

Expected<FitResult> fitCushionRebounds(const CushionReboundTable& table, const std::vector<FitParameter>& parameters,
                                       const std::vector<CushionRebound>& rebounds, double ratio_sigma,
                                       const FitOptions& options)
{
  if (!(ratio_sigma > 0.0) || !std::isfinite(ratio_sigma))
    return invalidArgument("ratio_sigma", "must be finite and > 0");
  for (std::size_t i = 0; i < rebounds.size(); ++i)
  {
    const CushionRebound& rebound = rebounds[i];
    if (!(rebound.speed_in > 0.0) || !std::isfinite(rebound.speed_in))
      return invalidArgument(indexedField("rebounds", i) + ".speed_in", "must be finite and > 0");
    if (!(rebound.speed_out >= 0.0) || !std::isfinite(rebound.speed_out))
      return invalidArgument(indexedField("rebounds", i) + ".speed_out", "must be finite and >= 0");
  }
  const std::vector<std::string> names = parameterNames(parameters);
  const std::vector<double> starts = parameterStarts(parameters);
  CushionReboundTable start = table;
  if (Status applied = applyReboundValues(names, starts, start); !applied)
    return applied.error();
  if (auto checked = predictRebound(start, 1.0); !checked && checked.error().code == ErrorKind::InvalidArgument)
    return checked.error();
  std::vector<ResidualBlock> blocks;
  blocks.reserve(rebounds.size());
  for (const CushionRebound& rebound : rebounds)
  {
    blocks.push_back({1, [=](const std::vector<double>& values, Eigen::VectorXd& residuals)
                      {
                        CushionReboundTable trial = table;
                        if (!applyReboundValues(names, values, trial))
                          return false;
                        const auto out = predictRebound(trial, rebound.speed_in);
                        if (!out)
                          return false;
                        residuals.resize(1);
                        residuals(0) = (out.value() - rebound.speed_out) / (ratio_sigma * rebound.speed_in);
                        return true;
                      }});
  }
  return fitLeastSquares(parameters, blocks, options);
}

}  // namespace billiard_shot_planner

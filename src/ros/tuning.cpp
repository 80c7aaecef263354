#include "tuning.hpp"
#include "parameter_names.hpp"

namespace billiard_shot_planner
{
namespace
{
/// Each tunable value and where it lives in the configuration; one table serves both directions.
template <class Visitor>
void visitTunables(ShotConfiguration& c, ShotPredictorConfig& t, Visitor&& visit)
{
  visit(t.cue_mass, c.cue_mass);
  visit(t.cue_end_mass, c.cue_end_mass);
  visit(t.ball_mass, c.ball_mass);
  visit(t.ball_radius, c.ball_radius);
  visit(t.stiffness_ratio, c.stiffness_ratio);
  visit(t.cue_contact_restitution, c.cue_contact.restitution);
  visit(t.cue_contact_friction, c.cue_contact.friction);
  visit(t.cue_contact_eta2, c.cue_contact.eta2);
  visit(t.cloth_restitution, c.table.cloth.restitution);
  visit(t.cloth_friction, c.table.cloth.friction);
  visit(t.cloth_eta2, c.table.cloth.eta2);
  visit(t.cushion_restitution, c.table.cushion.restitution);
  visit(t.cushion_friction, c.table.cushion.friction);
  visit(t.cushion_eta2, c.table.cushion.eta2);
  visit(t.sliding_friction, c.motion.sliding_friction);
  visit(t.rolling_friction, c.motion.rolling_friction);
  visit(t.spinning_friction, c.motion.spinning_friction);
  visit(t.planar, c.motion.planar);
  visit(t.min_bounce_speed, c.motion.min_bounce_speed);
}
}  // namespace

ShotPredictorConfig toTuning(const ShotConfiguration& configuration)
{
  ShotConfiguration c = configuration;
  ShotPredictorConfig tuning = ShotPredictorConfig::__getDefault__();
  visitTunables(c, tuning, [](auto& tuned, const auto& value) { tuned = value; });
  tuning.rolling_model = c.motion.rolling_model == RollingModel::Paper ? "paper" : "pooltool";
  return tuning;
}

Expected<ShotConfiguration> applyTuning(ShotConfiguration configuration, const ShotPredictorConfig& tuning)
{
  ShotPredictorConfig t = tuning;
  visitTunables(configuration, t, [](const auto& tuned, auto& value) { value = tuned; });
  if (t.rolling_model != "paper" && t.rolling_model != "pooltool")
    return invalidArgument("rolling_model", "must be paper or pooltool");
  configuration.motion.rolling_model = t.rolling_model == "paper" ? RollingModel::Paper : RollingModel::Pooltool;
  if (Status status = namedAsParameter(validate(configuration)); !status)
    return status.error();
  return configuration;
}

}  // namespace billiard_shot_planner

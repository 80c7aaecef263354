#include "node_settings.hpp"

#include <ros/param.h>
#include "parameter_names.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <utility>

#include "billiard_shot_planner/core/validation.hpp"

namespace billiard_shot_planner
{
namespace
{
Status readPockets(ParameterTree& parameters, Table& table)
{
  table.pockets = sixPockets(table.length, table.width);
  const XmlRpc::XmlRpcValue* found = parameters.find("table/pockets");
  if (!found)
    return {};
  XmlRpc::XmlRpcValue list = *found;  // XmlRpcValue's conversions are not const
  if (list.getType() != XmlRpc::XmlRpcValue::TypeArray)
    return invalidArgument("table/pockets", "must be a list of [x, y, radius]");
  table.pockets.clear();
  for (int i = 0; i < list.size(); ++i)
  {
    const std::string name = "table/pockets[" + std::to_string(i) + "]";
    if (list[i].getType() != XmlRpc::XmlRpcValue::TypeArray || list[i].size() != 3)
      return invalidArgument(name, "must be [x, y, radius]");
    double values[3];
    for (int k = 0; k < 3; ++k)
    {
      XmlRpc::XmlRpcValue& v = list[i][k];
      if (v.getType() == XmlRpc::XmlRpcValue::TypeDouble)
        values[k] = static_cast<double>(v);
      else if (v.getType() == XmlRpc::XmlRpcValue::TypeInt)
        values[k] = static_cast<int>(v);
      else
        return invalidArgument(name, "must be [x, y, radius] numbers");
    }
    table.pockets.push_back({{values[0], values[1]}, values[2]});
  }
  return {};
}

/// A parameter that names one of two choices, with the two names.
template <class Choice>
struct TwoChoices
{
  std::pair<const char*, Choice> first, second;

  const char* nameOf(Choice value) const { return value == first.second ? first.first : second.first; }
};
const TwoChoices<RollingModel> ROLLING_MODELS{{"paper", RollingModel::Paper}, {"pooltool", RollingModel::Pooltool}};
const TwoChoices<BallBallFriction> BALL_BALL_FRICTION_MODELS{{"alciatore", BallBallFriction::Alciatore},
                                                             {"constant", BallBallFriction::Constant}};

/// `value` becomes the choice the parameter `name` names; any other name is refused.
template <class Choice>
Status readChoice(ParameterTree& parameters, const std::string& name, const TwoChoices<Choice>& choices, Choice& value)
{
  std::string chosen = choices.nameOf(value);
  if (Status status = parameters.read(name, chosen); !status)
    return status;
  if (chosen != choices.first.first && chosen != choices.second.first)
    return invalidArgument(name, std::string("must be \"") + choices.first.first + "\" or \"" + choices.second.first +
                                     "\", got \"" + chosen + "\"");
  value = chosen == choices.first.first ? choices.first.second : choices.second.second;
  return {};
}

Status readMotionChoices(ParameterTree& parameters, MotionParameters& motion)
{
  if (Status status = parameters.read("motion/planar", motion.planar); !status)
    return status;
  return readChoice(parameters, "motion/rolling_model", ROLLING_MODELS, motion.rolling_model);
}

Status readBallContactChoices(ParameterTree& parameters, BallContactSettings& contact)
{
  return readChoice(parameters, "ball_ball/friction_model", BALL_BALL_FRICTION_MODELS, contact.friction_model);
}

/// Each contact's surface by its parameter's name.
std::vector<std::pair<const char*, SurfaceContact*>> contactSurfaces(ShotConfiguration& shot)
{
  return {{"cue_contact", &shot.cue_contact},
          {"table/cloth", &shot.table.cloth},
          {"table/cushion", &shot.table.cushion},
          {"ball_ball", &shot.ball_contact.ball_ball}};
}

/// ~<contact>/law/type ("constant", "elastic_plastic"): each contact's law, at its default parameters; the law's
/// own parameters (~table/cushion/law/yield_speed) are numeric parameters, read after it.
Status readContactLaws(ParameterTree& parameters, ShotConfiguration& shot)
{
  for (auto [contact, surface] : contactSurfaces(shot))
  {
    const std::string name = std::string(contact) + "/law";
    std::string type = lawType(surface->normal_law);
    if (Status status = parameters.read(name + "/type", type); !status)
      return status;
    auto law = lawOfType(type, name);
    if (!law)
      return namedAsParameter(Status(law.error()));
    surface->normal_law = law.value();
  }
  return {};
}

Status checkNodeSettings(const NodeSettings& s)
{
  if (s.target_frame.empty() || s.target_frame.front() == '/')
    return invalidArgument("target_frame", "must be a non-empty frame id without a leading '/'");
  if (!(std::isfinite(s.tf_timeout) && s.tf_timeout >= 0.0 && s.tf_timeout <= 10.0))
    return invalidArgument("tf_timeout", "must be in [0, 10] s");
  if (!(s.sample_spacing >= 1e-3 && s.sample_spacing <= 1.0))
    return invalidArgument("sample_spacing", "must be in [0.001, 1] s");
  if (!(s.table_state_timeout >= 0.0 && s.table_state_timeout <= 3600.0))
    return invalidArgument("table_state_timeout", "must be in [0, 3600] s (0: a table state is never stale)");
  if (s.threads < 1 || s.threads > 64)
    return invalidArgument("threads", "must be in [1, 64]");
  if (!(s.recording.track_duration > 0.0 && s.recording.track_duration <= 60.0))
    return invalidArgument("calibration/track_duration", "must be in (0, 60] s");
  if (s.recording.max_shots < 1 || s.recording.max_shots > 200)
    return invalidArgument("calibration/max_shots", "must be in [1, 200]");
  return {};
}

/// The node's own settings, not the physics'.
Status readNodeSettings(ParameterTree& parameters, NodeSettings& s)
{
  int max_shots = static_cast<int>(s.recording.max_shots);
  Status status =
      firstError({parameters.read("target_frame", s.target_frame), parameters.read("tf_timeout", s.tf_timeout),
                  parameters.read("sample_spacing", s.sample_spacing),
                  parameters.read("table_state_timeout", s.table_state_timeout), parameters.read("threads", s.threads),
                  parameters.read("calibration/track_duration", s.recording.track_duration),
                  parameters.read("calibration/max_shots", max_shots)});
  s.recording.max_shots = static_cast<std::size_t>(std::max(max_shots, 0));
  return status;
}

Status readNumericParameters(ParameterTree& parameters, ShotConfiguration& shot)
{
  for (const NamedParameter& parameter : numericParameters(shot))
    if (Status status = parameters.read(parameterName(parameter.name), *parameter.value); !status)
      return status;
  return {};
}
}  // namespace

Expected<NodeSettings> readSettings(ParameterTree& parameters)
{
  NodeSettings s;
  // In order: what cannot be read, then the node's own settings, then the physics, then what nobody read.
  if (Status status = firstError({readNodeSettings(parameters, s), readContactLaws(parameters, s.shot)}); !status)
    return status.error();
  // After the laws: the names of a law's own parameters follow the law each contact has.
  if (Status status = firstError({readNumericParameters(parameters, s.shot), readPockets(parameters, s.shot.table),
                                  readMotionChoices(parameters, s.shot.motion),
                                  readBallContactChoices(parameters, s.shot.ball_contact)});
      !status)
    return status.error();
  auto planning = readPlanningSettings(parameters);
  auto cockpit = readCockpitSettings(parameters);
  if (Status status = firstError({checkNodeSettings(s), namedAsParameter(validate(s.shot))}); !status)
    return status.error();
  if (!planning)
    return planning.error();
  if (!cockpit)
    return cockpit.error();
  s.planning = planning.value();
  s.cockpit = cockpit.value();
  // Aside: ~tuning/ (dynamic_reconfigure's record of the tuned values) and ~diagnostic_period (diagnostic_updater's).
  if (Status status = parameters.checkEveryParameterWasRead({"tuning", "diagnostic_period"}); !status)
    return status.error();
  return s;
}

SettingsDescription describeSettings(NodeSettings s)
{
  SettingsDescription d;
  auto number = [&d](const std::string& name, double value)
  {
    d.names.push_back(name);
    d.values.push_back(value);
  };
  auto choice = [&d](const std::string& name, const std::string& value)
  {
    d.choice_names.push_back(name);
    d.choice_values.push_back(value);
  };
  number("tf_timeout", s.tf_timeout);
  number("sample_spacing", s.sample_spacing);
  number("table_state_timeout", s.table_state_timeout);
  number("threads", s.threads);
  number("calibration/track_duration", s.recording.track_duration);
  number("calibration/max_shots", static_cast<double>(s.recording.max_shots));
  for (const NamedParameter& parameter : numericParameters(s.shot))
    number(parameterName(parameter.name), *parameter.value);
  for (const PlanningParameter& parameter : planningParameters(s.planning))
    number(parameter.name, *parameter.value);
  number("planning/rollouts", s.planning.rollouts);
  number("planning/threads", s.planning.threads);
  number("cockpit/rate", s.cockpit.rate);
  number("cockpit/speed_scale", s.cockpit.speed_scale);
  number("cockpit/slow_motion", s.cockpit.slow_motion);
  choice("target_frame", s.target_frame);
  choice("cockpit/enabled", s.cockpit.enabled ? "true" : "false");
  choice("cockpit/animate", s.cockpit.animate ? "true" : "false");
  choice("motion/planar", s.shot.motion.planar ? "true" : "false");
  choice("motion/rolling_model", ROLLING_MODELS.nameOf(s.shot.motion.rolling_model));
  choice("ball_ball/friction_model", BALL_BALL_FRICTION_MODELS.nameOf(s.shot.ball_contact.friction_model));
  for (auto [contact, surface] : contactSurfaces(s.shot))
    choice(std::string(contact) + "/law/type", lawType(surface->normal_law));
  std::ostringstream pockets;
  pockets.precision(std::numeric_limits<double>::max_digits10);  // reads back to the same doubles
  pockets << "[";
  for (std::size_t i = 0; i < s.shot.table.pockets.size(); ++i)
  {
    const Pocket& pocket = s.shot.table.pockets[i];
    pockets << (i ? ", [" : "[") << pocket.centre.x() << ", " << pocket.centre.y() << ", " << pocket.radius << "]";
  }
  choice("table/pockets", pockets.str() + "]");
  return d;
}

Expected<NodeSettings> readSettings(const ros::NodeHandle& private_handle)
{
  XmlRpc::XmlRpcValue tree;
  ros::param::get(private_handle.getNamespace(), tree);  // absent: no parameters, every default
  ParameterTree parameters(tree);
  return readSettings(parameters);
}

}  // namespace billiard_shot_planner

#include "node_settings.hpp"
#include "parameter_names.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "billiard_shot_planner/core/validation.hpp"

namespace billiard_shot_planner
{
namespace
{
Status readPockets(const ros::NodeHandle& pnh, Table& table)
{
  table.pockets = sixPockets(table.length, table.width);
  XmlRpc::XmlRpcValue list;
  if (!pnh.getParam("table/pockets", list))
    return {};
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

/// A parameter that names one of two choices: `value` becomes `first` or `second`; anything else is refused.
template <class Choice>
Status readChoice(const ros::NodeHandle& pnh, const std::string& name, std::pair<const char*, Choice> first,
                  std::pair<const char*, Choice> second, Choice& value)
{
  std::string chosen = value == first.second ? first.first : second.first;
  pnh.param(name, chosen, chosen);
  if (chosen != first.first && chosen != second.first)
    return invalidArgument(
        name, std::string("must be \"") + first.first + "\" or \"" + second.first + "\", got \"" + chosen + "\"");
  value = chosen == first.first ? first.second : second.second;
  return {};
}

Status readMotionChoices(const ros::NodeHandle& pnh, MotionParameters& motion)
{
  pnh.param("motion/planar", motion.planar, motion.planar);
  return readChoice(pnh, "motion/rolling_model", std::pair{"paper", RollingModel::Paper},
                    std::pair{"pooltool", RollingModel::Pooltool}, motion.rolling_model);
}

Status readBallContactChoices(const ros::NodeHandle& pnh, BallContactSettings& contact)
{
  return readChoice(pnh, "ball_ball/friction_model", std::pair{"alciatore", BallBallFriction::Alciatore},
                    std::pair{"constant", BallBallFriction::Constant}, contact.friction_model);
}

/// ~<contact>/law/type ("constant", "elastic_plastic"): each contact's law, at its default parameters; the law's
/// own parameters (~table/cushion/law/yield_speed) are numeric parameters, read after it.
Status readContactLaws(const ros::NodeHandle& pnh, ShotConfiguration& shot)
{
  for (auto [contact, surface] :
       {std::pair{"cue_contact", &shot.cue_contact}, std::pair{"table/cloth", &shot.table.cloth},
        std::pair{"table/cushion", &shot.table.cushion}, std::pair{"ball_ball", &shot.ball_contact.ball_ball}})
  {
    const std::string name = std::string(contact) + "/law";
    std::string type;
    if (!pnh.getParam(name + "/type", type))
      continue;
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
}  // namespace

Expected<NodeSettings> readSettings(const ros::NodeHandle& pnh)
{
  NodeSettings s;
  pnh.param("target_frame", s.target_frame, s.target_frame);
  pnh.param("tf_timeout", s.tf_timeout, s.tf_timeout);
  pnh.param("sample_spacing", s.sample_spacing, s.sample_spacing);
  pnh.param("table_state_timeout", s.table_state_timeout, s.table_state_timeout);
  pnh.param("threads", s.threads, s.threads);
  pnh.param("calibration/track_duration", s.recording.track_duration, s.recording.track_duration);
  int max_shots = static_cast<int>(s.recording.max_shots);
  pnh.param("calibration/max_shots", max_shots, max_shots);
  s.recording.max_shots = static_cast<std::size_t>(std::max(max_shots, 0));
  if (Status status = readContactLaws(pnh, s.shot); !status)
    return status.error();
  for (const NamedParameter& parameter : numericParameters(s.shot))
    pnh.param(parameterName(parameter.name), *parameter.value, *parameter.value);
  // In order: what cannot be read, then the node's own settings, then the physics.
  if (Status status = readPockets(pnh, s.shot.table); !status)
    return status.error();
  if (Status status = readMotionChoices(pnh, s.shot.motion); !status)
    return status.error();
  if (Status status = readBallContactChoices(pnh, s.shot.ball_contact); !status)
    return status.error();
  if (Status status = firstError({checkNodeSettings(s), namedAsParameter(validate(s.shot))}); !status)
    return status.error();
  auto planning = readPlanningSettings(pnh);
  if (!planning)
    return planning.error();
  s.planning = planning.value();
  return s;
}

}  // namespace billiard_shot_planner

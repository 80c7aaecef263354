#include "node_settings.hpp"

#include <ros/param.h>
#include "parameter_names.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <utility>

#include "billiard_shot_planner/core/validation.hpp"
#include "billiard_shot_planner/shot/configuration_fields.hpp"

namespace billiard_shot_planner
{
namespace
{
/// ~table/pockets, [[x, y, radius, id], …] (the id optional); absent: the table's default ones for its size and layout
/// (defaultPockets).
Status readPockets(ParameterTree& parameters, const std::string& name, std::vector<Pocket>& pockets, const Table& table)
{
  pockets = defaultPockets(table);
  const XmlRpc::XmlRpcValue* found = parameters.find(name);
  if (!found)
    return {};
  XmlRpc::XmlRpcValue list = *found;  // XmlRpcValue's conversions are not const
  if (list.getType() != XmlRpc::XmlRpcValue::TypeArray)
    return invalidArgument(name, "must be a list of [x, y, radius, id] (the id optional)");
  pockets.clear();
  for (int i = 0; i < list.size(); ++i)
  {
    const std::string element = name + "[" + std::to_string(i) + "]";
    if (list[i].getType() != XmlRpc::XmlRpcValue::TypeArray || list[i].size() < 3 || list[i].size() > 4)
      return invalidArgument(element, "must be [x, y, radius] or [x, y, radius, id]");
    double values[3];
    for (int k = 0; k < 3; ++k)
    {
      XmlRpc::XmlRpcValue& v = list[i][k];
      if (v.getType() == XmlRpc::XmlRpcValue::TypeDouble)
        values[k] = static_cast<double>(v);
      else if (v.getType() == XmlRpc::XmlRpcValue::TypeInt)
        values[k] = static_cast<int>(v);
      else
        return invalidArgument(element, "must be [x, y, radius] numbers");
    }
    pockets.push_back({{values[0], values[1]}, values[2], ""});
    if (list[i].size() == 4)
    {
      if (list[i][3].getType() != XmlRpc::XmlRpcValue::TypeString)
        return invalidArgument(element + "[3]", "must be the pocket's id, a name");
      pockets.back().id = static_cast<std::string>(list[i][3]);
    }
  }
  return {};
}

/// Reads each field of the configuration from the parameter of its name (table.cloth.friction →
/// ~table/cloth/friction); an absent parameter keeps the field's value.
class ParameterReader final : public ConfigurationVisitor
{
public:
  explicit ParameterReader(ParameterTree& parameters) : parameters_(parameters) {}

  void number(const std::string& path, double& value) override { fail(parameters_.read(parameterName(path), value)); }
  void flag(const std::string& path, bool& value) override { fail(parameters_.read(parameterName(path), value)); }
  void choice(const std::string& path, std::string& value, const std::vector<std::string>& /*options*/) override
  {
    fail(parameters_.read(parameterName(path), value));
  }
  void pockets(const std::string& path, std::vector<Pocket>& pockets, const Table& table) override
  {
    fail(readPockets(parameters_, parameterName(path), pockets, table));
  }

private:
  ParameterTree& parameters_;
};

/// Lists each field of the configuration under its parameter's name: numbers as numbers, the rest as text.
class SettingsLister final : public ConfigurationVisitor
{
public:
  explicit SettingsLister(SettingsDescription& description) : d_(description) {}

  void number(const std::string& path, double& value) override
  {
    d_.names.push_back(parameterName(path));
    d_.values.push_back(value);
  }
  void flag(const std::string& path, bool& value) override { text(path, value ? "true" : "false"); }
  void choice(const std::string& path, std::string& value, const std::vector<std::string>& /*options*/) override
  {
    text(path, value);
  }
  void pockets(const std::string& path, std::vector<Pocket>& pockets, const Table& /*table*/) override
  {
    std::ostringstream list;
    list.precision(std::numeric_limits<double>::max_digits10);  // reads back to the same doubles
    list << "[";
    for (std::size_t i = 0; i < pockets.size(); ++i)
      list << (i ? ", [" : "[") << pockets[i].centre.x() << ", " << pockets[i].centre.y() << ", " << pockets[i].radius
           << ", " << pocketId(pockets, i) << "]";
    text(path, list.str() + "]");
  }

private:
  void text(const std::string& path, const std::string& value)
  {
    d_.choice_names.push_back(parameterName(path));
    d_.choice_values.push_back(value);
  }

  SettingsDescription& d_;
};

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

Status readConfiguration(ParameterTree& parameters, ShotConfiguration& shot)
{
  ParameterReader reader(parameters);
  return namedAsParameter(visitConfiguration(shot, reader));
}
}  // namespace

Expected<NodeSettings> readSettings(ParameterTree& parameters)
{
  NodeSettings s;
  // In order: what cannot be read, then the node's own settings, then the physics, then what nobody read.
  if (Status status = firstError({readNodeSettings(parameters, s), readConfiguration(parameters, s.shot)}); !status)
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
  SettingsLister lister(d);
  (void)visitConfiguration(s.shot, lister);  // a lister changes no choice: the walk cannot fail
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

#include "tuning.hpp"

#include <algorithm>

#include "billiard_shot_planner/shot/configuration_fields.hpp"
#include "parameter_names.hpp"

namespace billiard_shot_planner
{
namespace
{
using Descriptions = std::vector<ShotPredictorConfig::AbstractParamDescriptionConstPtr>;

/// Each number of the tuning paired with the configuration's value it tunes, found by name (tuningName): the cfg's
/// list is the only list. An error names a tuning number that is not a parameter of the node.
template <class Visitor>
Status visitNumbers(ShotConfiguration& c, ShotPredictorConfig& tuning, Visitor&& visit)
{
  const std::vector<NamedParameter> parameters = numericParameters(c);
  for (const auto& description : ShotPredictorConfig::__getParamDescriptions__())
  {
    const auto number = boost::dynamic_pointer_cast<const ShotPredictorConfig::ParamDescription<double>>(description);
    if (!number)
      continue;
    const auto parameter =
        std::find_if(parameters.begin(), parameters.end(),
                     [&](const NamedParameter& p) { return tuningName(parameterName(p.name)) == description->name; });
    if (parameter == parameters.end())
      return invalidArgument(description->name, "is not the tuning name of a parameter of the node");
    visit(tuning.*(number->field), *parameter->value);
  }
  return {};
}
}  // namespace

std::string tuningName(std::string parameter_name)
{
  std::replace(parameter_name.begin(), parameter_name.end(), '/', '_');
  return parameter_name;
}

ShotPredictorConfig toTuning(const ShotConfiguration& configuration)
{
  ShotConfiguration c = configuration;
  ShotPredictorConfig tuning = ShotPredictorConfig::__getDefault__();
  // A tuning number that is no parameter keeps its default here; applyTuning() refuses it (test_tuning.cpp).
  static_cast<void>(visitNumbers(c, tuning, [](double& tuned, double value) { tuned = value; }));
  tuning.motion_rolling_model = nameOf(c.motion.rolling_model);
  tuning.motion_planar = c.motion.planar;
  return tuning;
}

Expected<ShotConfiguration> applyTuning(ShotConfiguration configuration, const ShotPredictorConfig& tuning)
{
  ShotPredictorConfig t = tuning;
  if (Status status = visitNumbers(configuration, t, [](double tuned, double& value) { value = tuned; }); !status)
    return status.error();
  auto model = rollingModelNamed(t.motion_rolling_model, "motion/rolling_model");
  if (!model)
    return model.error();
  configuration.motion.rolling_model = model.value();
  configuration.motion.planar = t.motion_planar;
  if (Status status = namedAsParameter(validate(configuration)); !status)
    return status.error();
  return configuration;
}

}  // namespace billiard_shot_planner

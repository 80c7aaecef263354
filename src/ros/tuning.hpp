#pragma once

#include <billiard_shot_planner/ShotPredictorConfig.h>

#include <string>

#include "billiard_shot_planner/core/expected.hpp"
#include "billiard_shot_planner/shot/shot_prediction.hpp"

namespace billiard_shot_planner
{
/// A parameter's name in the tuning (cfg/ShotPredictor.cfg): its name with each '/' as '_' ("table/cloth/friction"
/// → "table_cloth_friction"), dynamic_reconfigure allowing no '/'.
std::string tuningName(std::string parameter_name);

/// The dynamic_reconfigure view of a configuration (cfg/ShotPredictor.cfg): the values a user may tune at run time.
ShotPredictorConfig toTuning(const ShotConfiguration& configuration);

/// The configuration with the tuned values applied, or the validation error (the configuration is then unchanged);
/// a tuning number that is not the tuning name of a parameter of the node is an error too.
Expected<ShotConfiguration> applyTuning(ShotConfiguration configuration, const ShotPredictorConfig& tuning);

}  // namespace billiard_shot_planner

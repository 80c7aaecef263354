#pragma once

#include <billiard_shot_planner/ShotPredictorConfig.h>

#include "billiard_shot_planner/core/expected.hpp"
#include "billiard_shot_planner/shot/shot_prediction.hpp"

namespace billiard_shot_planner
{
/// The dynamic_reconfigure view of a configuration (cfg/ShotPredictor.cfg): the values a user may tune at run time.
ShotPredictorConfig toTuning(const ShotConfiguration& configuration);

/// The configuration with the tuned values applied, or the validation error (the configuration is then unchanged).
Expected<ShotConfiguration> applyTuning(ShotConfiguration configuration, const ShotPredictorConfig& tuning);

}  // namespace billiard_shot_planner

#pragma once

// The fits' unknowns as values of a configuration: shared by the strike and the track fits.
#include <string>
#include <vector>

#include "billiard_shot_planner/calibration/least_squares_fit.hpp"
#include "billiard_shot_planner/core/expected.hpp"
#include "billiard_shot_planner/shot/shot_prediction.hpp"

namespace billiard_shot_planner
{
/// Whether `name` is among `own`: an unknown that the fit applies itself, not a configuration's parameter.
bool isOwn(const std::string& name, const std::vector<std::string>& own);

/// The parameters' names, once each is known to be a parameter of the configuration (or among `own`) that accepts
/// its start. Error: the configuration's, naming the parameter.
Expected<std::vector<std::string>> checkedNames(const ShotConfiguration& configuration,
                                                const std::vector<FitParameter>& parameters,
                                                const std::vector<std::string>& own = {});

/// Sets the named parameters (but those among `own`) of `configuration` to `values`. Error: the first refused.
Status applyValues(ShotConfiguration& configuration, const std::vector<std::string>& names,
                   const std::vector<double>& values, const std::vector<std::string>& own = {});

}  // namespace billiard_shot_planner

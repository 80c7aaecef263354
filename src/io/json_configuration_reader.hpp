#pragma once

// The configuration in an impact_solve request, read by the one list of fields (visitConfiguration): the request's
// layout of them (docs/cli.md) and its reader (json_configuration_reader.cpp).
#include <optional>
#include <string>
#include <vector>

#include "billiard_shot_planner/shot/shot_prediction.hpp"
#include "json_fields.hpp"

namespace billiard_shot_planner
{
namespace json_io
{
/// Where a request keeps a field of the configuration: the motion's constants at the top level ("motion.gravity" →
/// "gravity"), the solver's in "solver" (read by solverOptions), every other field at its own path ("table.cloth.eta2",
/// "cue_contact.law.type"). "cue_end_mass" is kg or "inf", a tip held on the cue's axis (the paper's shooter).
std::optional<std::string> requestPlace(const std::string& configuration_path);

/// The parts of a request's configuration a problem reads: the strike's (the cue, the ball, the tip's contact, the
/// stiffness ratio and the cloth, in "table" or as "table_contact"), the motion's (the ball, the table and the
/// motion's constants), the ball–ball contact's.
enum class ConfigurationPart
{
  Strike,
  Motion,
  BallContact,
};

/// The top-level fields of those parts in the request layout, with "table_file", which gives them all.
std::vector<std::string> requestFieldsOf(const std::vector<ConfigurationPart>& parts);

/// An error about the configuration in the request's own names ("motion.sliding_friction" → "sliding_friction").
Error inRequestLayout(Error error);

/// The configuration a request gives: the defaults (config/default.yaml), under its "table_file" when it names one,
/// else with the strike's "table_contact" as the table's cloth, under the request's own fields in the request layout.
/// A key inside the configuration's objects ("table", "cue_contact", "ball_ball", a law) that is none of its fields is
/// refused, naming it. Values are read, not validated: each problem validates the part it uses.
Expected<ShotConfiguration> requestConfiguration(const json& request);

/// The strike's cloth: the request's "table_contact" over the table file's cloth (or the default cloth) when it
/// gives one, else the table's cloth.
Expected<SurfaceContact> strikeCloth(const json& request, const ShotConfiguration& configuration);

}  // namespace json_io
}  // namespace billiard_shot_planner

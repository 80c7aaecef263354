#include "cockpit_settings.hpp"

#include "billiard_shot_planner/core/validation.hpp"

namespace billiard_shot_planner
{
Expected<CockpitSettings> readCockpitSettings(ParameterTree& parameters)
{
  CockpitSettings s;
  if (Status status = firstError(
          {parameters.read("cockpit/enabled", s.enabled), parameters.read("cockpit/rate", s.rate),
           parameters.read("cockpit/speed_scale", s.speed_scale), parameters.read("cockpit/animate", s.animate),
           parameters.read("cockpit/slow_motion", s.slow_motion),
           requireWithin(s.rate, 0.5, 100.0, "cockpit/rate", "Hz"),
           requireWithin(s.speed_scale, 0.01, 1.0, "cockpit/speed_scale", "m per m/s"),
           requireWithin(s.slow_motion, MIN_SLOW_MOTION, MAX_SLOW_MOTION, "cockpit/slow_motion", "times real time")});
      !status)
    return status.error();
  return s;
}

}  // namespace billiard_shot_planner

#pragma once

#include "billiard_shot_planner/core/expected.hpp"
#include "parameter_tree.hpp"

namespace billiard_shot_planner
{
/// The rviz cockpit's parameters (~cockpit/...): the cue a person drags, click-to-plan and the animation.
struct CockpitSettings
{
  bool enabled = true;       ///< serve ~cue_control, plan on clicked_point, animate on ~animation
  double rate = 10.0;        ///< Hz: while the cue is dragged, predictions at most this often (the latest wins)
  double speed_scale = 0.1;  ///< m of the speed handle's distance behind the ball per m/s of cue speed
  bool animate = true;       ///< play every new prediction on ~animation
  double slow_motion = 1.0;  ///< 1: animations in real time; 2: at half speed
};

/// Reads ~cockpit/... (absent ones keep their defaults) and checks them; the error names the parameter.
Expected<CockpitSettings> readCockpitSettings(ParameterTree& parameters);

/// The bounds of ~cockpit/slow_motion, which the ~animate service also takes.
constexpr double MIN_SLOW_MOTION = 0.05;
constexpr double MAX_SLOW_MOTION = 100.0;

}  // namespace billiard_shot_planner

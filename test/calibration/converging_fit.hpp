#pragma once

#include "billiard_shot_planner/calibration/least_squares_fit.hpp"

/// Options for a test whose fit must converge: the longest wall-clock budget allowed. The fits' 60 s default is a
/// safety net in seconds, and the sanitized build runs them twenty times slower: a fit cut short there would answer
/// where it stopped, not where it converges.
inline billiard_shot_planner::FitOptions convergingFit()
{
  billiard_shot_planner::FitOptions options;
  options.max_seconds = 3600.0;
  return options;
}

#pragma once

#include <Eigen/Core>
#include <cmath>
#include <sstream>
#include <string>

#include "billiard_shot_planner/core/expected.hpp"

namespace billiard_shot_planner
{
/// A number as a person writes it, for messages: 1e-20 stays 1e-20 (std::to_string would print 0.000000).
inline std::string formatNumber(double value)
{
  std::ostringstream text;
  text << value;
  return text.str();
}

/// Field checks shared by every input type. Each returns an Error naming the field, or success.

inline Status requireFinite(double value, const std::string& field)
{
  if (!std::isfinite(value))
    return invalidArgument(field, "must be a finite number");
  return {};
}

inline Status requirePositive(double value, const std::string& field)
{
  if (!std::isfinite(value) || value <= 0.0)
    return invalidArgument(field, "must be finite and > 0, got " + formatNumber(value));
  return {};
}

/// A mass that may be infinite (a body held in place): > 0, not NaN.
inline Status requirePositiveOrInfinite(double value, const std::string& field)
{
  if (std::isnan(value) || value <= 0.0)
    return invalidArgument(field, "must be > 0 (or infinite), got " + formatNumber(value));
  return {};
}

inline Status requireNonNegative(double value, const std::string& field)
{
  if (!std::isfinite(value) || value < 0.0)
    return invalidArgument(field, "must be finite and >= 0, got " + formatNumber(value));
  return {};
}

inline Status requireUnitInterval(double value, const std::string& field)
{
  if (!std::isfinite(value) || value < 0.0 || value > 1.0)
    return invalidArgument(field, "must be in [0, 1], got " + formatNumber(value));
  return {};
}

template <class Derived>
Status requireFinite(const Eigen::MatrixBase<Derived>& value, const std::string& field)
{
  if (!value.allFinite())
    return invalidArgument(field, "contains NaN or infinite entries");
  return {};
}

/// A value within [lowest, highest]; `why` says what the range stands for.
inline Status requireWithin(double value, double lowest, double highest, const std::string& field, const char* why)
{
  if (!(value >= lowest && value <= highest))
    return invalidArgument(field, "must be in [" + formatNumber(lowest) + ", " + formatNumber(highest) + "] (" + why +
                                      "), got " + formatNumber(value));
  return {};
}

/// Ratios of two contacts' normal stiffnesses that the package accepts. The solve's work grows as a ratio departs
/// from one (a trajectory with cushion hits: 17 ms at 1, 0.19 s at 0.01, 0.5 s at 0.001, 65 s at 2e-6); no billiard
/// contact pair is a hundred times stiffer than another.
constexpr double MIN_STIFFNESS_RATIO = 1e-2;
constexpr double MAX_STIFFNESS_RATIO = 1e2;

inline Status requireStiffnessRatio(double value, const std::string& field)
{
  return requireWithin(value, MIN_STIFFNESS_RATIO, MAX_STIFFNESS_RATIO, field, "a ratio of contact stiffnesses");
}

/// Ratios of two bodies' masses that the package accepts. A light body between heavy ones rattles at √(mass ratio)
/// times the collision's own frequency, so the work of a solve grows with it (a three-ball chain with masses over
/// nine decades ran 170 000 steps into the time bound), and the kinetic energy of the light body drowns in the
/// heavy one's round-off (at m1/m2 = 5e9 a collision's energy rose by 2.8e-8 of the initial). Billiard bodies are
/// within a thousand of each other (a 0.5 kg cue, a 15 g tip, 0.16 kg balls); a million leaves room for
/// research problems.
constexpr double MAX_MASS_RATIO = 1e6;

/// `ratio` (named `ratio_name` in the message, "m1/m2") within [1/MAX_MASS_RATIO, MAX_MASS_RATIO].
inline Status requireMassRatio(double ratio, const std::string& field, const std::string& ratio_name)
{
  if (!(ratio >= 1.0 / MAX_MASS_RATIO && ratio <= MAX_MASS_RATIO))
    return invalidArgument(field, ratio_name + " must be in [" + formatNumber(1.0 / MAX_MASS_RATIO) + ", " +
                                      formatNumber(MAX_MASS_RATIO) + "] (a ratio of body masses), got " +
                                      formatNumber(ratio));
  return {};
}

/// The fastest speed, m/s, that a billiard input may have: a break shot's cue ball leaves at about 12 m/s, so 100
/// m/s leaves a wide margin; beyond it a value is a mistake (1e300 m/s), and far beyond, it overflows the answer.
constexpr double MAX_PLAUSIBLE_SPEED = 100.0;

/// A speed (or a surface speed ωR) no faster than MAX_PLAUSIBLE_SPEED.
inline Status requirePlausibleSpeed(double speed, const std::string& field)
{
  if (!(speed <= MAX_PLAUSIBLE_SPEED))
    return invalidArgument(field, "must be at most " + formatNumber(MAX_PLAUSIBLE_SPEED) +
                                      " m/s, a billiard speed, got " + formatNumber(speed));
  return {};
}

/// A direction: finite and of non-zero length (it is normalised by the caller).
inline Status requireDirection(const Eigen::Vector3d& value, const std::string& field)
{
  if (!value.allFinite())
    return invalidArgument(field, "contains NaN or infinite entries");
  if (value.norm() < 1e-12)
    return invalidArgument(field, "has zero length");
  return {};
}

/// The first failed check of a list, or success.
inline Status firstError(std::initializer_list<Status> checks)
{
  for (const Status& status : checks)
    if (!status)
      return status;
  return {};
}

}  // namespace billiard_shot_planner

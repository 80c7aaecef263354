#pragma once

#include <Eigen/Core>
#include <vector>

#include "billiard_shot_planner/calibration/least_squares_fit.hpp"
#include "billiard_shot_planner/core/expected.hpp"
#include "billiard_shot_planner/shot/shot_prediction.hpp"

namespace billiard_shot_planner
{
/// A strike whose outcome was seen: the cue as executed and the ball's planar velocity and spin right after it (what
/// a camera recovers from the first frames of the ball's path).
struct ObservedStrike
{
  CuePlacement cue;
  Eigen::Vector2d velocity = Eigen::Vector2d::Zero();          ///< v_x, v_y, m/s
  Eigen::Vector2d angular_velocity = Eigen::Vector2d::Zero();  ///< ω_x, ω_y, rad/s
  double velocity_sigma = 0.05;                                ///< m/s, the observation's standard deviation
  double angular_velocity_sigma = 2.0;                         ///< rad/s
};

/// Beside the configuration's numeric parameters (numericParameters(): "cue_contact.eta2", "stiffness_ratio", …), a
/// strike fit may turn every observed cue about its hit point: by "cue.yaw" (rad) about the vertical
/// (counter-clockwise seen from above), and by "cue.pitch" (rad) about the horizontal line across it, raising its
/// elevation. They stand for a cue direction known only roughly.
inline const char* const CUE_YAW = "cue.yaw";
inline const char* const CUE_PITCH = "cue.pitch";

/// The cue turned about the point where its axis meets the ball (so the hit point stays): its elevation raised by
/// `pitch`, then turned by `yaw` about the vertical. Errors: the axis misses the ball.
Expected<CuePlacement> turnedCue(const CuePlacement& cue, double yaw, double pitch, double ball_radius);

/// The configuration and a cue with a fit's named values applied. Errors: a name that is neither the
/// configuration's nor the cue's, a value the configuration rejects, a turned cue that misses the ball.
Status applyFitted(const std::vector<std::string>& names, const std::vector<double>& values,
                   ShotConfiguration& configuration, CuePlacement& cue);

/// Fits the named parameters of the strike to observed strikes (every one with the same configuration), by
/// fitLeastSquares on (v − v_obs)/σ_v and (ω − ω_obs)/σ_ω. Errors: InvalidArgument naming the parameter (unknown, or
/// its start rejected by the configuration) or the observation ("strikes[2].velocity"), and fitLeastSquares' own.
Expected<FitResult> fitStrikes(const ShotConfiguration& configuration, const std::vector<FitParameter>& parameters,
                               const std::vector<ObservedStrike>& strikes, const FitOptions& options = {});

}  // namespace billiard_shot_planner

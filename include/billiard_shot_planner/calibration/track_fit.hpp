#pragma once

#include <Eigen/Core>
#include <map>
#include <string>
#include <vector>

#include "billiard_shot_planner/calibration/least_squares_fit.hpp"
#include "billiard_shot_planner/core/expected.hpp"
#include "billiard_shot_planner/shot/shot_prediction.hpp"

namespace billiard_shot_planner
{
/// A ball's centre seen by a camera: t seconds after the strike, at (x, y) on the table.
struct TrackPoint
{
  double t = 0.0;
  Eigen::Vector2d position = Eigen::Vector2d::Zero();
};

/// An executed shot and what was seen of it: the cue as executed, the other balls where they stood, and the tracks
/// of any of the balls by id (CUE_BALL_ID for the cue ball). A track may start late, miss frames or stop early.
struct ObservedShot
{
  CuePlacement cue;
  std::vector<TableBall> others;
  std::map<std::string, std::vector<TrackPoint>> tracks;
};

struct TrackFit
{
  FitResult fit;
  /// Per shot, the root mean square of the distance between the tracks and the fitted prediction, m.
  std::vector<double> shot_rms;
};

/// Fits the named parameters of the configuration (numericParameters(): "motion.sliding_friction",
/// "table.cushion.restitution", …) to the tracks of executed shots, by
/// fitLeastSquares on every track point's (x, y) residual over `position_sigma`. Errors: InvalidArgument naming the
/// parameter, the shot or the observation ("shots[3].tracks.cue[17].t": NaN, negative, out of order),
/// position_sigma, or fewer observations than parameters; a shot whose cue misses its ball, named.
Expected<TrackFit> fitTracks(const ShotConfiguration& configuration, const std::vector<FitParameter>& parameters,
                             const std::vector<ObservedShot>& shots, double position_sigma,
                             const FitOptions& options = {});

}  // namespace billiard_shot_planner

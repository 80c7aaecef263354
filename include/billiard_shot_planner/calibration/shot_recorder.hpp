#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <deque>
#include <string>
#include <utility>
#include <vector>

#include "billiard_shot_planner/calibration/track_fit.hpp"
#include "billiard_shot_planner/core/expected.hpp"

namespace billiard_shot_planner
{
/// The balls a camera saw at one instant: ids and centres on the table, in the table frame.
struct TableSighting
{
  double time = 0.0;  ///< s, on the clock the strikes are given on
  std::vector<std::pair<std::string, Eigen::Vector2d>> balls;
};

/// Bounds on what a recorder keeps: every one a limit on memory, not on the fit.
struct RecorderLimits
{
  /// A shot's tracks are the sightings up to this long after its strike (and before the next recorded strike), s.
  double track_duration = 10.0;
  std::size_t max_shots = 200;
  /// Track points over all shots; sightings past it are dropped (and counted).
  std::size_t max_points = 200000;
  /// Sightings kept from before the newest shot, so that a shot may be recorded after it was struck.
  std::size_t history = 2000;
};

/// Turns a stream of sightings into observed shots: a shot is recorded with its cue and the balls where they stood,
/// and every sighting stamped within its track duration after the strike — those already seen included, up to the
/// next recorded strike — becomes a point of its balls' tracks. Sightings may arrive late or out of order: each
/// point takes its place in time order, and one at a time its track already has is a repeat, dropped and counted.
/// Not thread-safe.
class ShotRecorder
{
public:
  explicit ShotRecorder(RecorderLimits limits = {});

  /// Records a shot struck at `strike_time`: its cue and the balls other than the cue ball (its tracks, if any, are
  /// kept and extended). Returns its index. Errors: InvalidArgument naming "strike_time" (not finite, or before the
  /// previous strike) or "shots" (max_shots reached).
  Expected<std::size_t> record(ObservedShot shot, double strike_time);
  /// Adds a sighting to the tracks of the shot whose window holds it, and to the history.
  void observe(const TableSighting& sighting);
  /// The latest sighting at or before `time`, if the history holds one.
  const TableSighting* sightingAtOrBefore(double time) const;

  const std::vector<ObservedShot>& shots() const { return shots_; }
  std::size_t points() const { return points_; }
  std::size_t droppedPoints() const { return dropped_points_; }
  void clear();

private:
  /// The index of the shot whose window holds `time`, or shots_.size() when none does.
  std::size_t shotAt(double time) const;
  void addPoints(std::size_t shot, const TableSighting& sighting);
  /// Drops the shot's points from `time` on: the balls were struck again.
  void endWindow(std::size_t shot, double time);

  RecorderLimits limits_;
  std::vector<ObservedShot> shots_;
  std::vector<double> strike_times_;
  std::deque<TableSighting> history_;
  std::size_t points_ = 0;
  std::size_t dropped_points_ = 0;
};

}  // namespace billiard_shot_planner

#include "billiard_shot_planner/calibration/shot_recorder.hpp"

#include <algorithm>
#include <cmath>

#include "billiard_shot_planner/core/validation.hpp"

namespace billiard_shot_planner
{
namespace
{
bool takesPart(const ObservedShot& shot, const std::string& id)
{
  return id == CUE_BALL_ID ||
         std::any_of(shot.others.begin(), shot.others.end(), [&](const TableBall& ball) { return ball.id == id; });
}
}  // namespace

ShotRecorder::ShotRecorder(RecorderLimits limits) : limits_(limits) {}

Expected<std::size_t> ShotRecorder::record(ObservedShot shot, double strike_time)
{
  if (!std::isfinite(strike_time))
    return invalidArgument("strike_time", "must be finite");
  if (!strike_times_.empty() && strike_time < strike_times_.back())
    return invalidArgument("strike_time", "comes before the previous recorded strike (" +
                                              formatNumber(strike_times_.back()) + " s): record shots in order");
  if (shots_.size() >= limits_.max_shots)
    return invalidArgument(
        "shots", "at most " + std::to_string(limits_.max_shots) + " shots are kept: fit them, or clear them, first");
  if (!shots_.empty())
    endWindow(shots_.size() - 1, strike_time);
  for (const auto& entry : shot.tracks)
    points_ += entry.second.size();
  shots_.push_back(std::move(shot));
  strike_times_.push_back(strike_time);
  const std::size_t index = shots_.size() - 1;
  // Sightings already seen after the strike belong to the new shot (and no longer to the one before it).
  for (const TableSighting& sighting : history_)
    if (shotAt(sighting.time) == index)
      addPoints(index, sighting);
  return index;
}

void ShotRecorder::observe(const TableSighting& sighting)
{
  if (!std::isfinite(sighting.time))
    return;
  const std::size_t shot = shotAt(sighting.time);
  if (shot < shots_.size())
    addPoints(shot, sighting);
  history_.push_back(sighting);
  while (history_.size() > limits_.history)
    history_.pop_front();
}

const TableSighting* ShotRecorder::sightingAtOrBefore(double time) const
{
  const TableSighting* latest = nullptr;
  for (const TableSighting& sighting : history_)
    if (sighting.time <= time && (!latest || sighting.time >= latest->time))
      latest = &sighting;
  return latest;
}

void ShotRecorder::endWindow(std::size_t shot, double time)
{
  const double end = time - strike_times_[shot];
  for (auto& entry : shots_[shot].tracks)
  {
    std::vector<TrackPoint>& track = entry.second;
    const auto first_after =
        std::find_if(track.begin(), track.end(), [&](const TrackPoint& point) { return point.t >= end; });
    points_ -= static_cast<std::size_t>(track.end() - first_after);
    track.erase(first_after, track.end());
  }
}

void ShotRecorder::clear()
{
  shots_.clear();
  strike_times_.clear();
  history_.clear();
  points_ = 0;
  dropped_points_ = 0;
}

std::size_t ShotRecorder::shotAt(double time) const
{
  // The last strike at or before `time`; its window ends at its track duration or at the next strike.
  const auto after = std::upper_bound(strike_times_.begin(), strike_times_.end(), time);
  if (after == strike_times_.begin())
    return shots_.size();
  const std::size_t index = static_cast<std::size_t>(after - strike_times_.begin()) - 1;
  const double t = time - strike_times_[index];
  return t <= limits_.track_duration ? index : shots_.size();
}

void ShotRecorder::addPoints(std::size_t shot, const TableSighting& sighting)
{
  const double t = sighting.time - strike_times_[shot];
  ObservedShot& observed = shots_[shot];
  for (const auto& [id, position] : sighting.balls)
  {
    if (!takesPart(observed, id))
      continue;  // a ball that was not on the table at the strike: the fit has nothing to predict it from
    std::vector<TrackPoint>& track = observed.tracks[id];
    // In time order: a sighting may come late (a transform that came late, a slow network); one at a time the
    // track already has is a repeat.
    const auto place = std::lower_bound(track.begin(), track.end(), t,
                                        [](const TrackPoint& point, double time) { return point.t < time; });
    if (points_ >= limits_.max_points || !position.allFinite() || (place != track.end() && place->t == t))
    {
      ++dropped_points_;
      continue;
    }
    track.insert(place, {t, position});
    ++points_;
  }
}

}  // namespace billiard_shot_planner

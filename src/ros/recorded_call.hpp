#pragma once

#include <billiard_shot_planner/ErrorCode.h>
#include <ros/time.h>

#include <functional>
#include <string>

namespace billiard_shot_planner
{
/// Where a server reports each call it answered: its name ("plan_shot"), its wall-clock seconds, its code and message
/// (the node's health, NodeHealth::recordCall).
using CallRecorder = std::function<void(const std::string&, double, const ErrorCode&, const std::string&)>;

/// work()'s result (a service's or an action's, with error_code and message; a reference stays one), timed and
/// reported to `record` as `call` (nothing is reported when `record` is empty).
template <class Work>
decltype(auto) recordedCall(const CallRecorder& record, const std::string& call, Work&& work)
{
  const ros::WallTime start = ros::WallTime::now();
  decltype(auto) result = work();
  if (record)
    record(call, (ros::WallTime::now() - start).toSec(), result.error_code, result.message);
  return result;
}

}  // namespace billiard_shot_planner

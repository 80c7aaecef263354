#include "node_health.hpp"

#include <billiard_shot_planner/ErrorCode.h>

#include <algorithm>
#include <vector>

#include "error_codes.hpp"

namespace billiard_shot_planner
{
namespace
{
/// A failure for which the node, its inputs' timing or its limits are to blame (ErrorCode's -10 to -39), rather than
/// the request (-1 to -9) or the table (NO_SHOT_FOUND): what an operator should look at.
bool isNodeFailure(int32_t code)
{
  return code <= ErrorCode::TRANSFORM_FAILED && code > ErrorCode::NO_SHOT_FOUND;
}

double median(std::vector<double> values)
{
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}
}  // namespace

void NodeHealth::recordCall(const std::string& call, double seconds, int32_t code, const std::string& message,
                            const ros::Time& at)
{
  std::lock_guard<std::mutex> lock(mutex_);
  CallStatistics& statistics = calls_[call];
  ++statistics.calls;
  statistics.latencies.push_back(seconds);
  if (statistics.latencies.size() > LATENCY_WINDOW)
    statistics.latencies.pop_front();
  if (code == ErrorCode::SUCCESS)
  {
    node_failed_since_report_ = false;  // the node works again
    return;
  }
  ++statistics.failures;
  last_error_ = {call, code, message, at};
  node_failed_since_report_ = isNodeFailure(code);
}

void NodeHealth::recordTableState(const ros::Time& received)
{
  std::lock_guard<std::mutex> lock(mutex_);
  latest_table_state_ = received;
  ++table_states_in_period_;
}

void NodeHealth::reportCalls(diagnostic_updater::DiagnosticStatusWrapper& status) const
{
  for (const auto& [call, statistics] : calls_)
  {
    status.add(call + " calls", statistics.calls);
    status.add(call + " failed", statistics.failures);
    const std::vector<double> latencies(statistics.latencies.begin(), statistics.latencies.end());
    status.add(call + " latency median (ms)", 1e3 * median(latencies));
    status.add(call + " latency max (ms)", 1e3 * *std::max_element(latencies.begin(), latencies.end()));
  }
  if (last_error_.code == 0)
    return;
  status.add("last error", last_error_.call + ": " + errorCodeName(last_error_.code) + ": " + last_error_.message);
  status.add("last error stamp (s)", last_error_.at.toSec());
}

bool NodeHealth::reportTableState(diagnostic_updater::DiagnosticStatusWrapper& status, const ros::Time& now)
{
  const double period = period_start_.isZero() ? 0.0 : (now - period_start_).toSec();
  if (period > 0.0)
    status.add("table_state rate (Hz)", static_cast<double>(table_states_in_period_) / period);
  period_start_ = now;
  table_states_in_period_ = 0;
  if (latest_table_state_.isZero())
  {
    status.add("table_state age (s)", "none received");
    return false;
  }
  const double age = (now - latest_table_state_).toSec();
  status.add("table_state age (s)", age);
  return table_state_timeout_ > 0.0 && age > table_state_timeout_;
}

void NodeHealth::report(diagnostic_updater::DiagnosticStatusWrapper& status, const ros::Time& now)
{
  std::lock_guard<std::mutex> lock(mutex_);
  const bool stale = reportTableState(status, now);
  reportCalls(status);
  if (stale)
    status.summary(diagnostic_msgs::DiagnosticStatus::WARN,
                   "the latest ~table_state is older than ~table_state_timeout: requests without balls are refused");
  else if (node_failed_since_report_)
    status.summary(diagnostic_msgs::DiagnosticStatus::WARN, "the last call failed: " + last_error_.call + ": " +
                                                                errorCodeName(last_error_.code) + ": " +
                                                                last_error_.message);
  else
    status.summary(diagnostic_msgs::DiagnosticStatus::OK, "ready");
  node_failed_since_report_ = false;
}

}  // namespace billiard_shot_planner

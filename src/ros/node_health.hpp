#pragma once

#include <diagnostic_updater/DiagnosticStatusWrapper.h>
#include <ros/time.h>

#include <cstdint>
#include <deque>
#include <map>
#include <mutex>
#include <string>

namespace billiard_shot_planner
{
/// What /diagnostics says of the node: how long its calls take and how many fail, how often and how recently
/// ~table_state arrives, and the last error. The service threads and the subscriber record; the diagnostic updater
/// reports. Thread-safe.
class NodeHealth
{
public:
  /// Latencies kept per call for the median and the maximum.
  static constexpr std::size_t LATENCY_WINDOW = 100;

  /// `table_state_timeout`: s, the age beyond which the latest table state is stale (0: never).
  explicit NodeHealth(double table_state_timeout) : table_state_timeout_(table_state_timeout) {}

  /// A call of `call` ("predict_shot") answered at `at` after `seconds`, with its ErrorCode value and message.
  void recordCall(const std::string& call, double seconds, int32_t code, const std::string& message,
                  const ros::Time& at);
  void recordTableState(const ros::Time& received);

  /// The node's state at `now`: WARN when the latest table state is stale or the last call since the previous
  /// report failed for a reason of the node's (tf, freshness, a limit, numerics: not a caller's bad request or a
  /// table with no pot); OK otherwise. Each figure is a key–value pair. Starts the next period of the table state's
  /// rate.
  void report(diagnostic_updater::DiagnosticStatusWrapper& status, const ros::Time& now);

private:
  struct CallStatistics
  {
    std::deque<double> latencies;  ///< s, the last LATENCY_WINDOW
    long calls = 0;
    long failures = 0;
  };
  struct LastError
  {
    std::string call;
    int32_t code = 0;
    std::string message;
    ros::Time at;
  };

  void reportCalls(diagnostic_updater::DiagnosticStatusWrapper& status) const;
  /// The table state's age and rate; whether it is stale.
  bool reportTableState(diagnostic_updater::DiagnosticStatusWrapper& status, const ros::Time& now);

  const double table_state_timeout_;
  std::mutex mutex_;
  std::map<std::string, CallStatistics> calls_;
  ros::Time latest_table_state_;  ///< zero: none yet
  long table_states_in_period_ = 0;
  ros::Time period_start_;  ///< zero: before the first report
  LastError last_error_;
  bool node_failed_since_report_ = false;  ///< the last failed call failed for a reason of the node's
};

}  // namespace billiard_shot_planner

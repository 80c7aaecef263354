#pragma once

#include <billiard_shot_planner/GetConfiguration.h>
#include <billiard_shot_planner/GetTable.h>
#include <billiard_shot_planner/PlayerStroke.h>
#include <billiard_shot_planner/PredictShot.h>
#include <billiard_shot_planner/ShotPredictorConfig.h>
#include <billiard_shot_planner/TableGeometry.h>
#include <billiard_shot_planner/TableState.h>
#include <diagnostic_updater/diagnostic_updater.h>
#include <dynamic_reconfigure/server.h>
#include <message_filters/subscriber.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/message_filter.h>
#include <tf2_ros/transform_listener.h>
#include <boost/thread/recursive_mutex.hpp>

#include <memory>
#include <mutex>
#include <optional>

#include "cue_cockpit.hpp"
#include "node_health.hpp"
#include "node_settings.hpp"
#include "shot_animator.hpp"
#include "shot_calibration_server.hpp"
#include "shot_planner_server.hpp"

namespace billiard_shot_planner
{
/// The ROS face of the core library: ~predict_shot in, ~prediction and ~trajectory_markers out; the planner's
/// ~plan_shot and ~plan_shot_now (ShotPlannerServer) and calibration's ~record_shot, ~fit_calibration and
/// ~clear_shots (ShotCalibrationServer) share its table, tf buffer and configuration; ~get_configuration answers
/// the configuration in force, and /diagnostics reports the node's health (NodeHealth). A thin adapter:
/// messages and tf2 in, predictShot(), messages and markers out. The core is pure and thread-safe, so the service
/// may be served by several threads at once; the physical parameters can be tuned at run time (~tuning, through
/// dynamic_reconfigure), each request using a consistent snapshot of them.
class ShotPredictorNode
{
public:
  /// Throws std::runtime_error naming the parameter when a parameter is invalid (the node then exits).
  ShotPredictorNode(ros::NodeHandle& node, ros::NodeHandle& private_node);

  int threads() const { return settings_.threads; }

private:
  /// answer(), timed and recorded for /diagnostics as `call`.
  void predictRecorded(const std::string& call, PredictShot::Request& request, PredictShot::Response& response);
  bool predict(PredictShot::Request& request, PredictShot::Response& response);
  bool answer(PredictShot::Request& request, PredictShot::Response& response);
  bool describeConfiguration(GetConfiguration::Request& request, GetConfiguration::Response& response);
  /// ~get_table: the table's outline, as latched on ~table.
  bool describeTable(GetTable::Request& request, GetTable::Response& response);
  /// The cue's pose and the cue ball's position in the table frame; the cue ball's position is left for the table
  /// to give when it holds the cue ball.
  Expected<CuePlacement> placeCue(const PredictShot::Request& request, bool cue_ball_in_table) const;
  /// The request's table, or the latest ~table_state when it has no balls (Stale when older than
  /// ~table_state_timeout).
  Expected<TableState> tableFor(const TableState& given) const;
  /// The cue's tip and direction in the table frame, at `speed` (its ball left at the origin).
  Expected<CuePlacement> placeCuePose(const geometry_msgs::PoseStamped& cue_pose, double speed) const;
  /// The table's balls in the table frame (at rest on the cloth), waiting for tf at most `tf_timeout` seconds.
  Expected<std::vector<TableBall>> placeTable(const TableState& table, double tf_timeout) const;
  void storeTable(const TableState::ConstPtr& table);
  /// A table state tf can place at its stamp, for calibration's tracks (held back by sightings_ until it can).
  void observeSighting(const TableState::ConstPtr& table);
  /// The node's configuration (and, when `planning` is given, its planning settings) with per-call overrides.
  Expected<ShotConfiguration> configurationWith(const std::vector<std::string>& names,
                                                const std::vector<double>& values,
                                                PlanningSettings* planning = nullptr) const;
  /// A point in the table frame; errors name `field`.
  Expected<Eigen::Vector2d> placePoint(const geometry_msgs::PointStamped& point, const std::string& field) const;
  /// Records a call answered in the node's health (/diagnostics).
  CallRecorder callRecorder();
  ShotPlannerServer::NodeAccess plannerAccess();
  ShotCalibrationServer::NodeAccess calibrationAccess();
  CueCockpit::NodeAccess cockpitAccess();
  /// The cockpit's scene in the table frame: the balls of the last prediction or of the latest ~table_state,
  /// whichever came last (placed with the transforms tf has now), with the last prediction's cue ball.
  std::vector<TableBall> cockpitScene() const;
  /// The scene becomes `table`, with the cue ball at `cue_ball` when the table has none.
  void setScene(const TableState& table, const std::optional<Eigen::Vector2d>& cue_ball);
  /// A change through ~tuning: applied whole, or rejected whole with `tuning` reset to the node's configuration and
  /// the reason in tuning.rejected (the server answers the client with it).
  void retune(ShotPredictorConfig& tuning, uint32_t level);

  NodeSettings settings_;
  NodeHealth health_;
  diagnostic_updater::Updater diagnostics_;
  ros::Timer diagnostics_timer_;
  mutable std::mutex configuration_mutex_;  ///< guards settings_.shot against run-time tuning
  /// The tuning server's own lock, shared with it so that updateConfig() may be called without deadlock.
  boost::recursive_mutex tuning_mutex_;
  std::unique_ptr<dynamic_reconfigure::Server<ShotPredictorConfig>> tuning_server_;
  tf2_ros::Buffer buffer_;
  tf2_ros::TransformListener listener_{buffer_};
  ros::Publisher prediction_publisher_;
  ros::Publisher marker_publisher_;
  ros::Publisher table_publisher_;
  TableGeometry table_message_;  ///< laid out once: tuning leaves the table's size and pockets
  ros::ServiceServer service_;
  ros::ServiceServer configuration_service_;
  ros::ServiceServer table_service_;
  /// ~table_state has a queue and a thread of its own, so that no long call (a plan, a fit) holds up its intake.
  ros::CallbackQueue table_queue_;
  ros::AsyncSpinner table_spinner_{1, &table_queue_};
  message_filters::Subscriber<TableState> table_subscriber_;
  /// Sightings wait here until tf can place them at their stamps (a camera's frame whose transform comes later).
  std::unique_ptr<tf2_ros::MessageFilter<TableState>> sightings_;
  mutable std::mutex table_mutex_;  ///< guards latest_table_ against the subscriber's callback
  TableState latest_table_;
  ros::Time latest_table_received_;                ///< when latest_table_ arrived
  TableState scene_table_;                         ///< cockpitScene()'s, guarded by table_mutex_
  std::optional<Eigen::Vector2d> scene_cue_ball_;  ///< guarded by table_mutex_
  /// Declared before the servers that show their predictions to it, the cockpit after those it calls: each is
  /// destroyed before what it uses.
  std::unique_ptr<ShotAnimator> animator_;
  std::unique_ptr<ShotPlannerServer> planner_;
  std::unique_ptr<ShotCalibrationServer> calibration_;
  std::unique_ptr<CueCockpit> cockpit_;
};

}  // namespace billiard_shot_planner

#pragma once

#include <billiard_shot_planner/PlanShotAction.h>
#include <billiard_shot_planner/PredictShot.h>
#include <geometry_msgs/PointStamped.h>
#include <interactive_markers/interactive_marker_server.h>
#include <ros/ros.h>

#include <condition_variable>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "billiard_shot_planner/motion/table_simulation.hpp"
#include "cockpit_settings.hpp"
#include "cue_control_markers.hpp"

namespace billiard_shot_planner
{
/// rviz as the table's cockpit: a cue a person drags (the interactive marker server ~cue_control: aim, elevation, tip
/// and speed handles, cueHandleMarkers()), each drag asking the node for a prediction (at most ~cockpit/rate a
/// second, the latest drag winning); and a click with rviz's "Publish Point" on a ball (clicked_point) plans that
/// ball's pot. Both play on the cockpit's scene — the balls of the node's last prediction or of the latest
/// ~table_state, whichever came last — and the work runs on a thread of its own, so that no callback waits for it.
class CueCockpit
{
public:
  struct NodeAccess
  {
    /// The node's prediction, drawn and published as ~predict_shot's.
    std::function<void(PredictShot::Request&, PredictShot::Response&)> predict;
    /// A goal planned at once (its plan drawn and published).
    std::function<PlanShotResult(const PlanShotGoal&)> plan;
    /// The scene's balls in the table frame, the cue ball among them when there is one.
    std::function<std::vector<TableBall>()> scene;
    /// A point in the table frame (errors name `field`).
    std::function<Expected<Eigen::Vector2d>(const geometry_msgs::PointStamped&, const std::string&)> place_point;
    /// The configuration's ball radius now (it may be tuned).
    std::function<double()> ball_radius;
  };

  /// `frame` is the table frame; `default_ball` the cue ball's place while the scene has none.
  CueCockpit(ros::NodeHandle& node, ros::NodeHandle& private_node, NodeAccess access, const CockpitSettings& settings,
             std::string frame, const Eigen::Vector2d& default_ball);
  ~CueCockpit();
  CueCockpit(const CueCockpit&) = delete;
  CueCockpit& operator=(const CueCockpit&) = delete;

private:
  void dragged(const visualization_msgs::InteractiveMarkerFeedbackConstPtr& feedback);
  void clicked(const geometry_msgs::PointStamped::ConstPtr& point);
  /// The handles follow the scene's cue ball (without a new prediction: the scene's own is drawn).
  void followCueBall();
  /// The handles redrawn, all but `dragged` (rviz moves that one itself).
  void redraw(const CueHandles& handles, const std::string& dragged);
  void work();
  void predictStroke(const CueHandles& handles);
  void planPot(const PlanShotGoal& goal);
  /// The scene as a TableState in the table frame, with the cue ball at `cue_ball` when the scene has none.
  TableState sceneTable(const Eigen::Vector2d& cue_ball) const;

  NodeAccess access_;
  CockpitSettings settings_;
  std::string frame_;
  interactive_markers::InteractiveMarkerServer server_;
  std::mutex mutex_;  ///< guards what follows against the callbacks' threads and the worker
  std::condition_variable wake_;
  CueHandles handles_;
  bool stroke_pending_ = false;
  std::optional<PlanShotGoal> plan_pending_;
  bool stopping_ = false;
  ros::Subscriber clicked_subscriber_;
  ros::WallTimer follow_timer_;
  std::thread worker_;
};

}  // namespace billiard_shot_planner

#include "cue_cockpit.hpp"

#include <chrono>
#include <cmath>
#include <limits>

namespace billiard_shot_planner
{
namespace
{
/// m: the handles move with the cue ball once it has moved this far (a tracker's jitter aside).
constexpr double FOLLOW_DISTANCE = 1e-3;
/// Hz: how often the handles look for the scene's cue ball.
constexpr double FOLLOW_RATE = 2.0;
/// A click picks the ball whose centre is within this many radii of the clicked point.
constexpr double PICK_RADII = 2.0;

const TableBall* findBall(const std::vector<TableBall>& balls, const std::string& id)
{
  for (const TableBall& ball : balls)
    if (ball.id == id)
      return &ball;
  return nullptr;
}

/// The object ball nearest `point` within PICK_RADII radii, if any.
const TableBall* pickBall(const std::vector<TableBall>& balls, const Eigen::Vector2d& point, double radius)
{
  const TableBall* nearest = nullptr;
  double distance = PICK_RADII * radius;
  for (const TableBall& ball : balls)
  {
    const double d = (ball.state.position.head<2>() - point).norm();
    if (ball.id != CUE_BALL_ID && d <= distance)
    {
      nearest = &ball;
      distance = d;
    }
  }
  return nearest;
}
}  // namespace

CueCockpit::CueCockpit(ros::NodeHandle& node, ros::NodeHandle& private_node, NodeAccess access,
                       const CockpitSettings& settings, std::string frame, const Eigen::Vector2d& default_ball)
    : access_(std::move(access)),
      settings_(settings),
      frame_(std::move(frame)),
      server_(private_node.resolveName("cue_control"))
{
  handles_.ball = default_ball;
  handles_.radius = access_.ball_radius();
  handles_.speed_scale = settings_.speed_scale;
  redraw(handles_, "");
  // A relative name: /clicked_point (rviz's Publish Point tool) for a node in the root namespace, remappable.
  clicked_subscriber_ = node.subscribe("clicked_point", 1, &CueCockpit::clicked, this);
  follow_timer_ = node.createWallTimer(ros::WallDuration(1.0 / FOLLOW_RATE),
                                       [this](const ros::WallTimerEvent&) { followCueBall(); });
  worker_ = std::thread([this] { work(); });
}

CueCockpit::~CueCockpit()
{
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  worker_.join();
}

void CueCockpit::redraw(const CueHandles& handles, const std::string& dragged)
{
  for (const auto& marker : cueHandleMarkers(handles, frame_))
    if (marker.name != dragged)
      server_.insert(marker, [this](const visualization_msgs::InteractiveMarkerFeedbackConstPtr& feedback)
                     { this->dragged(feedback); });
  server_.applyChanges();
}

void CueCockpit::dragged(const visualization_msgs::InteractiveMarkerFeedbackConstPtr& feedback)
{
  using Feedback = visualization_msgs::InteractiveMarkerFeedback;
  if (feedback->event_type != Feedback::POSE_UPDATE && feedback->event_type != Feedback::MOUSE_UP)
    return;
  CueHandles handles;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    handles_.stroke = strokeAfterDrag(handles_, feedback->marker_name, feedback->pose);
    stroke_pending_ = true;
    handles = handles_;
  }
  wake_.notify_all();
  // While a handle is dragged rviz moves it; once let go, it snaps to the stroke's place like the others.
  redraw(handles, feedback->event_type == Feedback::MOUSE_UP ? "" : feedback->marker_name);
}

void CueCockpit::clicked(const geometry_msgs::PointStamped::ConstPtr& point)
{
  const auto placed = access_.place_point(*point, "clicked_point");
  if (!placed)
  {
    ROS_WARN("clicked_point: %s", placed.error().describe().c_str());
    return;
  }
  const std::vector<TableBall> balls = access_.scene();
  const TableBall* ball = pickBall(balls, placed.value(), access_.ball_radius());
  if (!ball)
  {
    ROS_WARN("clicked_point: no object ball within %g radii of (%.3f, %.3f) m in '%s'", PICK_RADII, placed.value().x(),
             placed.value().y(), frame_.c_str());
    return;
  }
  Eigen::Vector2d cue_ball;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    cue_ball = handles_.ball;
  }
  PlanShotGoal goal;
  goal.target = ball->id;
  goal.table = sceneTable(cue_ball);
  {
    std::lock_guard<std::mutex> lock(mutex_);
    plan_pending_ = goal;
  }
  ROS_INFO("clicked_point: planning the pot of ball '%s'", ball->id.c_str());
  wake_.notify_all();
}

void CueCockpit::followCueBall()
{
  const std::vector<TableBall> balls = access_.scene();
  const TableBall* cue_ball = findBall(balls, CUE_BALL_ID);
  if (!cue_ball)
    return;
  CueHandles handles;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    handles_.radius = access_.ball_radius();
    if ((handles_.ball - cue_ball->state.position.head<2>()).norm() < FOLLOW_DISTANCE)
      return;
    handles_.ball = cue_ball->state.position.head<2>();
    handles = handles_;
  }
  redraw(handles, "");
}

TableState CueCockpit::sceneTable(const Eigen::Vector2d& cue_ball) const
{
  TableState table;
  table.header.frame_id = frame_;
  const std::vector<TableBall> balls = access_.scene();
  for (const TableBall& given : balls)
  {
    billiard_shot_planner::Ball ball;
    ball.id = given.id;
    ball.position.x = given.state.position.x();
    ball.position.y = given.state.position.y();
    table.balls.push_back(ball);
  }
  if (!findBall(balls, CUE_BALL_ID))
  {
    billiard_shot_planner::Ball ball;
    ball.id = CUE_BALL_ID;
    ball.position.x = cue_ball.x();
    ball.position.y = cue_ball.y();
    table.balls.push_back(ball);
  }
  return table;
}

void CueCockpit::work()
{
  const auto period = std::chrono::duration<double>(1.0 / settings_.rate);
  std::unique_lock<std::mutex> lock(mutex_);
  while (true)
  {
    wake_.wait(lock, [this] { return stopping_ || stroke_pending_ || plan_pending_; });
    if (stopping_)
      return;
    if (plan_pending_)
    {
      const PlanShotGoal goal = *plan_pending_;
      plan_pending_.reset();
      lock.unlock();
      planPot(goal);
      lock.lock();
      continue;
    }
    stroke_pending_ = false;
    const CueHandles handles = handles_;
    const auto started = std::chrono::steady_clock::now();
    lock.unlock();
    predictStroke(handles);
    lock.lock();
    // At most `rate` predictions a second: drags that come meanwhile leave only their latest.
    wake_.wait_until(lock, started + period, [this] { return stopping_; });
  }
}

void CueCockpit::predictStroke(const CueHandles& handles)
{
  PredictShot::Request request;
  PredictShot::Response response;
  request.stroke.phi = handles.stroke.phi;
  request.stroke.theta = handles.stroke.theta;
  request.stroke.speed = handles.stroke.speed;
  request.stroke.a = handles.stroke.a;
  request.stroke.b = handles.stroke.b;
  request.table = sceneTable(handles.ball);
  access_.predict(request, response);
  if (!response.success)
    ROS_WARN_THROTTLE(2.0, "cue_control: %s", response.message.c_str());
}

void CueCockpit::planPot(const PlanShotGoal& goal)
{
  const PlanShotResult result = access_.plan(goal);
  if (!result.success)
  {
    ROS_WARN("clicked_point: %s", result.message.c_str());
    return;
  }
  ROS_INFO("clicked_point: ball '%s' pots with probability %.2f (%d rollouts)", goal.target.c_str(),
           result.plan.success_probability, result.plan.rollouts);
  // The handles take the plan's stroke, so that dragging starts from it.
  CueHandles handles;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    handles_.stroke = {result.plan.phi, result.plan.theta, result.plan.cue_speed, result.plan.a, result.plan.b};
    handles = handles_;
  }
  redraw(handles, "");
}

}  // namespace billiard_shot_planner

#include "shot_predictor_node.hpp"
#include "table_message.hpp"

#include <tf2_geometry_msgs/tf2_geometry_msgs.h>

#include <Eigen/Geometry>
#include <cmath>
#include <stdexcept>

#include "billiard_shot_planner/core/validation.hpp"
#include "billiard_shot_planner/planning/stroke_conventions.hpp"
#include "error_codes.hpp"
#include "parameter_names.hpp"
#include "prediction_message.hpp"
#include "request_fields.hpp"
#include "trajectory_markers.hpp"
#include "tuning.hpp"

namespace billiard_shot_planner
{
namespace
{
/// Table states waiting for their turn, and sightings waiting for tf.
constexpr uint32_t TABLE_STATE_QUEUE = 100;
/// A quaternion's norm may differ from 1 by this much (float round-off from other nodes), no more.
constexpr double QUATERNION_NORM_TOLERANCE = 1e-3;

bool isFinite(double x, double y, double z)
{
  return std::isfinite(x) && std::isfinite(y) && std::isfinite(z);
}

bool hasCueBall(const TableState& table)
{
  for (const billiard_shot_planner::Ball& ball : table.balls)
    if (ball.id == CUE_BALL_ID)
      return true;
  return false;
}

Status checkTable(const TableState& table)
{
  if (table.balls.size() > MAX_TABLE_BALLS)
    return invalidArgument("table.balls", "at most " + std::to_string(MAX_TABLE_BALLS) + " balls, got " +
                                              std::to_string(table.balls.size()));
  if (!table.balls.empty() && table.header.frame_id.empty())
    return invalidArgument("table.header.frame_id", "is empty: give the frame the balls are expressed in");
  for (std::size_t i = 0; i < table.balls.size(); ++i)
  {
    const std::string field = "table.balls[" + std::to_string(i) + "].";
    const auto& ball = table.balls[i];
    if (!isFinite(ball.position.x, ball.position.y, ball.position.z))
      return invalidArgument(field + "position", "contains NaN or infinite values");
    if (!isFinite(ball.velocity.x, ball.velocity.y, ball.velocity.z))
      return invalidArgument(field + "velocity", "contains NaN or infinite values");
    if (!isFinite(ball.angular_velocity.x, ball.angular_velocity.y, ball.angular_velocity.z))
      return invalidArgument(field + "angular_velocity", "contains NaN or infinite values");
  }
  return {};
}

/// The cue's pose and speed (PredictShot's and RecordShot's): finite, a unit quaternion, a frame.
Status checkCue(const geometry_msgs::PoseStamped& pose, double speed)
{
  const auto& p = pose.pose.position;
  const auto& q = pose.pose.orientation;
  if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
    return invalidArgument("cue_pose.pose.position", "contains NaN or infinite values");
  if (!std::isfinite(q.x) || !std::isfinite(q.y) || !std::isfinite(q.z) || !std::isfinite(q.w))
    return invalidArgument("cue_pose.pose.orientation", "contains NaN or infinite values");
  const double norm = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
  if (std::abs(norm - 1.0) > QUATERNION_NORM_TOLERANCE)
    return invalidArgument("cue_pose.pose.orientation", "is not a unit quaternion (norm " + formatNumber(norm) + ")");
  if (!std::isfinite(speed) || speed <= 0.0)
    return invalidArgument("cue_speed", "must be > 0 m/s, got " + formatNumber(speed));
  // An empty frame can never be resolved: refused at once rather than after the whole tf timeout.
  if (pose.header.frame_id.empty())
    return invalidArgument("cue_pose.header.frame_id", "is empty: give the frame the pose is expressed in");
  return {};
}

/// A request gives its cue as a stroke when the stroke's speed is not 0 (NaN included: refused below).
bool usesStroke(const PredictShot::Request& r)
{
  return r.stroke.speed != 0.0;
}

Status checkStroke(const PlayerStroke& s)
{
  if (s.convention != "" && s.convention != "pooltool" && s.convention != "fastfiz")
    return invalidArgument("stroke.convention",
                           "must be \"\" (this package's), \"pooltool\" or \"fastfiz\", got \"" + s.convention + "\"");
  if (!(std::isfinite(s.speed) && s.speed > 0.0))
    return invalidArgument("stroke.speed", "must be > 0 m/s (0: the cue is cue_pose), got " + formatNumber(s.speed));
  for (const auto& [value, name] : {std::pair{s.phi, "stroke.phi"}, std::pair{s.theta, "stroke.theta"},
                                    std::pair{s.a, "stroke.a"}, std::pair{s.b, "stroke.b"}})
    if (!std::isfinite(value))
      return invalidArgument(name, "must be finite");
  return {};
}

/// A stroke's error with its field named as the request's ("stroke.a").
Error inStroke(Error error)
{
  error.field = "stroke." + error.field;
  return error;
}

/// The stroke in this package's convention (`ball_radius`: the radius FastFiz's millimetres are of).
Stroke strokeOf(const PlayerStroke& s, double ball_radius)
{
  if (s.convention == "pooltool")
    return fromPooltool({s.speed, s.phi, s.theta, s.a, s.b});
  if (s.convention == "fastfiz")
    return fromFastFiz({s.a, s.b, s.theta, s.phi, s.speed}, ball_radius);
  return {s.phi, s.theta, s.speed, s.a, s.b};
}

Status checkRequest(const PredictShot::Request& r, bool cue_ball_in_table)
{
  if (Status status = usesStroke(r) ? checkStroke(r.stroke) : checkCue(r.cue_pose, r.cue_speed); !status)
    return status;
  const auto& b = r.ball_position.point;
  if (!cue_ball_in_table && (!std::isfinite(b.x) || !std::isfinite(b.y) || !std::isfinite(b.z)))
    return invalidArgument("ball_position.point", "contains NaN or infinite values");
  if (!cue_ball_in_table && r.ball_position.header.frame_id.empty())
    return invalidArgument("ball_position.header.frame_id", "is empty: give the frame the point is expressed in");
  if (r.override_names.size() != r.override_values.size())
    return invalidArgument("override_values", "must have one value per name in override_names");
  return {};
}
}  // namespace

namespace
{
NodeSettings readOrThrow(const ros::NodeHandle& private_node)
{
  auto settings = readSettings(private_node);
  if (!settings)
    throw std::runtime_error("invalid parameter ~" + settings.error().describe());
  return settings.value();
}
}  // namespace

ShotPredictorNode::ShotPredictorNode(ros::NodeHandle& node, ros::NodeHandle& private_node)
    : settings_(readOrThrow(private_node)), health_(settings_.table_state_timeout), diagnostics_(node, private_node)
{
  diagnostics_.setHardwareID("none");  // software only: the robot's devices report their own
  diagnostics_.add("health", [this](diagnostic_updater::DiagnosticStatusWrapper& status)
                   { health_.report(status, ros::Time::now()); });
  // Latched: a display or a logger that connects later still gets the last prediction.
  prediction_publisher_ = private_node.advertise<ShotPrediction>("prediction", 10, true);
  marker_publisher_ = private_node.advertise<visualization_msgs::MarkerArray>("trajectory_markers", 1, true);
  marker_publisher_.publish(tableMarkers(settings_.shot.table, settings_.target_frame));  // rviz has a table at once
  // Latched: the table's size, cushions and pockets do not change while the node runs (tuning leaves them).
  // The settings were validated, the outline with them: it lays out.
  table_message_ = tableMessage(tableOutline(settings_.shot.table).value(), settings_.shot.table,
                                settings_.target_frame, ros::Time::now());
  table_publisher_ = private_node.advertise<TableGeometry>("table", 1, true);
  table_publisher_.publish(table_message_);
  // The tuning server starts from the loaded parameters, not from the .cfg defaults.
  tuning_server_ = std::make_unique<dynamic_reconfigure::Server<ShotPredictorConfig>>(
      tuning_mutex_, ros::NodeHandle(private_node, "tuning"));
  tuning_server_->updateConfig(toTuning(settings_.shot));
  tuning_server_->setCallback([this](ShotPredictorConfig& tuning, uint32_t level) { retune(tuning, level); });
  calibration_ = std::make_unique<ShotCalibrationServer>(private_node, calibrationAccess(), settings_.recording,
                                                         settings_.threads);
  // A queue, not just the latest: every sighting counts for calibration. The latest table is taken as it comes;
  // a sighting goes on to calibration once tf can place it at its stamp (it waits in the filter's queue until then).
  ros::NodeHandle table_node(private_node);
  table_node.setCallbackQueue(&table_queue_);
  table_subscriber_.subscribe(table_node, "table_state", TABLE_STATE_QUEUE);
  table_subscriber_.registerCallback(&ShotPredictorNode::storeTable, this);
  sightings_ = std::make_unique<tf2_ros::MessageFilter<TableState>>(table_subscriber_, buffer_, settings_.target_frame,
                                                                    TABLE_STATE_QUEUE, table_node);
  sightings_->registerCallback(&ShotPredictorNode::observeSighting, this);
  sightings_->registerFailureCallback(
      [](const TableState::ConstPtr& table, tf2_ros::FilterFailureReason reason)
      {
        if (!table->balls.empty())
          ROS_WARN_THROTTLE(10.0, "a table_state in frame '%s' was not recorded for calibration: %s",
                            table->header.frame_id.c_str(),
                            reason == tf2_ros::filter_failure_reasons::EmptyFrameID ? "no frame"
                            : reason == tf2_ros::filter_failure_reasons::OutTheBack
                                ? "older than tf's buffer"
                                : "tf could not place it before the queue overflowed");
      });
  table_spinner_.start();
  service_ = private_node.advertiseService("predict_shot", &ShotPredictorNode::predict, this);
  configuration_service_ =
      private_node.advertiseService("get_configuration", &ShotPredictorNode::describeConfiguration, this);
  table_service_ = private_node.advertiseService("get_table", &ShotPredictorNode::describeTable, this);
  diagnostics_timer_ = node.createTimer(ros::Duration(1.0), [this](const ros::TimerEvent&) { diagnostics_.update(); });
  if (settings_.cockpit.enabled)
    animator_ = std::make_unique<ShotAnimator>(private_node, settings_.cockpit,
                                               [this]
                                               {
                                                 std::lock_guard<std::mutex> lock(configuration_mutex_);
                                                 return settings_.shot.ball_radius;
                                               });
  planner_ = std::make_unique<ShotPlannerServer>(private_node, plannerAccess(), settings_.target_frame,
                                                 settings_.sample_spacing, marker_publisher_);
  if (settings_.cockpit.enabled)
  {
    const Eigen::Vector2d head_spot(-0.25 * settings_.shot.table.length, 0.0);
    cockpit_ = std::make_unique<CueCockpit>(node, private_node, cockpitAccess(), settings_.cockpit,
                                            settings_.target_frame, head_spot);
  }
  ROS_INFO("predict_shot ready: answers in frame '%s'", settings_.target_frame.c_str());
}

void ShotPredictorNode::retune(ShotPredictorConfig& tuning, uint32_t /*level*/)
{
  std::lock_guard<std::mutex> lock(configuration_mutex_);
  auto tuned = applyTuning(settings_.shot, tuning);
  if (!tuned)
  {
    // The server keeps and answers what the callback leaves in `tuning`: the node's configuration, unchanged.
    tuning = toTuning(settings_.shot);
    tuning.rejected = tuned.error().describe();
    ROS_WARN("tuning rejected, parameters unchanged: %s", tuning.rejected.c_str());
    return;
  }
  settings_.shot = tuned.value();
  tuning.rejected.clear();
}

Expected<ShotConfiguration> ShotPredictorNode::configurationWith(const std::vector<std::string>& names,
                                                                 const std::vector<double>& values,
                                                                 PlanningSettings* planning) const
{
  ShotConfiguration configuration;
  {
    std::lock_guard<std::mutex> lock(configuration_mutex_);
    configuration = settings_.shot;
    if (planning)
      *planning = settings_.planning;
  }
  for (std::size_t i = 0; i < names.size(); ++i)
  {
    if (planning)
    {
      auto applied = applyPlanningOverride(*planning, names[i], values[i]);
      if (!applied)
        return Error{applied.error().code, "override " + applied.error().field, applied.error().message};
      if (applied.value())
        continue;
    }
    if (Status status = applyOverride(configuration, configurationPath(names[i]), values[i]); !status)
      return Error{status.error().code, "override " + parameterName(status.error().field), status.error().message};
  }
  return configuration;
}

Expected<Eigen::Vector2d> ShotPredictorNode::placePoint(const geometry_msgs::PointStamped& point,
                                                        const std::string& field) const
{
  const auto& p = point.point;
  if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
    return invalidArgument(field + ".point", "contains NaN or infinite values");
  if (point.header.frame_id.empty())
    return invalidArgument(field + ".header.frame_id", "is empty: give the frame the point is expressed in");
  try
  {
    const auto placed = buffer_.transform(point, settings_.target_frame, ros::Duration(settings_.tf_timeout));
    return Eigen::Vector2d(placed.point.x, placed.point.y);
  }
  catch (const tf2::TransformException& e)
  {
    return transformError(field + ".header.frame_id", e);
  }
}

ShotPlannerServer::NodeAccess ShotPredictorNode::plannerAccess()
{
  ShotPlannerServer::NodeAccess access;
  access.configure = [this](const std::vector<std::string>& names, const std::vector<double>& values,
                            PlanningSettings& planning) { return configurationWith(names, values, &planning); };
  access.table = [this](const TableState& table) { return tableFor(table); };
  access.place_table = [this](const TableState& table) -> Expected<std::vector<TableBall>>
  {
    if (Status status = checkTable(table); !status)
      return status.error();
    return placeTable(table, settings_.tf_timeout);
  };
  access.place_point = [this](const geometry_msgs::PointStamped& point, const std::string& field)
  { return placePoint(point, field); };
  access.record = callRecorder();
  access.show = [this](const ShotPrediction& prediction)
  {
    if (animator_)
      animator_->show(prediction);
  };
  return access;
}

CueCockpit::NodeAccess ShotPredictorNode::cockpitAccess()
{
  CueCockpit::NodeAccess access;
  access.predict = [this](PredictShot::Request& request, PredictShot::Response& response)
  { predictRecorded("cue_control", request, response); };
  access.plan = [this](const PlanShotGoal& goal) { return planner_->answer("clicked_point", goal); };
  access.scene = [this] { return cockpitScene(); };
  access.place_point = [this](const geometry_msgs::PointStamped& point, const std::string& field)
  { return placePoint(point, field); };
  access.ball_radius = [this]
  {
    std::lock_guard<std::mutex> lock(configuration_mutex_);
    return settings_.shot.ball_radius;
  };
  return access;
}

void ShotPredictorNode::setScene(const TableState& table, const std::optional<Eigen::Vector2d>& cue_ball)
{
  std::lock_guard<std::mutex> lock(table_mutex_);
  scene_table_ = table;
  scene_cue_ball_ = cue_ball;
}

std::vector<TableBall> ShotPredictorNode::cockpitScene() const
{
  TableState table;
  std::optional<Eigen::Vector2d> cue_ball;
  {
    std::lock_guard<std::mutex> lock(table_mutex_);
    table = scene_table_;
    cue_ball = scene_cue_ball_;
  }
  auto balls = checkTable(table) ? placeTable(table, 0.0) : Expected<std::vector<TableBall>>(std::vector<TableBall>{});
  if (!balls)
    return {};  // tf cannot place it yet: the cockpit keeps its cue where it is
  if (cue_ball && !hasCueBall(table))
  {
    TableBall ball{CUE_BALL_ID, {}};
    ball.state.position = Eigen::Vector3d(cue_ball->x(), cue_ball->y(), 0.0);
    balls.value().push_back(ball);
  }
  return balls.value();
}

ShotCalibrationServer::NodeAccess ShotPredictorNode::calibrationAccess()
{
  ShotCalibrationServer::NodeAccess access;
  access.configuration = [this]
  {
    std::lock_guard<std::mutex> lock(configuration_mutex_);
    return settings_.shot;
  };
  access.place_table = [this](const TableState& table, bool wait_for_tf) -> Expected<std::vector<TableBall>>
  {
    if (Status status = checkTable(table); !status)
      return status.error();
    return placeTable(table, wait_for_tf ? settings_.tf_timeout : 0.0);
  };
  access.place_cue = [this](const geometry_msgs::PoseStamped& pose, double speed) -> Expected<CuePlacement>
  {
    if (Status status = checkCue(pose, speed); !status)
      return status.error();
    return placeCuePose(pose, speed);
  };
  access.record = callRecorder();
  return access;
}

void ShotPredictorNode::storeTable(const TableState::ConstPtr& table)
{
  health_.recordTableState(ros::Time::now());
  {
    std::lock_guard<std::mutex> lock(table_mutex_);
    latest_table_ = *table;
    latest_table_received_ = ros::Time::now();
  }
  setScene(*table, std::nullopt);
}

void ShotPredictorNode::observeSighting(const TableState::ConstPtr& table)
{
  calibration_->observe(*table);
}

Expected<TableState> ShotPredictorNode::tableFor(const TableState& given) const
{
  if (!given.balls.empty())
    return given;
  std::lock_guard<std::mutex> lock(table_mutex_);
  const double age = (ros::Time::now() - latest_table_received_).toSec();
  if (!latest_table_.balls.empty() && settings_.table_state_timeout > 0.0 && age > settings_.table_state_timeout)
    return Error{ErrorKind::Stale, "table",
                 "the latest ~table_state arrived " + std::to_string(age) + " s ago, more than ~table_state_timeout (" +
                     std::to_string(settings_.table_state_timeout) + " s): publish a fresh one or give the balls"};
  return latest_table_;
}

Expected<std::vector<TableBall>> ShotPredictorNode::placeTable(const TableState& table, double tf_timeout) const
{
  if (table.balls.empty())
    return std::vector<TableBall>{};
  geometry_msgs::TransformStamped to_table;
  try
  {
    to_table = buffer_.lookupTransform(settings_.target_frame, table.header.frame_id, table.header.stamp,
                                       ros::Duration(tf_timeout));
  }
  catch (const tf2::TransformException& e)
  {
    return transformError("table.header.frame_id", e);
  }
  std::vector<TableBall> balls;
  for (const billiard_shot_planner::Ball& given : table.balls)
  {
    geometry_msgs::Point position;
    geometry_msgs::Vector3 velocity, angular_velocity;
    tf2::doTransform(given.position, position, to_table);
    tf2::doTransform(given.velocity, velocity, to_table);  // vectors turn with the frame; they do not shift
    tf2::doTransform(given.angular_velocity, angular_velocity, to_table);
    TableBall ball{given.id, {}};
    ball.state.position = Eigen::Vector3d(position.x, position.y, 0.0);
    ball.state.velocity = Eigen::Vector3d(velocity.x, velocity.y, 0.0);
    ball.state.angular_velocity = Eigen::Vector3d(angular_velocity.x, angular_velocity.y, angular_velocity.z);
    balls.push_back(ball);
  }
  return balls;
}

Expected<CuePlacement> ShotPredictorNode::placeCuePose(const geometry_msgs::PoseStamped& cue_pose, double speed) const
{
  geometry_msgs::PoseStamped pose;
  try
  {
    pose = buffer_.transform(cue_pose, settings_.target_frame, ros::Duration(settings_.tf_timeout));
  }
  catch (const tf2::TransformException& e)
  {
    return transformError("cue_pose.header.frame_id", e);
  }
  const auto& q = pose.pose.orientation;
  CuePlacement cue;
  cue.tip = Eigen::Vector3d(pose.pose.position.x, pose.pose.position.y, pose.pose.position.z);
  cue.direction = Eigen::Quaterniond(q.w, q.x, q.y, q.z).normalized() * Eigen::Vector3d::UnitX();
  cue.speed = speed;
  return cue;
}

Expected<CuePlacement> ShotPredictorNode::placeCue(const PredictShot::Request& request, bool cue_ball_in_table) const
{
  // A stroke is placed at the cue ball once its place is known (strikeAt); a pose places the cue itself.
  auto cue =
      usesStroke(request) ? Expected<CuePlacement>(CuePlacement{}) : placeCuePose(request.cue_pose, request.cue_speed);
  if (!cue || cue_ball_in_table)
    return cue;  // the table gives the cue ball's place when it holds the cue ball
  auto placed = placePoint(request.ball_position, "ball_position");
  if (!placed)
    return placed.error();
  cue.value().ball = placed.value();
  return cue;
}

CallRecorder ShotPredictorNode::callRecorder()
{
  return [this](const std::string& call, double seconds, const ErrorCode& code, const std::string& message)
  { health_.recordCall(call, seconds, code.val, message, ros::Time::now()); };
}

void ShotPredictorNode::predictRecorded(const std::string& call, PredictShot::Request& request,
                                        PredictShot::Response& response)
{
  recordedCall(callRecorder(), call,
               [&]() -> const PredictShot::Response&
               {
                 answer(request, response);
                 return response;
               });
}

bool ShotPredictorNode::predict(PredictShot::Request& request, PredictShot::Response& response)
{
  predictRecorded("predict_shot", request, response);
  return true;  // a domain error is an answer, not a failed call
}

bool ShotPredictorNode::describeConfiguration(GetConfiguration::Request& /*request*/,
                                              GetConfiguration::Response& response)
{
  NodeSettings settings;
  {
    std::lock_guard<std::mutex> lock(configuration_mutex_);
    settings = settings_;
  }
  const SettingsDescription description = describeSettings(settings);
  response.names = description.names;
  response.values = description.values;
  response.choice_names = description.choice_names;
  response.choice_values = description.choice_values;
  response.success = true;
  response.message = "ok";
  response.error_code = errorCode(ErrorCode::SUCCESS);
  return true;
}

bool ShotPredictorNode::describeTable(GetTable::Request& /*request*/, GetTable::Response& response)
{
  response.table = table_message_;
  response.success = true;
  response.message = "ok";
  response.error_code = errorCode(ErrorCode::SUCCESS);
  return true;
}

bool ShotPredictorNode::answer(PredictShot::Request& request, PredictShot::Response& response)
{
  auto fail = [&](const Error& error)
  {
    response.success = false;
    response.message = error.describe();
    response.error_code = errorCodeOf(error);
    ROS_WARN("predict_shot: %s", response.message.c_str());
    return true;  // a domain error is an answer, not a failed call
  };
  const auto fresh = tableFor(request.table);
  if (!fresh)
    return fail(fresh.error());
  const TableState& table = fresh.value();
  if (Status status = firstError({checkTable(table), checkRequest(request, hasCueBall(table))}); !status)
    return fail(status.error());
  auto configuration = configurationWith(request.override_names, request.override_values);
  if (!configuration)
    return fail(configuration.error());
  auto balls = placeTable(table, settings_.tf_timeout);
  if (!balls)
    return fail(balls.error());
  auto cue = placeCue(request, hasCueBall(table));
  if (!cue)
    return fail(cue.error());
  std::vector<TableBall> others;
  BallOrigins origins;
  for (std::size_t i = 0; i < balls.value().size(); ++i)
  {
    TableBall& ball = balls.value()[i];
    if (ball.id != CUE_BALL_ID)
    {
      others.push_back(ball);
      origins.others.push_back(i);
      continue;
    }
    // The cue strikes a ball at rest: a tracked cue ball's small motion is the tracker's noise.
    if (Status status = settleAtRest(ball, settings_.planning.rest_speed, configuration.value().ball_radius); !status)
      return fail(status.error());
    cue.value().ball = ball.state.position.head<2>();
    origins.cue_ball = i;
  }
  if (usesStroke(request))
  {
    const double radius = configuration.value().ball_radius;
    auto struck = placeStroke(strokeOf(request.stroke, radius), cue.value().ball, radius);
    if (!struck)
      return fail(inStroke(struck.error()));
    cue = struck;
  }
  auto outcome = predictShot(cue.value(), configuration.value(), others);
  if (!outcome)
    return fail(inRequestTerms(outcome.error(), origins));
  response.success = true;
  response.message = "ok";
  response.error_code = errorCode(ErrorCode::SUCCESS);
  response.prediction = toMessage(outcome.value(), settings_.target_frame, settings_.sample_spacing);
  // The prediction is of the strike: at the cue pose's time, or now for a pose stamped 0 ("the latest").
  response.prediction.header.stamp =
      request.cue_pose.header.stamp.isZero() ? ros::Time::now() : request.cue_pose.header.stamp;
  response.ball_velocity = response.prediction.ball_velocity;
  response.ball_angular_velocity = response.prediction.ball_angular_velocity;
  response.states = response.prediction.states;
  prediction_publisher_.publish(response.prediction);
  marker_publisher_.publish(
      trajectoryMarkers(outcome.value(), configuration.value(), settings_.target_frame, settings_.sample_spacing));
  setScene(table, hasCueBall(table) ? std::nullopt : std::optional<Eigen::Vector2d>(cue.value().ball));
  if (animator_)
    animator_->show(response.prediction);
  return true;
}

}  // namespace billiard_shot_planner

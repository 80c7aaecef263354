// The shot_predictor node end to end (rostest): answers equal the core library's, frames do not matter, bad
// input is answered with success = false and a reason, markers are latched arrays that replace each other, and
// concurrent callers are all served.
#include <billiard_shot_planner/GetConfiguration.h>
#include <billiard_shot_planner/GetTable.h>
#include <billiard_shot_planner/PredictShot.h>
#include <billiard_shot_planner/ShotPrediction.h>
#include <billiard_shot_planner/TableState.h>
#include <diagnostic_msgs/DiagnosticArray.h>
#include <dynamic_reconfigure/Reconfigure.h>
#include <gtest/gtest.h>

#include <ros/ros.h>
#include <tf2_geometry_msgs/tf2_geometry_msgs.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>
#include <visualization_msgs/MarkerArray.h>
#include <limits>
#include <map>
#include <optional>

#include <Eigen/Geometry>
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <mutex>
#include <set>
#include <thread>

#include "billiard_shot_planner/planning/stroke.hpp"
#include "shot_fixtures.hpp"

namespace bsp = billiard_shot_planner;

namespace
{
const std::string SERVICE = "/shot_predictor/predict_shot";

using shot_fixtures::toRequest;

bsp::PredictShot::Response call(const bsp::PredictShot::Request& request)
{
  bsp::PredictShot srv;
  srv.request = request;
  EXPECT_TRUE(ros::service::call(SERVICE, srv));
  return srv.response;
}

/// The first status named `name` on /diagnostics within 10 s that has `level` (any when absent) and the key
/// `key` (any when empty).
std::optional<diagnostic_msgs::DiagnosticStatus> waitForStatus(const std::string& name, std::optional<int8_t> level,
                                                               const std::string& key = "")
{
  ros::NodeHandle node;
  std::mutex mutex;
  std::optional<diagnostic_msgs::DiagnosticStatus> found;
  ros::Subscriber subscriber = node.subscribe<diagnostic_msgs::DiagnosticArray>(
      "/diagnostics", 10,
      [&](const diagnostic_msgs::DiagnosticArray::ConstPtr& array)
      {
        for (const auto& status : array->status)
        {
          const bool has_key = key.empty() || std::any_of(status.values.begin(), status.values.end(),
                                                          [&](const auto& pair) { return pair.key == key; });
          std::lock_guard<std::mutex> lock(mutex);
          if (status.name == name && (!level || status.level == *level) && has_key)
            found = status;
        }
      });
  for (int attempt = 0; attempt < 200; ++attempt)
  {
    ros::Duration(0.05).sleep();
    ros::spinOnce();
    std::lock_guard<std::mutex> lock(mutex);
    if (found)
      break;
  }
  return found;
}

class PredictShotNode : public testing::Test
{
protected:
  static void SetUpTestSuite() { ASSERT_TRUE(ros::service::waitForService(SERVICE, ros::Duration(30))); }
};
}  // namespace

TEST_F(PredictShotNode, AnswerEqualsTheCoreLibrary)
{
  const auto response = call(toRequest(shot_fixtures::masse()));
  ASSERT_TRUE(response.success) << response.message;
  EXPECT_EQ(response.error_code.val, bsp::ErrorCode::SUCCESS);
  // The node computes the cue direction from the quaternion; the core test uses the same placement.
  bsp::CuePlacement cue = shot_fixtures::masse();
  const auto& o = toRequest(cue).cue_pose.pose.orientation;
  cue.direction = Eigen::Quaterniond(o.w, o.x, o.y, o.z).normalized() * Eigen::Vector3d::UnitX();
  const auto expected = bsp::predictShot(cue, bsp::ShotConfiguration{}).value();
  EXPECT_NEAR(response.ball_velocity.x, expected.strike.velocity.x(), 1e-12);
  EXPECT_NEAR(response.ball_velocity.y, expected.strike.velocity.y(), 1e-12);
  EXPECT_NEAR(response.ball_velocity.z, expected.strike.velocity.z(), 1e-12);
  EXPECT_NEAR(response.ball_angular_velocity.x, expected.strike.angular_velocity.x(), 1e-12);
  EXPECT_NEAR(response.ball_angular_velocity.y, expected.strike.angular_velocity.y(), 1e-12);
  EXPECT_NEAR(response.ball_angular_velocity.z, expected.strike.angular_velocity.z(), 1e-12);
  EXPECT_EQ(response.states, expected.strike.states);
  EXPECT_EQ(response.prediction.outcome, bsp::toString(expected.trajectory.outcome));
  EXPECT_NEAR(response.prediction.final_position.x, expected.trajectory.finalState().position.x(), 1e-12);
  EXPECT_NEAR(response.prediction.final_position.y, expected.trajectory.finalState().position.y(), 1e-12);
  EXPECT_NEAR(response.prediction.cue_speed_after, expected.strike.cue_velocity, 1e-12);
  EXPECT_EQ(response.prediction.header.frame_id, "table");
  EXPECT_FALSE(response.prediction.trajectory.empty());
}

TEST_F(PredictShotNode, SameShotInAnotherFrameGivesTheSamePrediction)
{
  tf2_ros::Buffer buffer;
  tf2_ros::TransformListener listener(buffer);
  const auto in_table = toRequest(shot_fixtures::masse());
  auto in_rotated = in_table;
  in_rotated.cue_pose = buffer.transform(in_table.cue_pose, "rotated", ros::Duration(5.0));
  in_rotated.ball_position = buffer.transform(in_table.ball_position, "rotated", ros::Duration(5.0));
  ASSERT_NE(in_rotated.cue_pose.pose.position.x, in_table.cue_pose.pose.position.x);
  const auto a = call(in_table), b = call(in_rotated);
  ASSERT_TRUE(a.success && b.success) << a.message << " / " << b.message;
  EXPECT_EQ(a.states, b.states);
  EXPECT_NEAR(a.ball_velocity.x, b.ball_velocity.x, 1e-9);
  EXPECT_NEAR(a.ball_velocity.y, b.ball_velocity.y, 1e-9);
  EXPECT_NEAR(a.ball_velocity.z, b.ball_velocity.z, 1e-9);
  EXPECT_NEAR(a.ball_angular_velocity.y, b.ball_angular_velocity.y, 1e-7);
  EXPECT_NEAR(a.prediction.final_position.x, b.prediction.final_position.x, 1e-6);
  EXPECT_EQ(b.prediction.header.frame_id, "table");
}

TEST_F(PredictShotNode, BadInputIsAnsweredWithAReason)
{
  struct Case
  {
    const char* what;
    bsp::PredictShot::Request request;
    const char* message;
    int32_t code = bsp::ErrorCode::INVALID_ARGUMENT;  ///< msg/ErrorCode.msg
  };
  std::vector<Case> cases;
  auto base = toRequest(shot_fixtures::masse());
  auto r = base;
  r.cue_pose.pose.position.x = std::nan("");
  cases.push_back({"NaN in the pose", r, "cue_pose.pose.position"});
  r = base;
  r.cue_speed = 0.0;
  cases.push_back({"zero speed", r, "cue_speed"});
  r = base;
  r.cue_speed = -1.0;
  cases.push_back({"negative speed", r, "cue_speed"});
  r = base;
  r.cue_pose.pose.orientation.w *= 2.0;
  cases.push_back({"non-unit quaternion", r, "unit quaternion"});
  r = toRequest(
      []
      {
        auto cue = shot_fixtures::masse();
        cue.direction = -cue.direction;
        cue.tip = Eigen::Vector3d(0.6, 0.1, 0.0286) + 0.0286 * Eigen::Vector3d(0.480151, -0.102889, 0.871131) +
                  0.05 * cue.direction;
        return cue;
      }());
  cases.push_back({"cue pointing away", r, "behind the cue", bsp::ErrorCode::INVALID_SHOT});
  r = toRequest(
      []
      {
        auto cue = shot_fixtures::follow();
        cue.tip = Eigen::Vector3d(cue.ball.x(), cue.ball.y(), 0.0286) - 0.01 * cue.direction;
        return cue;
      }());
  cases.push_back({"tip inside the ball", r, "inside the ball", bsp::ErrorCode::INVALID_SHOT});
  r = toRequest(
      []
      {
        auto cue = shot_fixtures::follow();
        cue.tip.y() += 0.2;
        return cue;
      }());
  cases.push_back({"axis misses the ball", r, "misses the ball", bsp::ErrorCode::INVALID_SHOT});
  r = toRequest(
      []
      {
        auto cue = shot_fixtures::follow();
        cue.tip.x() += 3.0;
        cue.ball.x() += 3.0;
        return cue;
      }());
  cases.push_back({"ball outside the table", r, "off the table"});
  r = base;
  r.cue_pose.header.frame_id = "no_such_frame";
  cases.push_back({"unknown frame", r, "cue_pose.header.frame_id", bsp::ErrorCode::TRANSFORM_FAILED});
  r = base;
  r.ball_position.header.frame_id = "";
  cases.push_back({"empty frame", r, "ball_position.header.frame_id"});
  r = base;
  r.override_names = {"cue_contact/friction"};
  r.override_values = {-0.5};
  cases.push_back({"bad override", r, "cue_contact/friction"});
  r = base;
  r.override_names = {"cue_end_mass"};
  r.override_values = {std::nan("")};
  cases.push_back({"NaN end mass", r, "cue_end_mass"});
  // A budget no strike fits in (a microsecond of wall clock): the time limit's own code, the budget named.
  r = toRequest(shot_fixtures::masse());
  r.override_names = {"solver/max_seconds"};
  r.override_values = {1e-6};
  cases.push_back({"time limit", r, "within 1e-06 s", bsp::ErrorCode::TIME_LIMIT});
  for (const Case& c : cases)
  {
    const auto response = call(c.request);
    EXPECT_FALSE(response.success) << c.what;
    EXPECT_EQ(response.error_code.val, c.code) << c.what << ": " << response.message;
    EXPECT_NE(response.message.find(c.message), std::string::npos) << c.what << ": " << response.message;
  }
}

TEST_F(PredictShotNode, OverridesChangeThePrediction)
{
  auto request = toRequest(shot_fixtures::masse());
  const auto plain = call(request);
  request.override_names = {"cue_contact/eta2"};
  request.override_values = {2.0};
  const auto softer = call(request);
  ASSERT_TRUE(plain.success && softer.success);
  EXPECT_GT(std::abs(plain.ball_angular_velocity.y - softer.ball_angular_velocity.y), 1e-3);
}

TEST_F(PredictShotNode, EveryStrokeIsPredicted)
{
  // A level draw (the tip 0.4 radii below the centre) and the same stroke with the tip held on the cue's axis (an
  // infinite end mass): both answered, backspin, and the held tip lifts the ball far more.
  auto request = toRequest(
      []
      {
        auto cue = shot_fixtures::follow();
        cue.direction = Eigen::Vector3d::UnitX();
        cue.tip = Eigen::Vector3d(cue.ball.x(), cue.ball.y(), 0.0286 - 0.4 * 0.0286) - 0.05 * cue.direction;
        return cue;
      }());
  const auto draw = call(request);
  request.override_names = {"cue_end_mass"};
  request.override_values = {std::numeric_limits<double>::infinity()};
  const auto held = call(request);
  ASSERT_TRUE(draw.success && held.success) << draw.message << " / " << held.message;
  EXPECT_LT(draw.ball_angular_velocity.y, 0.0);
  EXPECT_EQ(draw.states.front(), "S3");  // the cloth is not pressed
  EXPECT_TRUE(draw.prediction.leaves_cloth);
  EXPECT_GT(held.ball_velocity.z, 5.0 * draw.ball_velocity.z);
}

namespace
{
/// Sets one double through ~tuning; the server's answer (its configuration after the change).
dynamic_reconfigure::Config tuneDouble(const std::string& name, double value)
{
  dynamic_reconfigure::Reconfigure srv;
  dynamic_reconfigure::DoubleParameter parameter;
  parameter.name = name;
  parameter.value = value;
  srv.request.config.doubles.push_back(parameter);
  EXPECT_TRUE(ros::service::call("/shot_predictor/tuning/set_parameters", srv));
  return srv.response.config;
}

std::optional<double> doubleIn(const dynamic_reconfigure::Config& config, const std::string& name)
{
  for (const auto& parameter : config.doubles)
    if (parameter.name == name)
      return parameter.value;
  return std::nullopt;
}

std::string rejectedIn(const dynamic_reconfigure::Config& config)
{
  for (const auto& parameter : config.strs)
    if (parameter.name == "rejected")
      return parameter.value;
  return "<missing>";
}
}  // namespace

TEST_F(PredictShotNode, RunTimeTuningRejectsBadValuesWithTheReasonAndStaysUsable)
{
  const auto request = toRequest(shot_fixtures::masse());
  const auto before = call(request);
  // Beyond an open bound (clamped to it by dynamic_reconfigure: a mass of 0), across parameters, or NaN: rejected
  // whole; the answer is the node's unchanged configuration.
  struct Bad
  {
    const char* name;
    double value;
    const char* field;  // as the reason names it: the node's parameter name
  };
  for (const Bad& bad : {Bad{"cue_mass", -5.0, "cue_mass"}, Bad{"ball_radius", 0.001, "table/cushion_height"},
                         Bad{"cue_end_mass", std::nan(""), "cue_end_mass"}})
  {
    const std::string name = bad.name;
    const auto answer = tuneDouble(name, bad.value);
    EXPECT_NE(rejectedIn(answer).find(bad.field), std::string::npos) << name << ": " << rejectedIn(answer);
    const auto after = call(request);
    ASSERT_TRUE(after.success) << after.message;
    EXPECT_EQ(after.ball_angular_velocity.y, before.ball_angular_velocity.y) << name;
  }
  EXPECT_EQ(doubleIn(tuneDouble("ball_radius", 0.001), "ball_radius"), 0.0286);
  // Beyond a closed bound: clamped to it (the cfg's range is the parameter's own), and applied.
  const auto clamped = tuneDouble("table_cloth_restitution", 1.5);
  EXPECT_EQ(rejectedIn(clamped), "");
  EXPECT_EQ(doubleIn(clamped, "table_cloth_restitution"), 1.0);
  EXPECT_EQ(rejectedIn(tuneDouble("table_cloth_restitution", 0.51625)), "");
  // A valid change after the rejections is applied (no stuck server), and so is the restore.
  const auto applied = tuneDouble("cue_contact_friction", 0.5);
  EXPECT_EQ(rejectedIn(applied), "");
  EXPECT_EQ(doubleIn(applied, "cue_contact_friction"), 0.5);
  EXPECT_NE(call(request).ball_angular_velocity.y, before.ball_angular_velocity.y);
  EXPECT_EQ(rejectedIn(tuneDouble("cue_contact_friction", 0.7)), "");
  EXPECT_EQ(call(request).ball_angular_velocity.y, before.ball_angular_velocity.y);
}

TEST_F(PredictShotNode, RunTimeTuningChangesThePrediction)
{
  auto tune = [](double eta2)
  {
    dynamic_reconfigure::Reconfigure srv;
    dynamic_reconfigure::DoubleParameter value;
    value.name = "cue_contact_eta2";
    value.value = eta2;
    srv.request.config.doubles.push_back(value);
    return ros::service::call("/shot_predictor/tuning/set_parameters", srv);
  };
  auto request = toRequest(shot_fixtures::masse());
  auto overridden = request;
  overridden.override_names = {"cue_contact/eta2"};
  overridden.override_values = {2.0};
  const auto expected = call(overridden);
  ASSERT_TRUE(tune(2.0));
  const auto tuned = call(request);
  ASSERT_TRUE(tune(1.2));  // back to config/default.yaml
  const auto restored = call(request);
  ASSERT_TRUE(expected.success && tuned.success && restored.success);
  EXPECT_EQ(tuned.ball_angular_velocity.y, expected.ball_angular_velocity.y);
  EXPECT_EQ(restored.ball_angular_velocity.y, call(request).ball_angular_velocity.y);
  EXPECT_NE(restored.ball_angular_velocity.y, tuned.ball_angular_velocity.y);
}

TEST_F(PredictShotNode, MarkersAreLatchedArraysThatReplaceEachOther)
{
  ros::NodeHandle nh;
  std::vector<visualization_msgs::MarkerArray> received;
  std::mutex mutex;
  auto subscriber =
      nh.subscribe<visualization_msgs::MarkerArray>("/shot_predictor/trajectory_markers", 10,
                                                    [&](const visualization_msgs::MarkerArray::ConstPtr& m)
                                                    {
                                                      std::lock_guard<std::mutex> lock(mutex);
                                                      received.push_back(*m);
                                                    });
  auto wait_for = [&](std::size_t count)
  {
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(20.0);
    while (ros::WallTime::now() < deadline)
    {
      ros::spinOnce();
      {
        std::lock_guard<std::mutex> lock(mutex);
        if (received.size() >= count)
          return true;
      }
      ros::WallDuration(0.01).sleep();
    }
    return false;
  };
  ASSERT_TRUE(call(toRequest(shot_fixtures::masse())).success);
  ASSERT_TRUE(wait_for(1));  // the latched array (of this or an earlier call) arrives
  ASSERT_TRUE(call(toRequest(shot_fixtures::follow())).success);
  ASSERT_TRUE(wait_for(2));
  std::lock_guard<std::mutex> lock(mutex);
  const auto& last = received.back();
  ASSERT_FALSE(last.markers.empty());
  EXPECT_EQ(last.markers.front().action, visualization_msgs::Marker::DELETEALL);
  std::set<std::string> namespaces;
  for (const auto& m : last.markers)
    namespaces.insert(m.ns);
  for (const char* ns : {"trajectory", "ball_start", "ball_end", "velocity", "spin", "hit_point", "cue", "table"})
    EXPECT_EQ(namespaces.count(ns), 1u) << ns;
  // The second array is the follow shot's: its ball starts at (−0.6, −0.2).
  for (const auto& m : last.markers)
    if (m.ns == "ball_start")
    {
      EXPECT_NEAR(m.pose.position.x, -0.6, 1e-9);
    }
}

TEST_F(PredictShotNode, PredictionIsPublished)
{
  ros::NodeHandle nh;
  std::atomic<int> received{0};
  std::atomic<double> velocity{0.0};
  auto subscriber = nh.subscribe<bsp::ShotPrediction>("/shot_predictor/prediction", 10,
                                                      [&](const bsp::ShotPrediction::ConstPtr& m)
                                                      {
                                                        velocity = m->ball_velocity.x;
                                                        ++received;
                                                      });
  const ros::WallTime connect_deadline = ros::WallTime::now() + ros::WallDuration(10.0);
  while (subscriber.getNumPublishers() == 0 && ros::WallTime::now() < connect_deadline)
    ros::WallDuration(0.01).sleep();
  const auto response = call(toRequest(shot_fixtures::masse()));
  ASSERT_TRUE(response.success);
  // ~prediction is latched: the previous call's prediction may come first.
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(10.0);
  while (velocity.load() != response.ball_velocity.x && ros::WallTime::now() < deadline)
  {
    ros::spinOnce();
    ros::WallDuration(0.01).sleep();
  }
  ASSERT_GT(received.load(), 0);
  EXPECT_EQ(velocity.load(), response.ball_velocity.x);
}

TEST_F(PredictShotNode, ConcurrentCallersAreAllAnsweredCorrectly)
{
  const auto request = toRequest(shot_fixtures::follow());
  const auto reference = call(request);
  ASSERT_TRUE(reference.success);
  std::atomic<int> correct{0};
  std::vector<double> latencies_ms;
  std::mutex latency_mutex;
  std::vector<std::thread> clients;
  for (int c = 0; c < 8; ++c)
    clients.emplace_back(
        [&]
        {
          ros::NodeHandle nh;
          ros::ServiceClient client = nh.serviceClient<bsp::PredictShot>(SERVICE, /*persistent=*/true);
          for (int i = 0; i < 200; ++i)
          {
            bsp::PredictShot srv;
            srv.request = request;
            const auto start = std::chrono::steady_clock::now();
            const bool ok = client.call(srv);
            const double ms =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
            if (ok && srv.response.success && srv.response.ball_velocity.x == reference.ball_velocity.x &&
                srv.response.prediction.final_position.y == reference.prediction.final_position.y)
              ++correct;
            std::lock_guard<std::mutex> lock(latency_mutex);
            latencies_ms.push_back(ms);
          }
        });
  for (auto& t : clients)
    t.join();
  EXPECT_EQ(correct.load(), 8 * 200);
  std::sort(latencies_ms.begin(), latencies_ms.end());
  std::printf("8 clients x 200 calls: round trip p50 %.2f ms, p99 %.2f ms\n", latencies_ms[latencies_ms.size() / 2],
              latencies_ms[latencies_ms.size() * 99 / 100]);
}

TEST_F(PredictShotNode, ABadParameterStopsTheNode)
{
  // The node with ball_radius = −0.01 exits at start-up; its service never appears.
  EXPECT_FALSE(ros::service::waitForService("/bad_predictor/predict_shot", ros::Duration(3.0)));
  std::vector<std::string> nodes;
  ASSERT_TRUE(ros::master::getNodes(nodes));
  EXPECT_EQ(std::count(nodes.begin(), nodes.end(), "/bad_predictor"), 0);
}

int main(int argc, char** argv)
{
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_predict_shot_node");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}

namespace
{
/// The follow shot with an object ball "one" 0.3 m ahead of the cue ball on its line, in the table frame.
bsp::PredictShot::Request followWithObjectBall()
{
  auto request = toRequest(shot_fixtures::follow());
  request.table.header.frame_id = "table";
  bsp::Ball one;
  one.id = "one";
  one.position.x = shot_fixtures::follow().ball.x() + 0.3;
  one.position.y = shot_fixtures::follow().ball.y();
  request.table.balls.push_back(one);
  return request;
}
}  // namespace

// Every ball of the table is predicted, as the core library predicts it; the frame of the table does not matter.
TEST_F(PredictShotNode, TheTableIsPredictedBallByBall)
{
  const auto request = followWithObjectBall();
  const auto response = call(request);
  ASSERT_TRUE(response.success) << response.message;
  ASSERT_EQ(response.prediction.balls.size(), 2u);
  EXPECT_EQ(response.prediction.balls[0].id, "cue");
  EXPECT_EQ(response.prediction.balls[1].id, "one");
  EXPECT_EQ(response.prediction.first_contact, "one");
  bsp::CuePlacement cue = shot_fixtures::follow();
  const auto& o = request.cue_pose.pose.orientation;
  cue.direction = Eigen::Quaterniond(o.w, o.x, o.y, o.z).normalized() * Eigen::Vector3d::UnitX();
  bsp::TableBall one{"one", {}};
  one.state.position << request.table.balls[0].position.x, request.table.balls[0].position.y, 0.0;
  const auto expected = bsp::predictShot(cue, bsp::ShotConfiguration{}, {one}).value();
  const auto& final_one = response.prediction.balls[1].final_position;
  EXPECT_NEAR(final_one.x, expected.table.balls[1].finalState().position.x(), 1e-9);
  EXPECT_NEAR(final_one.y, expected.table.balls[1].finalState().position.y(), 1e-9);
  EXPECT_GT(final_one.x, one.state.position.x());  // struck forward
  EXPECT_FALSE(response.prediction.balls[1].path.empty());

  tf2_ros::Buffer buffer;
  tf2_ros::TransformListener listener(buffer);
  auto rotated = request;
  geometry_msgs::PointStamped point;
  point.header = request.table.header;
  point.point = request.table.balls[0].position;
  rotated.table.header.frame_id = "rotated";
  rotated.table.balls[0].position = buffer.transform(point, "rotated", ros::Duration(5.0)).point;
  const auto again = call(rotated);
  ASSERT_TRUE(again.success) << again.message;
  EXPECT_NEAR(again.prediction.balls[1].final_position.x, final_one.x, 1e-6);
  EXPECT_NEAR(again.prediction.balls[1].final_position.y, final_one.y, 1e-6);
}

// A tracked ball in motion starts with its velocity and spin, as the core library starts it, whatever frame they come
// in: the vectors turn with the frame and do not shift with it. The cue ball must be at rest (the tracker's noise,
// below ~planning/rest_speed, is dropped).
TEST_F(PredictShotNode, AMovingBallStartsWithItsTrackedMotion)
{
  constexpr double SPEED = 0.3;  // m/s along +y, rolling: the spin about -x is SPEED / R
  auto request = followWithObjectBall();
  request.table.balls[0].velocity.y = SPEED;
  request.table.balls[0].angular_velocity.x = -SPEED / bsp::ShotConfiguration{}.ball_radius;
  const auto response = call(request);
  ASSERT_TRUE(response.success) << response.message;

  bsp::CuePlacement cue = shot_fixtures::follow();
  const auto& o = request.cue_pose.pose.orientation;
  cue.direction = Eigen::Quaterniond(o.w, o.x, o.y, o.z).normalized() * Eigen::Vector3d::UnitX();
  bsp::TableBall one{"one", {}};
  one.state.position << request.table.balls[0].position.x, request.table.balls[0].position.y, 0.0;
  one.state.velocity << 0.0, SPEED, 0.0;
  one.state.angular_velocity << -SPEED / bsp::ShotConfiguration{}.ball_radius, 0.0, 0.0;
  const auto expected = bsp::predictShot(cue, bsp::ShotConfiguration{}, {one}).value();
  const auto& final_one = response.prediction.balls[1].final_position;
  EXPECT_NEAR(final_one.x, expected.table.balls[1].finalState().position.x(), 1e-9);
  EXPECT_NEAR(final_one.y, expected.table.balls[1].finalState().position.y(), 1e-9);
  const auto at_rest = call(followWithObjectBall());
  ASSERT_TRUE(at_rest.success) << at_rest.message;
  // The motion counts: 0.05 s after the strike, before the cue ball reaches it, the ball has rolled about
  // 0.3 m/s × 0.05 s = 15 mm where the resting one has not moved.
  const auto at = [](const bsp::BallPrediction& ball, double t)
  { return *std::find_if(ball.path.begin(), ball.path.end(), [&](const auto& sample) { return sample.time >= t; }); };
  EXPECT_NEAR(at(response.prediction.balls[1], 0.05).position.y - at(at_rest.prediction.balls[1], 0.05).position.y,
              SPEED * at(response.prediction.balls[1], 0.05).time, 1e-3);

  tf2_ros::Buffer buffer;
  tf2_ros::TransformListener listener(buffer);
  auto rotated = request;
  rotated.table.header.frame_id = "rotated";
  geometry_msgs::PointStamped point;
  point.header = request.table.header;
  point.point = request.table.balls[0].position;
  rotated.table.balls[0].position = buffer.transform(point, "rotated", ros::Duration(5.0)).point;
  for (auto [given, turned] :
       {std::pair{request.table.balls[0].velocity, &rotated.table.balls[0].velocity},
        std::pair{request.table.balls[0].angular_velocity, &rotated.table.balls[0].angular_velocity}})
  {
    geometry_msgs::Vector3Stamped vector;
    vector.header = request.table.header;
    vector.vector = given;
    *turned = buffer.transform(vector, "rotated", ros::Duration(5.0)).vector;
  }
  const auto again = call(rotated);
  ASSERT_TRUE(again.success) << again.message;
  EXPECT_NEAR(again.prediction.balls[1].final_position.x, final_one.x, 1e-6);
  EXPECT_NEAR(again.prediction.balls[1].final_position.y, final_one.y, 1e-6);
}

TEST_F(PredictShotNode, AMovingCueBallIsRefusedWithItsCodeAndItsNoiseIsDropped)
{
  auto request = followWithObjectBall();
  bsp::Ball cue;
  cue.id = "cue";
  cue.position.x = shot_fixtures::follow().ball.x();
  cue.position.y = shot_fixtures::follow().ball.y();
  request.table.balls.push_back(cue);
  const auto at_rest = call(request);
  ASSERT_TRUE(at_rest.success) << at_rest.message;

  request.table.balls[1].velocity.x = 0.5;  // m/s, fifty times the default ~planning/rest_speed
  const auto moving = call(request);
  EXPECT_FALSE(moving.success);
  EXPECT_EQ(moving.error_code.val, bsp::ErrorCode::BALLS_MOVING) << moving.message;
  EXPECT_NE(moving.message.find("rest_speed"), std::string::npos) << moving.message;

  request.table.balls[1].velocity.x = 0.002;  // a tracker's noise
  const auto noisy = call(request);
  ASSERT_TRUE(noisy.success) << noisy.message;
  EXPECT_EQ(noisy.prediction.balls[1].final_position.x, at_rest.prediction.balls[1].final_position.x);
  EXPECT_EQ(noisy.prediction.balls[1].final_position.y, at_rest.prediction.balls[1].final_position.y);
}

// A stroke is the same shot as the cue pose it describes, in this package's convention and in pooltool's and
// FastFiz's (their numbers converted by hand here: pooltool's heading is 90° more, its a of the opposite sign;
// FastFiz's heading 90° less, its offsets in millimetres).
TEST_F(PredictShotNode, AStrokeIsTheSameShotAsItsCuePoseInEveryConvention)
{
  constexpr double R = 0.0286, DEG = M_PI / 180.0;
  const bsp::Stroke stroke{30.0 * DEG, 12.0 * DEG, 2.5, 0.3, -0.2};
  const Eigen::Vector2d ball(-0.4, 0.1);
  const auto cue = bsp::placeStroke(stroke, ball, R);
  ASSERT_TRUE(cue.ok()) << cue.error().describe();
  const auto as_pose = call(toRequest(cue.value()));
  ASSERT_TRUE(as_pose.success) << as_pose.message;

  bsp::PlayerStroke ours, pooltool, fastfiz;
  ours.phi = stroke.phi;
  ours.theta = stroke.theta;
  ours.speed = stroke.speed;
  ours.a = stroke.a;
  ours.b = stroke.b;
  pooltool.convention = "pooltool";
  pooltool.phi = 120.0;
  pooltool.theta = 12.0;
  pooltool.speed = 2.5;
  pooltool.a = -0.3;
  pooltool.b = -0.2;
  fastfiz.convention = "fastfiz";
  fastfiz.phi = -60.0;
  fastfiz.theta = 12.0;
  fastfiz.speed = 2.5;
  fastfiz.a = 0.3 * R * 1e3;
  fastfiz.b = -0.2 * R * 1e3;
  for (const auto& given : {ours, pooltool, fastfiz})
  {
    auto request = toRequest(cue.value());
    request.cue_pose = geometry_msgs::PoseStamped();  // unused with a stroke
    request.cue_speed = 0.0;
    request.stroke = given;
    const auto as_stroke = call(request);
    ASSERT_TRUE(as_stroke.success) << given.convention << ": " << as_stroke.message;
    for (const auto& [x, y] : {std::pair{as_stroke.ball_velocity, as_pose.ball_velocity},
                               std::pair{as_stroke.ball_angular_velocity, as_pose.ball_angular_velocity}})
    {
      const double scale = std::max(1.0, std::hypot(y.x, y.y, y.z));
      EXPECT_NEAR(x.x, y.x, 1e-9 * scale) << given.convention;
      EXPECT_NEAR(x.y, y.y, 1e-9 * scale) << given.convention;
      EXPECT_NEAR(x.z, y.z, 1e-9 * scale) << given.convention;
    }
  }
  auto bad = toRequest(cue.value());
  bad.stroke = ours;
  bad.stroke.convention = "snooker";
  EXPECT_NE(call(bad).message.find("stroke.convention"), std::string::npos);
  bad.stroke = ours;
  bad.stroke.a = 1.2;  // off the ball
  const auto off = call(bad);
  EXPECT_FALSE(off.success);
  EXPECT_NE(off.message.find("stroke.a"), std::string::npos) << off.message;
  bad.stroke = ours;
  bad.stroke.speed = -1.0;
  EXPECT_NE(call(bad).message.find("stroke.speed"), std::string::npos);
}

TEST_F(PredictShotNode, BadTablesAreAnsweredWithAReason)
{
  auto duplicate = followWithObjectBall();
  duplicate.table.balls.push_back(duplicate.table.balls[0]);
  duplicate.table.balls[1].position.x += 0.2;
  auto no_frame = followWithObjectBall();
  no_frame.table.header.frame_id = "";
  auto not_finite = followWithObjectBall();
  not_finite.table.balls[0].position.y = std::numeric_limits<double>::quiet_NaN();
  auto moving_nan = followWithObjectBall();
  moving_nan.table.balls[0].angular_velocity.z = std::numeric_limits<double>::infinity();
  auto overlap = followWithObjectBall();
  overlap.table.balls[0].position.x = shot_fixtures::follow().ball.x() + 0.03;
  for (const auto& [request, field] :
       {std::pair{duplicate, "table.balls[1].id"}, std::pair{no_frame, "table.header.frame_id"},
        std::pair{not_finite, "table.balls[0].position"}, std::pair{overlap, "table.balls[0].position"},
        std::pair{moving_nan, "table.balls[0].angular_velocity"}})
  {
    const auto response = call(request);
    EXPECT_FALSE(response.success) << field;
    EXPECT_NE(response.message.find(field), std::string::npos) << response.message;
  }
}

// A request without a table uses the latest TableState received on ~table_state.
TEST_F(PredictShotNode, TheLatestTableStateIsUsedWhenTheRequestHasNone)
{
  ros::NodeHandle node;
  ros::Publisher publisher = node.advertise<bsp::TableState>("/shot_predictor/table_state", 1, true);
  const auto with_table = followWithObjectBall();
  publisher.publish(with_table.table);
  auto without = with_table;
  without.table = bsp::TableState{};
  bool used = false;
  for (int attempt = 0; attempt < 50 && !used; ++attempt)
  {
    ros::Duration(0.1).sleep();
    const auto response = call(without);
    used = response.success && response.prediction.balls.size() == 2;
  }
  EXPECT_TRUE(used);
  publisher.publish(bsp::TableState{});  // the other tests predict the cue ball alone
  for (int attempt = 0; attempt < 50; ++attempt)
  {
    ros::Duration(0.1).sleep();
    if (call(without).prediction.balls.size() == 1)
      break;
  }
  EXPECT_EQ(call(without).prediction.balls.size(), 1u);
}

// With ~table_state_timeout (0.5 s for the node "stale_predictor" of predict_shot.test), the latest table state is
// used while it is fresh and refused with STALE_INPUT once it is older; a request that gives its balls is unaffected.
TEST_F(PredictShotNode, AStaleTableStateIsRefusedWithItsCode)
{
  const std::string stale_service = "/stale_predictor/predict_shot";
  ASSERT_TRUE(ros::service::waitForService(stale_service, ros::Duration(30)));
  ros::NodeHandle node;
  ros::Publisher publisher = node.advertise<bsp::TableState>("/stale_predictor/table_state", 1, true);
  const auto with_table = followWithObjectBall();
  auto without = with_table;
  without.table = bsp::TableState{};
  const auto callStale = [&](const bsp::PredictShot::Request& request)
  {
    bsp::PredictShot srv;
    srv.request = request;
    EXPECT_TRUE(ros::service::call(stale_service, srv));
    return srv.response;
  };
  bool fresh = false;
  for (int attempt = 0; attempt < 50 && !fresh; ++attempt)
  {
    publisher.publish(with_table.table);
    ros::Duration(0.05).sleep();
    const auto response = callStale(without);
    fresh = response.success && response.prediction.balls.size() == 2;
  }
  EXPECT_TRUE(fresh);
  ros::Duration(1.0).sleep();
  const auto stale = callStale(without);
  EXPECT_FALSE(stale.success);
  EXPECT_EQ(stale.error_code.val, bsp::ErrorCode::STALE_INPUT) << stale.message;
  EXPECT_NE(stale.message.find("table"), std::string::npos) << stale.message;
  EXPECT_TRUE(callStale(with_table).success);
  // /diagnostics says so: the node's status warns of the stale table state.
  const auto status = waitForStatus("stale_predictor: health", diagnostic_msgs::DiagnosticStatus::WARN);
  ASSERT_TRUE(status.has_value());
  EXPECT_NE(status->message.find("table_state"), std::string::npos) << status->message;
}

TEST_F(PredictShotNode, DiagnosticsReportTheNodesCallsAndTableStateUnderItsName)
{
  const auto response = call(toRequest(shot_fixtures::follow()));
  ASSERT_TRUE(response.success) << response.message;
  const auto status = waitForStatus("shot_predictor: health", std::nullopt, "predict_shot calls");
  ASSERT_TRUE(status.has_value());
  EXPECT_EQ(status->hardware_id, "none");
  std::map<std::string, std::string> values;
  for (const auto& pair : status->values)
    values[pair.key] = pair.value;
  EXPECT_GE(std::stol(values["predict_shot calls"]), 1);
  EXPECT_GT(std::stod(values["predict_shot latency median (ms)"]), 0.0);
  EXPECT_GE(std::stod(values["predict_shot latency max (ms)"]), std::stod(values["predict_shot latency median (ms)"]));
  EXPECT_TRUE(values.count("table_state age (s)"));
}

// ~get_configuration answers the parameters in force by their names: default.yaml's, with predict_shot.test's
// threads = 4.
TEST_F(PredictShotNode, GetConfigurationAnswersTheParametersInForce)
{
  bsp::GetConfiguration srv;
  ASSERT_TRUE(ros::service::call("/shot_predictor/get_configuration", srv));
  ASSERT_TRUE(srv.response.success) << srv.response.message;
  ASSERT_EQ(srv.response.names.size(), srv.response.values.size());
  std::map<std::string, double> numbers;
  for (std::size_t i = 0; i < srv.response.names.size(); ++i)
    numbers[srv.response.names[i]] = srv.response.values[i];
  EXPECT_EQ(numbers.at("threads"), 4.0);
  EXPECT_EQ(numbers.at("ball_radius"), 0.0286);
  EXPECT_EQ(numbers.at("table/cloth/friction"), 0.152479);
  EXPECT_EQ(numbers.at("planning/rollouts"), 200.0);
  std::map<std::string, std::string> choices;
  for (std::size_t i = 0; i < srv.response.choice_names.size(); ++i)
    choices[srv.response.choice_names[i]] = srv.response.choice_values[i];
  EXPECT_EQ(choices.at("target_frame"), "table");
  EXPECT_EQ(choices.at("motion/rolling_model"), "paper");
  EXPECT_EQ(choices.at("table/cushion/law/type"), "constant");
}

// The prediction is stamped with the strike's time, the cue pose's stamp (a pose in the table frame needs no tf at
// that time), and ~prediction is latched: a subscriber that connects after the call still gets it.
TEST_F(PredictShotNode, ThePredictionIsStampedWithTheStrikeAndLatched)
{
  auto request = toRequest(shot_fixtures::follow());
  request.cue_pose.header.stamp = ros::Time(1234.5);
  const auto response = call(request);
  ASSERT_TRUE(response.success) << response.message;
  EXPECT_EQ(response.prediction.header.stamp, ros::Time(1234.5));
  ros::NodeHandle node;
  std::atomic<bool> received{false};
  ros::Subscriber subscriber = node.subscribe<bsp::ShotPrediction>(
      "/shot_predictor/prediction", 1, [&](const bsp::ShotPrediction::ConstPtr&) { received = true; });
  for (int attempt = 0; attempt < 100 && !received; ++attempt)
  {
    ros::Duration(0.05).sleep();
    ros::spinOnce();
  }
  EXPECT_TRUE(received);
}

// ~get_table answers the table the node predicts on by ids a client can name, and ~table holds the same, latched:
// default.yaml's 9-ft table, its six pockets' mouths the WPA's (corner 4.5-4.625 in, side 5-5.125 in).
TEST_F(PredictShotNode, TheTableIsAnsweredAndLatchedWithItsPocketsIds)
{
  bsp::GetTable srv;
  ASSERT_TRUE(ros::service::call("/shot_predictor/get_table", srv));
  ASSERT_TRUE(srv.response.success) << srv.response.message;
  EXPECT_EQ(srv.response.error_code.val, bsp::ErrorCode::SUCCESS);
  const bsp::TableGeometry& table = srv.response.table;
  EXPECT_EQ(table.header.frame_id, "table");
  EXPECT_EQ(table.length, 2.54);
  std::set<std::string> ids;
  for (const auto& pocket : table.pockets)
  {
    ids.insert(pocket.id);
    const double mouth = std::hypot(pocket.jaw_out.x - pocket.jaw_in.x, pocket.jaw_out.y - pocket.jaw_in.y);
    const bool side = pocket.id.find("side") != std::string::npos;
    EXPECT_GE(mouth, (side ? 5.0 : 4.5) * 0.0254 - 1e-12) << pocket.id;
    EXPECT_LE(mouth, (side ? 5.125 : 4.625) * 0.0254 + 1e-12) << pocket.id;
  }
  EXPECT_EQ(ids,
            (std::set<std::string>{"bottom_left", "bottom_side", "bottom_right", "top_right", "top_side", "top_left"}));
  for (const auto& segment : table.cushions)
    EXPECT_EQ(segment.start.z, table.cushion_height) << segment.id;

  ros::NodeHandle node;
  std::atomic<std::size_t> latched_pockets{0};
  ros::Subscriber subscriber = node.subscribe<bsp::TableGeometry>(
      "/shot_predictor/table", 1, [&](const bsp::TableGeometry::ConstPtr& m) { latched_pockets = m->pockets.size(); });
  for (int attempt = 0; attempt < 100 && latched_pockets == 0; ++attempt)
  {
    ros::Duration(0.05).sleep();
    ros::spinOnce();
  }
  EXPECT_EQ(latched_pockets, 6u);
}

// Round-trip time of ~predict_shot on localhost for the paper's massé shot (strike, trajectory, message and
// markers included), one persistent client calling in sequence, or several clients at once sending the fault mix
// (valid calls alternating with bad ones). Prints p50 and p99. Run by ./scripts/bench against a node it starts.
#include <billiard_shot_planner/PredictShot.h>
#include <ros/ros.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include "../test/fixtures/bench_problems.hpp"

namespace
{
/// The massé shot as the service takes it (table frame).
billiard_shot_planner::PredictShot::Request masseRequest()
{
  billiard_shot_planner::PredictShot::Request request;
  const billiard_shot_planner::CuePlacement shot = bench::serviceMasseShot();
  const Eigen::Vector3d& tip = shot.tip;
  const Eigen::Quaterniond q = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitX(), shot.direction);
  request.cue_pose.header.frame_id = "table";
  request.cue_pose.pose.position.x = tip.x();
  request.cue_pose.pose.position.y = tip.y();
  request.cue_pose.pose.position.z = tip.z();
  request.cue_pose.pose.orientation.x = q.x();
  request.cue_pose.pose.orientation.y = q.y();
  request.cue_pose.pose.orientation.z = q.z();
  request.cue_pose.pose.orientation.w = q.w();
  request.cue_speed = shot.speed;
  request.ball_position.header.frame_id = "table";
  request.ball_position.point.x = shot.ball.x();
  request.ball_position.point.y = shot.ball.y();
  return request;
}

/// The break as the service takes it: a level cue through the cue ball's centre towards the rack at the cue speed
/// of bench::breakShot's ball speed, and the 15 racked balls as the request's table. The node's wall-clock budget
/// is raised to the longest, since the break takes longer than the default second (bench/NOTES.md).
billiard_shot_planner::PredictShot::Request breakRequest()
{
  const std::vector<billiard_shot_planner::TableBall> balls = bench::breakShot();
  const Eigen::Vector3d centre = balls[0].state.position;
  billiard_shot_planner::PredictShot::Request request;
  request.cue_pose.header.frame_id = "table";
  request.cue_pose.pose.position.x = centre.x() - billiard_shot_planner::BallProperties{}.radius;
  request.cue_pose.pose.position.y = centre.y();
  request.cue_pose.pose.position.z = centre.z();
  request.cue_pose.pose.orientation.w = 1.0;
  request.cue_speed = balls[0].state.velocity.norm();
  request.ball_position.header.frame_id = "table";
  request.ball_position.point.x = centre.x();
  request.ball_position.point.y = centre.y();
  request.table.header.frame_id = "table";
  for (std::size_t i = 1; i < balls.size(); ++i)
  {
    billiard_shot_planner::Ball ball;
    ball.id = balls[i].id;
    ball.position.x = balls[i].state.position.x();
    ball.position.y = balls[i].state.position.y();
    request.table.balls.push_back(ball);
  }
  request.override_names = {"solver/max_seconds"};
  request.override_values = {60.0};
  return request;
}

/// The fault mix: the massé shot alternating with four kinds of bad request (NaN pose, a bad override, an empty
/// frame, an axis that misses the ball).
std::vector<billiard_shot_planner::PredictShot::Request> faultMix()
{
  std::vector<billiard_shot_planner::PredictShot::Request> mix(8, masseRequest());
  mix[1].cue_pose.pose.position.x = std::nan("");
  mix[3].override_names = {"motion/max_time"};
  mix[3].override_values = {1e12};
  mix[5].ball_position.header.frame_id = "";
  mix[7].cue_pose.pose.position.y += 0.2;
  return mix;
}

double percentile(std::vector<double> values, int p)
{
  std::sort(values.begin(), values.end());
  return values[values.size() * p / 100];
}
}  // namespace

/// Arguments: N calls (default 1000); with "mix C", C clients (threads, each with its persistent connection)
/// share the N calls of the fault mix; with "break", the break with the full rack.
int main(int argc, char** argv)
{
  ros::init(argc, argv, "service_roundtrip");
  ros::NodeHandle nh;
  const int calls = argc > 1 ? std::stoi(argv[1]) : 1000;
  const bool mix = argc > 2 && std::string(argv[2]) == "mix";
  const bool rack = argc > 2 && std::string(argv[2]) == "break";
  const int clients = mix && argc > 3 ? std::stoi(argv[3]) : 1;
  const std::string service = "/shot_predictor/predict_shot";
  if (!ros::service::waitForService(service, ros::Duration(30)))
    return 1;
  const auto requests = mix    ? faultMix()
                        : rack ? std::vector<billiard_shot_planner::PredictShot::Request>{breakRequest()}
                               : std::vector<billiard_shot_planner::PredictShot::Request>{masseRequest()};
  std::vector<std::vector<double>> ms(static_cast<std::size_t>(clients));
  std::atomic<bool> failed{false};
  auto client = [&](int c)
  {
    ros::ServiceClient predictor = nh.serviceClient<billiard_shot_planner::PredictShot>(service, true);
    for (int i = c; i < calls; i += clients)
    {
      billiard_shot_planner::PredictShot srv;
      srv.request = requests[static_cast<std::size_t>(i) % requests.size()];
      const auto start = std::chrono::steady_clock::now();
      const bool valid = !mix || i % 2 == 0;
      if (!predictor.call(srv) || srv.response.success != valid)
        failed = true;
      ms[static_cast<std::size_t>(c)].push_back(
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    }
  };
  std::vector<std::thread> threads;
  for (int c = 0; c < clients; ++c)
    threads.emplace_back(client, c);
  for (std::thread& t : threads)
    t.join();
  if (failed)
    return 1;
  std::vector<double> all;
  for (const auto& list : ms)
    all.insert(all.end(), list.begin(), list.end());
  if (mix)
    std::printf("service round trip, fault mix, %d clients, %d calls: p50 %.2f ms, p99 %.2f ms\n", clients, calls,
                percentile(all, 50), percentile(all, 99));
  else if (rack)
    std::printf("service round trip, break with the full rack, %d calls: p50 %.2f ms, p99 %.2f ms\n", calls,
                percentile(all, 50), percentile(all, 99));
  else
    std::printf("service round trip, massé shot, %d calls: p50 %.2f ms, p99 %.2f ms\n", calls, percentile(all, 50),
                percentile(all, 99));
  return 0;
}

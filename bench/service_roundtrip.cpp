// Round-trip time of ~predict_shot on localhost for the paper's massé shot (strike, trajectory, message and
// markers included), one persistent client calling in sequence. Prints p50 and p99 over N calls (argument,
// default 1000). Run by ./scripts/bench against a node it starts.
#include <billiard_shot_planner/PredictShot.h>
#include <ros/ros.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "bench_problems.hpp"

int main(int argc, char** argv)
{
  ros::init(argc, argv, "service_roundtrip");
  ros::NodeHandle nh;
  const int calls = argc > 1 ? std::stoi(argv[1]) : 1000;
  const std::string service = "/shot_predictor/predict_shot";
  if (!ros::service::waitForService(service, ros::Duration(30)))
    return 1;
  billiard_shot_planner::PredictShot srv;
  const billiard_shot_planner::CuePlacement shot = bench::serviceMasseShot();
  const Eigen::Vector3d& tip = shot.tip;
  const Eigen::Quaterniond q = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitX(), shot.direction);
  srv.request.cue_pose.header.frame_id = "table";
  srv.request.cue_pose.pose.position.x = tip.x();
  srv.request.cue_pose.pose.position.y = tip.y();
  srv.request.cue_pose.pose.position.z = tip.z();
  srv.request.cue_pose.pose.orientation.x = q.x();
  srv.request.cue_pose.pose.orientation.y = q.y();
  srv.request.cue_pose.pose.orientation.z = q.z();
  srv.request.cue_pose.pose.orientation.w = q.w();
  srv.request.cue_speed = shot.speed;
  srv.request.ball_position.header.frame_id = "table";
  srv.request.ball_position.point.x = shot.ball.x();
  srv.request.ball_position.point.y = shot.ball.y();
  ros::ServiceClient client = nh.serviceClient<billiard_shot_planner::PredictShot>(service, true);
  std::vector<double> ms;
  for (int i = 0; i < calls; ++i)
  {
    const auto start = std::chrono::steady_clock::now();
    if (!client.call(srv) || !srv.response.success)
      return 1;
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(ms.begin(), ms.end());
  std::printf("service round trip, massé shot, %d calls: p50 %.2f ms, p99 %.2f ms\n", calls, ms[ms.size() / 2],
              ms[ms.size() * 99 / 100]);
  return 0;
}

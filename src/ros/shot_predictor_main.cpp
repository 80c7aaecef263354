#include <ros/ros.h>

#include <stdexcept>

#include "shot_predictor_node.hpp"

int main(int argc, char** argv)
{
  ros::init(argc, argv, "shot_predictor");
  ros::NodeHandle node, private_node("~");
  try
  {
    billiard_shot_planner::ShotPredictorNode predictor(node, private_node);
    ros::MultiThreadedSpinner spinner(predictor.threads());
    spinner.spin();
  }
  catch (const std::runtime_error& e)
  {
    ROS_FATAL("%s", e.what());
    return 1;
  }
  return 0;
}

// aco-ros-planner: the colony as a ROS 1 global planner (README.md). Started with rosrun-style
// arguments (__name:=, remappings, _param:=value), e.g.
//   aco-ros-planner __name:=aco_planner _preset:=robust map:=/map
#include <ros/ros.h>

#include "ros_planner.hpp"

int main(int argc, char** argv) {
  ros::init(argc, argv, "aco_planner");
  ros::NodeHandle node;
  ros::NodeHandle params("~");
  aco_ros::RosPlanner planner(node, params);
  ros::AsyncSpinner spinner(1);  // the map and the publishers' callbacks; plans have their own thread
  spinner.start();
  ros::waitForShutdown();
  return 0;
}

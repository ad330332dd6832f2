#pragma once
// aco-ros-planner's ROS half: it keeps the latest map of the `map` topic (nav_msgs/OccupancyGrid),
// answers nav_msgs/GetPlan on `make_plan` with the planning half (planner_core.hpp: the same
// planning request as acoplan and Python) and publishes each plan on `plan` (nav_msgs/Path) and,
// with ~publish_pheromone, the pheromone on `pheromone`. Its private parameters are acoplan's keys
// (README.md), read at every request.
#include <mutex>

#include <nav_msgs/GetPlan.h>
#include <nav_msgs/OccupancyGrid.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>

#include "planner_core.hpp"

namespace aco_ros {

class RosPlanner {
 public:
  // `node` names the topics and the service, `params` is the private namespace (~).
  RosPlanner(ros::NodeHandle node, ros::NodeHandle params);

 private:
  void on_map(const nav_msgs::OccupancyGrid::ConstPtr& map);
  // Always true: an impossible request is an empty plan and a ROS error naming the reason.
  bool make_plan(nav_msgs::GetPlan::Request& request, nav_msgs::GetPlan::Response& response);
  nav_msgs::Path plan(const nav_msgs::GetPlan::Request& request, const nav_msgs::OccupancyGrid& map);

  ros::NodeHandle node_;
  ros::NodeHandle params_;
  Planner planner_;
  std::mutex map_mutex_;  // guards map_: a new map replaces the old between requests
  nav_msgs::OccupancyGrid::ConstPtr map_;
  ros::Subscriber map_subscriber_;
  ros::Publisher plan_publisher_;
  ros::Publisher pheromone_publisher_;
  // Requests are planned one at a time on a thread of their own, in the order they came: the map
  // and the other callbacks (the global queue) are answered meanwhile.
  ros::CallbackQueue plan_queue_;
  ros::AsyncSpinner plan_spinner_{1, &plan_queue_};
  ros::ServiceServer make_plan_service_;
};

}  // namespace aco_ros

#include "ros_planner.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <geometry_msgs/PoseStamped.h>
#include <nav_msgs/Path.h>

namespace aco_ros {
namespace {

std::string text_of(const std::string& name, XmlRpc::XmlRpcValue& value) {
  switch (value.getType()) {
    case XmlRpc::XmlRpcValue::TypeBoolean:
      return static_cast<bool>(value) ? "true" : "false";
    case XmlRpc::XmlRpcValue::TypeInt:
      return std::to_string(static_cast<int>(value));
    case XmlRpc::XmlRpcValue::TypeDouble: {
      char digits[32];
      const auto end = std::to_chars(digits, digits + sizeof digits, static_cast<double>(value)).ptr;
      return std::string(digits, end);  // the shortest text that reads back as the same double
    }
    case XmlRpc::XmlRpcValue::TypeString:
      return static_cast<std::string>(value);
    default:
      throw std::runtime_error("~" + name + " must be a number, a boolean or a text");
  }
}

Settings read_settings(const ros::NodeHandle& params) {
  Settings s;
  std::vector<std::string> names;
  ros::param::getParamNames(names);
  const std::string prefix = params.getNamespace() + "/";
  for (const std::string& full : names) {
    if (full.rfind(prefix, 0) != 0) continue;
    const std::string name = full.substr(prefix.size());
    XmlRpc::XmlRpcValue value;
    if (!params.getParam(name, value)) continue;  // deleted meanwhile
    const std::string text = text_of(name, value);
    const bool is_int = value.getType() == XmlRpc::XmlRpcValue::TypeInt;
    const bool is_bool = value.getType() == XmlRpc::XmlRpcValue::TypeBoolean;
    if (name == "occupied_threshold") {
      if (!is_int || static_cast<int>(value) < 0 || static_cast<int>(value) > 100)
        throw std::runtime_error("~occupied_threshold must be a whole number from 0 to 100 (an occupancy), not " +
                                 text);
      s.occupied_threshold = static_cast<int>(value);
    } else if (name == "allow_unknown" || name == "publish_pheromone") {
      if (!is_bool) throw std::runtime_error("~" + name + " must be true or false, not " + text);
      (name == "allow_unknown" ? s.allow_unknown : s.publish_pheromone) = static_cast<bool>(value);
    } else if (name == "threads") {
      if (!is_int || static_cast<int>(value) < 0)
        throw std::runtime_error("~threads must be a whole number >= 0 (0: all cores), not " + text);
      s.threads = static_cast<int>(value);
    } else if (name == "preset" || name == "config") {
      (name == "preset" ? s.preset : s.config) = text;
    } else if (std::count(name.begin(), name.end(), '/') > 1) {
      throw std::runtime_error("~" + name +
                               " is not a parameter of the planner (a run key is ~KEY or ~SLOT/PARAMETER)");
    } else {
      const std::string key = run_key(name);
      for (const char* given : {"map", "scen", "scen-index", "start", "goal"})
        if (key == given)
          throw std::runtime_error("~" + name + ": the map comes on the map topic, start and goal with each request");
      s.keys[key] = text;
    }
  }
  return s;
}

void check_frame(const std::string& what, const std::string& frame, const std::string& map_frame) {
  const auto bare = [](const std::string& f) { return f.empty() || f.front() != '/' ? f : f.substr(1); };
  if (!frame.empty() && bare(frame) != bare(map_frame))
    throw std::runtime_error(what + " is in frame '" + frame + "', the map in '" + map_frame +
                             "': give poses in the map's frame (the planner does not transform them)");
}

geometry_msgs::Quaternion facing(double heading) {  // a turn about z
  geometry_msgs::Quaternion q;
  q.z = std::sin(heading / 2);
  q.w = std::cos(heading / 2);
  return q;
}

}  // namespace

RosPlanner::RosPlanner(ros::NodeHandle node, ros::NodeHandle params) : node_(node), params_(params) {
  map_subscriber_ = node_.subscribe("map", 1, &RosPlanner::on_map, this);
  plan_publisher_ = node_.advertise<nav_msgs::Path>("plan", 1, true);
  pheromone_publisher_ = node_.advertise<nav_msgs::OccupancyGrid>("pheromone", 1, true);
  ros::NodeHandle planning(node_);
  planning.setCallbackQueue(&plan_queue_);
  make_plan_service_ = planning.advertiseService("make_plan", &RosPlanner::make_plan, this);
  plan_spinner_.start();
}

void RosPlanner::on_map(const nav_msgs::OccupancyGrid::ConstPtr& map) {
  const auto& info = map->info;
  const auto& q = info.origin.orientation;
  const double yaw = std::atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z));
  std::string fault;
  if (info.width == 0 || info.height == 0)
    fault = "it is empty";
  else if (map->data.size() != std::size_t(info.width) * info.height)
    fault = "it has " + std::to_string(map->data.size()) + " cells for " + std::to_string(info.width) + "x" +
            std::to_string(info.height);
  else if (!(info.resolution > 0) || !std::isfinite(info.resolution))
    fault = "its resolution is " + std::to_string(info.resolution) + " m per cell";
  else if (std::abs(yaw) > 1e-9 || std::abs(q.x) + std::abs(q.y) > 1e-9)
    fault =
        "its origin is turned (yaw " + std::to_string(yaw) + " rad): the planner takes maps aligned with their frame";
  if (!fault.empty()) {
    ROS_ERROR("aco planner: map on %s refused: %s; the previous map stays", map_subscriber_.getTopic().c_str(),
              fault.c_str());
    return;
  }
  const std::lock_guard<std::mutex> lock(map_mutex_);
  map_ = map;
  ROS_INFO("aco planner: map %ux%u at %g m per cell in frame '%s'", info.width, info.height, info.resolution,
           map->header.frame_id.c_str());
}

bool RosPlanner::make_plan(nav_msgs::GetPlan::Request& request, nav_msgs::GetPlan::Response& response) {
  nav_msgs::OccupancyGrid::ConstPtr map;
  {
    const std::lock_guard<std::mutex> lock(map_mutex_);
    map = map_;
  }
  try {
    if (!map) throw std::runtime_error("no map yet: nothing has come on " + map_subscriber_.getTopic());
    response.plan = plan(request, *map);
    plan_publisher_.publish(response.plan);
  } catch (const std::exception& error) {
    response.plan = nav_msgs::Path();
    response.plan.header.stamp = ros::Time::now();
    if (map) response.plan.header.frame_id = map->header.frame_id;
    ROS_ERROR("aco planner: make_plan: %s", error.what());
  }
  return true;
}

nav_msgs::Path RosPlanner::plan(const nav_msgs::GetPlan::Request& request, const nav_msgs::OccupancyGrid& map) {
  const Settings settings = read_settings(params_);
  check_frame("the start", request.start.header.frame_id, map.header.frame_id);
  check_frame("the goal", request.goal.header.frame_id, map.header.frame_id);
  GridMap grid;
  grid.frame = map.header.frame_id;
  grid.width = map.info.width;
  grid.height = map.info.height;
  grid.resolution = map.info.resolution;
  grid.origin_x = map.info.origin.position.x;
  grid.origin_y = map.info.origin.position.y;
  grid.occupancy = map.data;
  const auto& from = request.start.pose.position;
  const auto& to = request.goal.pose.position;
  const Plan planned = planner_.plan(grid, {from.x, from.y}, {to.x, to.y}, request.tolerance, settings);

  nav_msgs::Path path;
  path.header.frame_id = map.header.frame_id;
  path.header.stamp = ros::Time::now();
  for (std::size_t i = 0; i < planned.points.size(); ++i) {
    geometry_msgs::PoseStamped pose;
    pose.header = path.header;
    const Point p = planned.points[i];
    pose.pose.position.x = p.x;
    pose.pose.position.y = p.y;
    // Facing the next point; the last takes the goal's orientation.
    pose.pose.orientation = i + 1 < planned.points.size()
                                ? facing(std::atan2(planned.points[i + 1].y - p.y, planned.points[i + 1].x - p.x))
                                : request.goal.pose.orientation;
    path.poses.push_back(pose);
  }
  ROS_INFO("aco planner: %zu poses, %.3f m, in %.1f ms", path.poses.size(), planned.length, planned.time_ms);
  if (!planned.pheromone.empty()) {
    nav_msgs::OccupancyGrid field;
    field.header = path.header;
    field.info = map.info;
    field.data = planned.pheromone;
    pheromone_publisher_.publish(field);
  }
  return path;
}

}  // namespace aco_ros

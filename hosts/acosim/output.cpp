// What a simulation leaves behind: a JSON summary with the trajectory, a CSV of the trajectory,
// and an SVG of the map, the plans, the driven trajectory and the moving obstacles' tracks.
#include <nlohmann/json.hpp>
#include <sstream>

#include "aco/map_io.hpp"
#include "aco/svg.hpp"
#include "simulation.hpp"

namespace acosim {

std::string summary_json(const Scenario& scenario, const SimulationResult& r) {
  nlohmann::json j;
  j["scenario"] = scenario.file.string();
  j["reached"] = r.reached;
  j["outcome"] = r.outcome;
  if (!r.reason.empty()) j["reason"] = r.reason;
  j["time"] = r.time;
  j["distance"] = r.distance;
  j["min_clearance"] = std::isfinite(r.min_clearance) ? nlohmann::json(r.min_clearance) : nlohmann::json();
  j["collisions"] = r.collisions;
  j["replans"] = r.replans;
  j["steps"] = r.steps;
  j["config"] = nlohmann::json::parse(aco::to_json(scenario.run));
  for (const auto& plan : r.plans) {
    nlohmann::json points = nlohmann::json::array();
    for (const auto& p : plan) points.push_back({p.x(), p.y()});
    j["plans"].push_back(points);
  }
  j["sensed"] = nlohmann::json::array();
  for (const aco::Cell& c : r.sensed) j["sensed"].push_back({c.x, c.y});
  for (const Frame& f : r.frames) {
    nlohmann::json moving = nlohmann::json::array();
    for (const auto& m : f.moving) moving.push_back({m.x(), m.y()});
    j["trajectory"].push_back({{"t", f.t}, {"x", f.robot.x}, {"y", f.robot.y}, {"heading", f.robot.heading},
                               {"v", f.robot.v}, {"w", f.robot.w}, {"plan", f.plan}, {"goal_index", f.goal_index},
                               {"moving", moving}});
  }
  return j.dump();
}

std::string trajectory_csv(const SimulationResult& r) {
  std::ostringstream out;
  out.precision(10);
  out << "t,x,y,heading,v,w,plan,goal_index\n";
  for (const Frame& f : r.frames)
    out << f.t << "," << f.robot.x << "," << f.robot.y << "," << f.robot.heading << "," << f.robot.v << "," << f.robot.w << ","
        << f.plan << "," << f.goal_index << "\n";
  return out.str();
}

std::string render_svg(const Scenario& scenario, const SimulationResult& r) {
  const aco::LoadedProblem problem = aco::load_problem(scenario.run.problem);
  const aco::Map& map = *problem.map;
  const double cell = 24.0, pad = 12.0;
  const auto X = [&](double x) { return pad + (x + 0.5) * cell; };
  const auto Y = [&](double y) { return pad + (y + 0.5) * cell; };
  std::ostringstream s;
  s.precision(6);
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << 2 * pad + map.width() * cell << "\" height=\""
    << 2 * pad + map.height() * cell + 24 << "\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  for (int y = 0; y < map.height(); ++y)
    for (int x = 0; x < map.width(); ++x)
      if (!map.passable({x, y}))
        s << "<rect x=\"" << pad + x * cell << "\" y=\"" << pad + y * cell << "\" width=\"" << cell << "\" height=\"" << cell
          << "\" fill=\"#444\"/>\n";
  for (const aco::Cell& c : scenario.unknown)
    s << "<rect class=\"unknown\" x=\"" << pad + c.x * cell << "\" y=\"" << pad + c.y * cell << "\" width=\"" << cell
      << "\" height=\"" << cell << "\" fill=\"#c0392b\" fill-opacity=\"0.7\"/>\n";
  const auto polyline = [&](const std::vector<Eigen::Vector2d>& points, const char* style) {
    s << "<polyline fill=\"none\" " << style << " points=\"";
    for (const auto& p : points) s << X(p.x()) << "," << Y(p.y()) << " ";
    s << "\"/>\n";
  };
  for (std::size_t i = 0; i < r.plans.size(); ++i)
    polyline(r.plans[i], i == 0 ? "class=\"plan\" stroke=\"#2471a3\" stroke-width=\"2\" stroke-dasharray=\"6,4\""
                                : "class=\"plan\" stroke=\"#8e44ad\" stroke-width=\"2\" stroke-dasharray=\"6,4\"");
  for (std::size_t k = 0; k < scenario.moving.size(); ++k) {
    std::vector<Eigen::Vector2d> track;
    for (const Frame& f : r.frames) track.push_back(f.moving[k]);
    polyline(track, "class=\"moving\" stroke=\"#e67e22\" stroke-width=\"1.5\"");
  }
  std::vector<Eigen::Vector2d> driven;
  for (const Frame& f : r.frames) driven.push_back(f.robot.position());
  polyline(driven, "class=\"trajectory\" stroke=\"#27ae60\" stroke-width=\"2.5\"");
  s << "<text x=\"" << pad << "\" y=\"" << 2 * pad + map.height() * cell + 12 << "\" font-family=\"sans-serif\" font-size=\"13\">"
    << aco::xml_escape(r.outcome + (r.reason.empty() ? "" : ": " + r.reason)) << "; time " << r.time << " s, "
    << r.replans << " replans</text>\n</svg>\n";
  return s.str();
}

}  // namespace acosim

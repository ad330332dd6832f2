// What a simulation leaves behind: a JSON summary with the trajectory, a CSV of the trajectory,
// and an SVG of the map, the plans, the driven trajectory and the moving obstacles' tracks.
#include <nlohmann/json.hpp>
#include <sstream>

#include "aco/map_io.hpp"
#include "aco/svg.hpp"
#include "aco/simulation/simulation.hpp"

namespace acosim {

std::string summary_json(const Scenario& scenario, const SimulationResult& r, const aco::PluginRegistry& registry) {
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
  j["plugins"] = nlohmann::json::parse(aco::plugins_json(scenario.run, registry));
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

namespace {

constexpr double kCell = 24.0, kPad = 12.0;  // pixels per map unit, margin
double px(double x) { return kPad + (x + 0.5) * kCell; }

// The picture: the map, unknown cells, every plan, each moving obstacle's track, the driven
// trajectory and the outcome line. The player adds the robot and the discs on top.
std::string picture(const Scenario& scenario, const SimulationResult& r, const std::string& extra) {
  const aco::Map& map = *scenario.map;
  std::ostringstream s;
  s.precision(6);
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" id=\"world\" width=\"" << 2 * kPad + map.width() * kCell << "\" height=\""
    << 2 * kPad + map.height() * kCell + 24 << "\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  const auto square = [&](aco::Cell c, const char* attributes) {
    s << "<rect " << attributes << " x=\"" << kPad + c.x * kCell << "\" y=\"" << kPad + c.y * kCell << "\" width=\"" << kCell
      << "\" height=\"" << kCell << "\"/>\n";
  };
  for (int y = 0; y < map.height(); ++y)
    for (int x = 0; x < map.width(); ++x)
      if (!map.passable({x, y})) square({x, y}, "fill=\"#444\"");
  for (const aco::Cell& c : scenario.unknown) square(c, "class=\"unknown\" fill=\"#c0392b\" fill-opacity=\"0.7\"");
  const auto polyline = [&](const std::vector<Eigen::Vector2d>& points, const char* attributes) {
    s << "<polyline fill=\"none\" " << attributes << " points=\"";
    for (const auto& p : points) s << px(p.x()) << "," << px(p.y()) << " ";
    s << "\"/>\n";
  };
  for (std::size_t i = 0; i < r.plans.size(); ++i)
    polyline(r.plans[i], i == 0 ? "class=\"plan\" stroke=\"#2471a3\" stroke-width=\"2\" stroke-dasharray=\"6,4\""
                                : "class=\"plan\" stroke=\"#8e44ad\" stroke-width=\"2\" stroke-dasharray=\"6,4\"");
  for (std::size_t k = 0; k < scenario.moving.size(); ++k) {
    std::vector<Eigen::Vector2d> track;
    for (const Frame& f : r.frames) track.push_back(f.moving[k]);
    polyline(track, "class=\"moving\" stroke=\"#e67e22\" stroke-width=\"1.5\" stroke-opacity=\"0.6\"");
  }
  std::vector<Eigen::Vector2d> driven;
  for (const Frame& f : r.frames) driven.push_back(f.robot.position());
  polyline(driven, "class=\"trajectory\" id=\"trajectory\" stroke=\"#27ae60\" stroke-width=\"2.5\"");
  s << extra;
  s << "<text x=\"" << kPad << "\" y=\"" << 2 * kPad + map.height() * kCell + 12 << "\" font-family=\"sans-serif\" font-size=\"13\">"
    << aco::xml_escape(r.outcome + (r.reason.empty() ? "" : ": " + r.reason)) << "; time " << r.time << " s, " << r.replans
    << " replans</text>\n</svg>\n";
  return s.str();
}

}  // namespace

std::string render_svg(const Scenario& scenario, const SimulationResult& r) { return picture(scenario, r, ""); }

// The player: the picture with the robot (disc and heading) and the moving discs drawn at one
// frame, a play/pause button and a time slider. Frames are inline data; no network. Opened
// with #final it shows the last frame at once.
std::string render_html(const Scenario& scenario, const SimulationResult& r) {
  const double radius = scenario.robot.radius * kCell;
  std::ostringstream robot;
  robot << "<g id=\"robot\"><circle id=\"robot-body\" r=\"" << radius << "\" fill=\"#27ae60\" fill-opacity=\"0.8\"/>"
        << "<line id=\"robot-heading\" stroke=\"black\" stroke-width=\"2\"/></g>\n";
  for (std::size_t k = 0; k < scenario.moving.size(); ++k)
    robot << "<circle class=\"disc\" r=\"" << scenario.moving[k].radius * kCell << "\" fill=\"#e67e22\"/>\n";
  nlohmann::json frames = nlohmann::json::array();
  for (const Frame& f : r.frames) {
    nlohmann::json row = {f.t, px(f.robot.x), px(f.robot.y), f.robot.heading, f.robot.v};
    for (const auto& m : f.moving) row.push_back(px(m.x())), row.push_back(px(m.y()));
    frames.push_back(row);
  }
  std::ostringstream html;
  html << "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>acosim: " << aco::xml_escape(scenario.file.filename().string())
       << "</title>\n<style>body{font-family:sans-serif;margin:16px} #controls{margin:8px 0} #slider{width:420px}</style>\n"
       << "</head><body>\n<h1>acosim: " << aco::xml_escape(scenario.file.string()) << "</h1>\n<p>" << aco::xml_escape(r.outcome)
       << (r.reason.empty() ? "" : ": " + aco::xml_escape(r.reason)) << "; " << r.time << " s, " << r.distance << " driven, "
       << r.replans << " replans, local planner " << aco::xml_escape(scenario.run.pipeline.at("local").plugin) << "</p>\n"
       << "<div id=\"controls\"><button id=\"play\">play</button> <input id=\"slider\" type=\"range\" min=\"0\" max=\""
       << r.frames.size() - 1 << "\" value=\"0\"> <span id=\"time\">0 s</span> <span id=\"speed\"></span></div>\n"
       << picture(scenario, r, robot.str()) << "<script>\nconst frames = " << frames.dump() << ";\nconst radius = " << radius << ";\n"
       << R"JS(const slider = document.getElementById('slider'), play = document.getElementById('play');
const body = document.getElementById('robot-body'), heading = document.getElementById('robot-heading');
const discs = document.querySelectorAll('.disc');
const trajectory = document.getElementById('trajectory'), full = trajectory.getAttribute('points').trim().split(' ');
let timer = null;
function show(i) {
  const f = frames[i];
  body.setAttribute('cx', f[1]); body.setAttribute('cy', f[2]);
  heading.setAttribute('x1', f[1]); heading.setAttribute('y1', f[2]);
  heading.setAttribute('x2', f[1] + 1.6 * radius * Math.cos(f[3])); heading.setAttribute('y2', f[2] + 1.6 * radius * Math.sin(f[3]));
  discs.forEach((d, k) => { d.setAttribute('cx', f[5 + 2 * k]); d.setAttribute('cy', f[6 + 2 * k]); });
  trajectory.setAttribute('points', full.slice(0, i + 1).join(' '));
  document.getElementById('time').textContent = (Math.round(f[0] * 10) / 10) + ' s';
  document.getElementById('speed').textContent = 'v ' + f[4].toFixed(2);
  slider.value = i;
}
function stop() { clearInterval(timer); timer = null; play.textContent = 'play'; }
play.onclick = () => {
  if (timer) return stop();
  if (+slider.value >= frames.length - 1) show(0);
  play.textContent = 'pause';
  timer = setInterval(() => { const i = +slider.value + 1; if (i >= frames.length) return stop(); show(i); }, 25);
};
slider.oninput = () => { stop(); show(+slider.value); };
show(location.hash === '#final' ? frames.length - 1 : 0);
</script>
</body></html>
)JS";
  return html.str();
}

}  // namespace acosim

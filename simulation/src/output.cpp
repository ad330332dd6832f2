// What a simulation leaves behind: a JSON summary with the trajectory, a CSV of the trajectory,
// and an SVG of the map, the plans, the driven trajectory and the moving obstacles' tracks.
#include <nlohmann/json.hpp>
#include <algorithm>
#include <sstream>

#include "aco/engine/map_io.hpp"
#include "aco/drawing/svg.hpp"
#include "aco/simulation/simulation.hpp"

namespace aco::simulation {

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
    j["trajectory"].push_back({{"t", f.t},
                               {"x", f.robot.x},
                               {"y", f.robot.y},
                               {"heading", f.robot.heading},
                               {"v", f.robot.v},
                               {"w", f.robot.w},
                               {"plan", f.plan},
                               {"goal_index", f.goal_index},
                               {"moving", moving}});
  }
  return j.dump();
}

std::string trajectory_csv(const SimulationResult& r) {
  std::ostringstream out;
  out.precision(10);
  out << "t,x,y,heading,v,w,plan,goal_index\n";
  for (const Frame& f : r.frames)
    out << f.t << "," << f.robot.x << "," << f.robot.y << "," << f.robot.heading << "," << f.robot.v << "," << f.robot.w
        << "," << f.plan << "," << f.goal_index << "\n";
  return out.str();
}

namespace {

constexpr double kCell = 24.0, kPad = 12.0;  // pixels per map unit, margin
constexpr double kLegendGap = 24.0, kLegendRow = 22.0, kSwatch = 28.0;  // the legend beside the map
constexpr double kFontSize = 13.0;
double px(double x) { return kPad + (x + 0.5) * kCell; }

// The line styles, shared by the drawing and its legend.
constexpr const char* kFirstPlanStyle = "stroke=\"#2471a3\" stroke-width=\"2\" stroke-dasharray=\"6,4\"";
constexpr const char* kReplanStyle = "stroke=\"#8e44ad\" stroke-width=\"2\" stroke-dasharray=\"6,4\"";
constexpr const char* kTrackStyle = "stroke=\"#e67e22\" stroke-width=\"1.5\" stroke-opacity=\"0.6\"";
constexpr const char* kTrajectoryStyle = "stroke=\"#27ae60\" stroke-width=\"2.5\"";
constexpr const char* kObstacleFill = "fill=\"#444\"";
constexpr const char* kUnknownFill = "fill=\"#c0392b\" fill-opacity=\"0.7\"";
constexpr const char* kMovingFill = "fill=\"#e67e22\" fill-opacity=\"0.55\" stroke=\"#e67e22\"";

// The start marker (a ring) and the goal marker (a bull's eye), centred on (x, y).
std::string start_mark(double x, double y) {
  std::ostringstream s;
  s << "<circle cx=\"" << x << "\" cy=\"" << y << "\" r=\"7\" fill=\"#fff\" stroke=\"#000\" stroke-width=\"2.5\"/>";
  return s.str();
}
std::string goal_mark(double x, double y) {
  std::ostringstream s;
  s << "<circle cx=\"" << x << "\" cy=\"" << y
    << "\" r=\"7\" fill=\"#fff\" stroke=\"#000\" stroke-width=\"2.5\"/><circle cx=\"" << x << "\" cy=\"" << y
    << "\" r=\"3\" fill=\"#000\"/>";
  return s.str();
}
// A cross where the robot touched an obstacle: black on a white outline, to stand out on the red
// of an unknown cell as on the dark grey of a known one.
std::string collision_mark(double x, double y) {
  std::ostringstream cross;
  cross << "M" << x - 7 << ',' << y - 7 << "L" << x + 7 << ',' << y + 7 << "M" << x - 7 << ',' << y + 7 << "L" << x + 7
        << ',' << y - 7;
  return "<path d=\"" + cross.str() + "\" stroke=\"#fff\" stroke-width=\"6\"/><path d=\"" + cross.str() +
         "\" stroke=\"#000\" stroke-width=\"3\"/>";
}

// A marker with its word beside it: above and to the right, unless that would leave the map;
// the white outline keeps the word legible over lines and obstacles.
void labelled_mark(std::ostream& s, const char* id, const std::string& mark, const char* word, double x, double y,
                   double map_right) {
  const bool left = x + 10 + aco::text_width(word, kFontSize) > map_right;
  const bool below = y - 8 - kFontSize < kPad;
  s << "<g id=\"" << id << "\">" << mark << "<text x=\"" << (left ? x - 10 : x + 10) << "\" y=\""
    << (below ? y + 8 + kFontSize : y - 8) << "\" text-anchor=\"" << (left ? "end" : "start")
    << "\" font-family=\"sans-serif\" font-size=\"" << kFontSize
    << "\" font-weight=\"bold\" stroke=\"#fff\" stroke-width=\"3\" paint-order=\"stroke\">" << word << "</text></g>\n";
}

struct LegendEntry {
  std::string swatch;  // drawn in a kSwatch x kSwatch box whose top left corner is (0, 0)
  std::string text;
};

// Every kind of line and mark the picture holds, in one column.
std::vector<LegendEntry> legend_entries(const Scenario& scenario, const SimulationResult& r, bool moving_discs) {
  const std::string line = "<line x1=\"2\" x2=\"26\" y1=\"7\" y2=\"7\" ";
  const std::string cell = "<rect x=\"7\" y=\"0\" width=\"14\" height=\"14\" ";
  std::vector<LegendEntry> entries{
      {start_mark(14, 7), "start"}, {goal_mark(14, 7), "goal"}, {cell + kObstacleFill + "/>", "obstacle on the map"}};
  if (!scenario.unknown.empty()) entries.push_back({cell + kUnknownFill + "/>", "obstacle the map did not show"});
  if (!r.plans.empty()) entries.push_back({line + kFirstPlanStyle + "/>", "planned path"});
  if (r.plans.size() > 1)
    entries.push_back({line + kReplanStyle + "/>", "replanned path" + std::string(r.plans.size() > 2 ? "s" : "") +
                                                       " (" + std::to_string(r.plans.size() - 1) + ")"});
  if (!scenario.moving.empty()) {
    entries.push_back({line + kTrackStyle + "/>", "moving obstacle's track"});
    if (moving_discs)
      entries.push_back(
          {"<circle cx=\"14\" cy=\"7\" r=\"6\" " + std::string(kMovingFill) + "/>", "moving obstacle at the end"});
  }
  entries.push_back({line + kTrajectoryStyle + "/>", "driven trajectory"});
  if (r.collisions > 0) entries.push_back({collision_mark(14, 7), "collision"});
  return entries;
}

double legend_width(const std::vector<LegendEntry>& entries) {
  double widest = 0.0;
  for (const auto& entry : entries) widest = std::max(widest, aco::text_width(entry.text, kFontSize));
  return kSwatch + 8 + widest;
}

void draw_legend(std::ostream& s, const std::vector<LegendEntry>& entries, double left, double top) {
  s << "<g id=\"legend\" class=\"legend\" transform=\"translate(" << left << ',' << top
    << ")\" font-family=\"sans-serif\" font-size=\"" << kFontSize << "\">\n";
  for (std::size_t i = 0; i < entries.size(); ++i)
    s << "<g class=\"legend-entry\" transform=\"translate(0," << double(i) * kLegendRow << ")\">" << entries[i].swatch
      << "<text x=\"" << kSwatch + 8 << "\" y=\"12\">" << aco::xml_escape(entries[i].text) << "</text></g>\n";
  s << "</g>\n";
}

// The picture: the map, unknown cells, every plan, each moving obstacle's track, the driven
// trajectory, start and goal, the outcome line below and the legend beside the map. The
// player adds the robot and the discs on top (`extra`); the still picture draws the discs where
// they were at the end (`moving_discs`).
std::string picture(const Scenario& scenario, const SimulationResult& r, const std::string& extra, bool moving_discs) {
  const aco::Map& map = *scenario.map;
  const double map_right = kPad + map.width() * kCell, map_bottom = kPad + map.height() * kCell;
  std::ostringstream summary;
  summary.precision(6);
  summary << r.outcome << (r.reason.empty() ? "" : ": " + r.reason) << "; time " << r.time << " s, " << r.replans
          << " replans";
  const std::string outcome = summary.str();
  const auto entries = legend_entries(scenario, r, moving_discs);
  const double legend_left = map_right + kLegendGap;
  const double width = std::max(legend_left + legend_width(entries), kPad + aco::text_width(outcome, kFontSize)) + kPad;
  const double height = std::max(map_bottom + 24, kPad + double(entries.size()) * kLegendRow) + kPad;
  std::ostringstream s;
  s.precision(6);
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" id=\"world\" width=\"" << width << "\" height=\"" << height
    << "\" viewBox=\"0 0 " << width << ' ' << height << "\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  s << "<rect x=\"" << kPad << "\" y=\"" << kPad << "\" width=\"" << map.width() * kCell << "\" height=\""
    << map.height() * kCell << "\" fill=\"none\" stroke=\"#888\"/>\n";
  // Obstacle cells merged into horizontal runs, drawn with crisp edges: no seams between them.
  s << "<g id=\"obstacles\" " << kObstacleFill << " shape-rendering=\"crispEdges\">\n";
  for (int y = 0; y < map.height(); ++y)
    for (int x = 0; x < map.width();) {
      int end = x;
      while (end < map.width() && !map.passable({end, y})) ++end;
      if (end > x)
        s << "<rect x=\"" << kPad + x * kCell << "\" y=\"" << kPad + y * kCell << "\" width=\"" << (end - x) * kCell
          << "\" height=\"" << kCell << "\"/>\n";
      x = std::max(end, x + 1);
    }
  s << "</g>\n<g id=\"unknown\" " << kUnknownFill << " shape-rendering=\"crispEdges\">\n";
  for (const aco::Cell& c : scenario.unknown)
    s << "<rect class=\"unknown\" x=\"" << kPad + c.x * kCell << "\" y=\"" << kPad + c.y * kCell << "\" width=\""
      << kCell << "\" height=\"" << kCell << "\"/>\n";
  s << "</g>\n";
  const auto polyline = [&](const std::vector<Eigen::Vector2d>& points, const std::string& attributes) {
    s << "<polyline fill=\"none\" " << attributes << " points=\"";
    for (const auto& p : points) s << px(p.x()) << "," << px(p.y()) << " ";
    s << "\"/>\n";
  };
  for (std::size_t i = 0; i < r.plans.size(); ++i)
    polyline(r.plans[i], std::string("class=\"plan\" ") + (i == 0 ? kFirstPlanStyle : kReplanStyle));
  for (std::size_t k = 0; k < scenario.moving.size(); ++k) {
    std::vector<Eigen::Vector2d> track;
    for (const Frame& f : r.frames) track.push_back(f.moving[k]);
    polyline(track, std::string("class=\"moving\" ") + kTrackStyle);
  }
  std::vector<Eigen::Vector2d> driven;
  for (const Frame& f : r.frames) driven.push_back(f.robot.position());
  polyline(driven, std::string("class=\"trajectory\" id=\"trajectory\" ") + kTrajectoryStyle);
  if (moving_discs && !r.frames.empty())
    for (std::size_t k = 0; k < scenario.moving.size(); ++k) {
      const Eigen::Vector2d& at = r.frames.back().moving[k];
      s << "<circle class=\"moving-end\" cx=\"" << px(at.x()) << "\" cy=\"" << px(at.y()) << "\" r=\""
        << scenario.moving[k].radius * kCell << "\" " << kMovingFill << "/>\n";
    }
  labelled_mark(s, "start", start_mark(px(scenario.start.x), px(scenario.start.y)), "start", px(scenario.start.x),
                px(scenario.start.y), map_right);
  labelled_mark(s, "goal", goal_mark(px(scenario.goal.x), px(scenario.goal.y)), "goal", px(scenario.goal.x),
                px(scenario.goal.y), map_right);
  if (r.collisions > 0 && !r.frames.empty()) {
    const auto& robot = r.frames.back().robot;
    s << "<g id=\"collision\">" << collision_mark(px(robot.x), px(robot.y)) << "</g>\n";
  }
  s << extra;
  draw_legend(s, entries, legend_left, kPad);
  s << "<text id=\"outcome\" x=\"" << kPad << "\" y=\"" << map_bottom + 18
    << "\" font-family=\"sans-serif\" font-size=\"" << kFontSize << "\">" << aco::xml_escape(outcome)
    << "</text>\n</svg>\n";
  return s.str();
}

}  // namespace

std::string render_svg(const Scenario& scenario, const SimulationResult& r) { return picture(scenario, r, "", true); }

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
  html << "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>acosim: "
       << aco::xml_escape(scenario.file.filename().string())
       << "</title>\n<style>body{font-family:sans-serif;margin:16px} #controls{margin:8px 0} "
          "#slider{width:420px}</style>\n"
       << "</head><body>\n<h1>acosim: " << aco::xml_escape(scenario.file.string()) << "</h1>\n<p>"
       << aco::xml_escape(r.outcome) << (r.reason.empty() ? "" : ": " + aco::xml_escape(r.reason)) << "; " << r.time
       << " s, " << r.distance << " driven, " << r.replans << " replans, local planner "
       << aco::xml_escape(scenario.run.pipeline.at("local").plugin) << "</p>\n"
       << "<div id=\"controls\"><button id=\"play\">play</button> <input id=\"slider\" type=\"range\" min=\"0\" max=\""
       << r.frames.size() - 1 << "\" value=\"0\"> <span id=\"time\">0 s</span> <span id=\"speed\"></span></div>\n"
       << picture(scenario, r, robot.str(), false) << "<script>\nconst frames = " << frames.dump()
       << ";\nconst radius = " << radius << ";\n"
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

}  // namespace aco::simulation

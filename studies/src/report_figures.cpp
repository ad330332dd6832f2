#include "report_figures.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <utility>

#include "aco/planning/run_spec.hpp"
#include "aco/studies/plots.hpp"
#include "report_numbers.hpp"

namespace aco::studies {
namespace {

// The mean best-so-far gap of each configuration's measured runs on problem p, against wall time
// and against walks (log scales, 100 points between the first iteration's end and the last's).
std::vector<Figure> anytime_charts(const Analysis& a, std::size_t p, FigureFiles& files) {
  const double optimal = a.problems[p].optimal_length;
  if (!(optimal > 0)) return {};
  struct Effort {
    const char* file;
    const char* title;
    const char* label;
    std::function<std::vector<double>(const TrialRecord&)> of;
  };
  const Effort efforts[] = {
      {"anytime-time-", "best-so-far gap against time (mean of the runs): ",
       "wall time since the search began, s (log scale)", [](const TrialRecord& t) { return t.elapsed_s; }},
      {"anytime-walks-", "best-so-far gap against walks (mean of the runs): ",
       "walks: candidate paths built (log scale)", [](const TrialRecord& t) { return as_reals(t.walks); }},
  };
  std::vector<Figure> figures;
  for (const Effort& effort : efforts) {
    std::vector<std::pair<int, std::vector<StepCurve>>> by_config;
    double low = INFINITY, high = 0.0;
    for (const Result& r : a.results[p]) {
      std::vector<StepCurve> curves;
      for (const TrialRecord* t : r.runs) {
        if (t->elapsed_s.empty()) continue;
        curves.push_back({effort.of(*t), gap_curve(*t, optimal)});
        low = std::min(low, curves.back().x.front());
        high = std::max(high, curves.back().x.back());
      }
      if (!curves.empty()) by_config.emplace_back(r.config, std::move(curves));
    }
    if (by_config.empty() || !(low > 0)) continue;
    LineChart chart;
    chart.title = effort.title + a.problems[p].name;
    chart.x_label = effort.label;
    chart.y_label = "gap to the optimum %";
    chart.css_class = "anytime";
    chart.log_x = true;
    for (const auto& [config, curves] : by_config) {
      chart.series.push_back(mean_series(a.configs[config].second.name, curves, log_spaced(low, high, 100), true));
      chart.series.back().style = static_cast<std::size_t>(config);
      // No confidence band: early on, while only one or two runs have a path, it spans hundreds of %.
      chart.series.back().band_low.clear();
      chart.series.back().band_high.clear();
    }
    figures.push_back(files.add(effort.file + a.problems[p].name, line_chart_svg(chart)));
  }
  return figures;
}

// The keys of the problem's map as the configuration's trials planned on it: the file, reader and
// map parameters the problem recorded, with the terrain options of the configuration's run
// (max-slope decides which cells of a height map are blocked, cell-size where a path's points lie).
aco::Keys problem_map_keys(const Analysis& a, const ProblemRecord& problem, const ConfigRecord& config) {
  const auto setup = nlohmann::json::parse(problem.setup_json);
  aco::Keys keys{{"map", (a.experiment_dir / setup.at("map").get<std::string>()).string()}};
  if (setup.contains("map-format")) keys["map-format"] = setup.at("map-format").get<std::string>();
  // Held by name: items() of a temporary would dangle in the loop.
  const nlohmann::json map_parameters = setup.value("map-parameters", nlohmann::json::object());
  for (const auto& [name, value] : map_parameters.items()) keys["map." + name] = value.get<std::string>();
  const auto run = nlohmann::json::parse(config.settings_json).value("run", nlohmann::json::object());
  for (const aco::ParamSpec& terrain : aco::problem_parameters())
    if (run.contains(terrain.name) && run.at(terrain.name).is_number())
      keys[terrain.name] = run.at(terrain.name).dump();
  keys.erase("scen-index");
  return keys;
}

// Whether two maps draw alike: the same cells blocked, the same cell size.
bool same_picture(const aco::Map& x, const aco::Map& y) {
  if (x.width() != y.width() || x.height() != y.height() || x.depth() != y.depth() ||
      x.position({1, 0}) != y.position({1, 0}))
    return false;
  for (int row = 0; row < x.height(); ++row)
    for (int column = 0; column < x.width(); ++column)
      if (x.passable({column, row}) != y.passable({column, row})) return false;
  return true;
}

// The problem's map with each configuration's best path: one picture per map the configurations
// planned on (terrain options that block other cells of a height map make another). Each set of
// map keys is loaded once: configurations with the same terrain options share the map.
std::vector<Figure> path_pictures(const Analysis& a, std::size_t p, FigureFiles& files) {
  struct Picture {
    std::vector<aco::Keys> keys;  // every set of map keys that loads a map drawn alike
    std::unique_ptr<aco::Map> map;
    std::vector<MapPath> paths;
  };
  std::vector<Picture> pictures;
  const auto picture_of = [&](const ConfigRecord& config) -> Picture& {
    aco::Keys keys = problem_map_keys(a, a.problems[p], config);
    for (Picture& picture : pictures)
      if (std::find(picture.keys.begin(), picture.keys.end(), keys) != picture.keys.end()) return picture;
    auto map = aco::load_problem_map(aco::resolve_problem(keys, *a.registry), a.registry);
    for (Picture& picture : pictures)
      if (same_picture(*picture.map, *map)) {
        picture.keys.push_back(std::move(keys));
        return picture;
      }
    return pictures.emplace_back(Picture{{std::move(keys)}, std::move(map), {}});
  };
  std::vector<std::pair<const ConfigRecord*, MapPath>> paths;
  for (const Result& r : a.results[p]) {
    if (!r.best) continue;
    MapPath path{
        a.configs[r.config].second.name + " " + fixed(r.best->length, 2), static_cast<std::size_t>(r.config), {}, {}};
    for (const auto& point : nlohmann::json::parse(r.best->path_json)) {
      path.points.push_back({point[0].get<double>(), point[1].get<double>()});
      if (point.size() == 3) path.layers.push_back(point[2].get<double>());
    }
    paths.emplace_back(&a.configs[r.config].second, std::move(path));
  }
  try {
    for (auto& [config, path] : paths) picture_of(*config).paths.push_back(std::move(path));
    // A problem no configuration solved still shows its map.
    if (pictures.empty() && !a.configs.empty()) picture_of(a.configs.front().second);
  } catch (const std::exception& e) {
    return {{"", "", "map not drawn: " + std::string(e.what())}};
  }
  std::vector<Figure> figures;
  for (const Picture& picture : pictures)
    figures.push_back(files.add("paths-" + a.problems[p].name, map_paths_svg(*picture.map, picture.paths)));
  return figures;
}

}  // namespace

Figure FigureFiles::add(const std::string& name, std::string svg) {
  std::string safe;
  for (const char c : name) safe += std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' ? c : '-';
  std::string unique = safe;
  for (int n = 2; !taken_.insert(unique).second; ++n) unique = safe + "-" + std::to_string(n);
  return {unique + ".svg", std::move(svg), ""};
}

std::vector<Figure> ecdf_charts(const Analysis& a, FigureFiles& files) {
  const auto all = reaches(a);
  double low = INFINITY, high = 0.0;
  for (const auto& t : a.trials)
    if (a.problems[t.problem].optimal_length > 0 && !t.elapsed_s.empty() && t.elapsed_s.front() > 0) {
      low = std::min(low, t.elapsed_s.front());
      high = std::max(high, t.elapsed_s.back());
    }
  if (!(high >= low)) return {};
  std::vector<Figure> figures;
  for (std::size_t k = 0; k < kTargets.size(); ++k) {
    LineChart chart;
    chart.title = "runs within " + fixed(kTargets[k], 0) + " % of the optimum, by time (ECDF)";
    chart.x_label = "wall time since the search began, s (log scale)";
    chart.y_label = "share of (problem, run) pairs";
    chart.css_class = "ecdf";
    chart.log_x = chart.steps = true;
    chart.y_range = std::pair(0.0, 1.0);
    for (std::size_t c = 0; c < a.configs.size(); ++c) {
      if (all[c].empty()) continue;
      std::vector<double> hits;
      for (const Reach& r : all[c]) hits.push_back(r.seconds[k]);
      chart.series.push_back(ecdf_series(a.configs[c].second.name, hits, low, high));
      chart.series.back().style = c;
    }
    figures.push_back(files.add("ecdf-" + fixed(kTargets[k], 0) + "pct", line_chart_svg(chart)));
  }
  return figures;
}

std::vector<Figure> problem_figures(const Analysis& a, std::size_t p, FigureFiles& files) {
  const double optimal = a.problems[p].optimal_length;
  const std::string& problem = a.problems[p].name;
  std::vector<Figure> figures;
  BoxPlot box{"final path length: " + problem, "path length", {}, optimal > 0 ? std::optional(optimal) : std::nullopt};
  LineChart chart;
  chart.title = "best-so-far length (mean, 95 % CI): " + problem;
  chart.y_label = "path length";
  if (optimal > 0) chart.reference = optimal;
  for (const auto& r : a.results[p]) {
    const std::string& name = a.configs[r.config].second.name;
    box.samples.push_back({name, r.lengths});
    std::vector<std::vector<double>> curves;
    for (const auto* trial : r.runs)
      if (!trial->best_so_far.empty()) curves.push_back(trial->best_so_far);
    if (!curves.empty()) {
      chart.series.push_back(convergence_series(name, curves));
      chart.series.back().style = static_cast<std::size_t>(r.config);
    }
  }
  figures.push_back(files.add("box-" + problem, box_plot_svg(box)));
  if (!chart.series.empty()) figures.push_back(files.add("convergence-" + problem, line_chart_svg(chart)));
  for (Figure& figure : anytime_charts(a, p, files)) figures.push_back(std::move(figure));
  for (Figure& figure : path_pictures(a, p, files)) figures.push_back(std::move(figure));
  return figures;
}

std::vector<Figure> ablation_charts(const Analysis& a, FigureFiles& files) {
  if (a.ablation_path.empty()) return {};
  Series gaps;
  gaps.name = "mean gap %";
  gaps.value = ablation_gaps(a);
  LineChart chart;
  chart.title = "ablation path: mean gap to the optimum";
  chart.x_label = "step";
  chart.y_label = "gap %";
  chart.series = {gaps};
  return {files.add("ablation", line_chart_svg(chart))};
}

}  // namespace aco::studies

#include "support.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <optional>
#include <queue>
#include <limits>

#include "aco/error.hpp"
#include "aco/engine/map_io.hpp"
#include "aco/drawing/svg.hpp"

extern char** environ;

namespace test {

std::filesystem::path data_dir() { return ACO_TEST_DATA_DIR; }

std::vector<std::string> map1_acoplan_args(const std::string& plugin_dir, const std::vector<std::string>& more) {
  std::vector<std::string> args{"--map",        (data_dir() / "maps/classic20/map1.txt").string(),
                                "--start",      "0,0",
                                "--goal",       "19,19",
                                "--ants",       "10",
                                "--iterations", "6",
                                "--plugin-dir", plugin_dir};
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

aco::OccupancyGrid classic_map(int n) {
  const auto file = data_dir() / "maps/classic20" / ("map" + std::to_string(n) + ".txt");
  std::ifstream in(file);
  return aco::read_matrix_map(in, file.string());
}

RandomProblem random_problem(std::mt19937& rng, int min_size, int max_size) {
  std::uniform_int_distribution<int> size(min_size, max_size);
  const int w = size(rng), h = size(rng);
  RandomProblem p{random_grid(rng, w, h), {}, {}};
  std::uniform_int_distribution<int> px(0, w - 1), py(0, h - 1);
  p.start = {px(rng), py(rng)};
  p.goal = {px(rng), py(rng)};
  p.map.set_blocked(p.start, false);
  p.map.set_blocked(p.goal, false);
  return p;
}

aco::OccupancyGrid random_grid(std::mt19937& rng, int w, int h) {
  std::bernoulli_distribution blocked(std::uniform_real_distribution<double>(0.0, 0.4)(rng));
  aco::OccupancyGrid map(w, h, "random");
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) map.set_blocked({x, y}, blocked(rng));
  return map;
}

aco::Graph build(const aco::Map& map, aco::Neighbourhood n, bool corner_cutting) {
  aco::GraphOptions options;
  options.neighbourhood = n;
  options.corner_cutting = corner_cutting;
  return aco::build_graph(map, options);
}

bool has_edge(const aco::Graph& g, aco::Cell a, aco::Cell b) { return g.find_edge(g.node(a), g.node(b)) >= 0; }

std::vector<std::string> open_grid(int w, int h) { return std::vector<std::string>(h, std::string(w, '.')); }

aco::OccupancyGrid grid(const std::vector<std::string>& rows) {
  aco::OccupancyGrid g(static_cast<int>(rows.front().size()), static_cast<int>(rows.size()), "test grid");
  for (int y = 0; y < g.height(); ++y)
    for (int x = 0; x < g.width(); ++x) g.set_blocked({x, y}, rows[y][x] == '#');
  return g;
}

aco::PluginRegistry& plugins() {
  static aco::PluginRegistry registry({ACO_TEST_PLUGIN_DIR});
  return registry;
}

aco::Context context(const aco::Graph& graph, aco::Cell start, aco::Cell goal, int iteration, int max_iterations) {
  aco::Context c;
  c.graph = &graph;
  c.start = graph.node(start);
  c.goal = graph.node(goal);
  c.ants = 10;
  c.iteration = iteration;
  c.max_iterations = max_iterations;
  c.alpha = 1.0;
  c.beta = 1.0;
  c.seed = 1;
  return c;
}

aco::Ant ant(const aco::Graph& graph, const std::vector<aco::Cell>& cells) {
  aco::Ant a;
  a.arrived = true;
  for (const auto& c : cells) a.nodes.push_back(graph.node(c));
  for (std::size_t i = 1; i < a.nodes.size(); ++i) {
    const aco::EdgeId e = graph.find_edge(a.nodes[i - 1], a.nodes[i]);
    if (e < 0) throw aco::Error("test ant: cells are not neighbours");
    a.edges.push_back(e);
    a.length += graph.cost(e);
  }
  return a;
}

namespace {
std::string slurp(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}
// Every temporary file of this test process lives under one folder, removed at exit.
struct TempRoot {
  std::filesystem::path path = std::filesystem::temp_directory_path() / ("aco_tests_" + std::to_string(::getpid()));
  ~TempRoot() {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
};
std::filesystem::path fresh_dir() {
  static TempRoot root;
  static std::atomic<int> counter{0};
  auto dir = root.path / std::to_string(counter++);
  std::filesystem::create_directories(dir);
  return dir;
}
}  // namespace

namespace {

// Starts argv[0] with argv and the environment plus `env`, its files as `actions` set them; -1 if
// it cannot be started.
pid_t spawn(const std::vector<std::string>& argv, const std::vector<std::string>& env,
            const posix_spawn_file_actions_t& actions) {
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  std::vector<std::string> environment;
  for (char** e = environ; *e; ++e) environment.emplace_back(*e);
  environment.insert(environment.end(), env.begin(), env.end());
  std::vector<char*> envp;
  for (auto& e : environment) envp.push_back(e.data());
  envp.push_back(nullptr);
  pid_t pid = 0;
  return posix_spawn(&pid, args[0], &actions, nullptr, args.data(), envp.data()) == 0 ? pid : -1;
}

}  // namespace

bool reference_voxel_move(const aco::Map& map, aco::Cell a, int dx, int dy, int dz, bool corner_cutting) {
  const aco::Cell b{a.x + dx, a.y + dy, a.z + dz};
  if (!map.passable(a) || !map.passable(b)) return false;
  if (corner_cutting) return true;
  for (int x = std::min(a.x, b.x); x <= std::max(a.x, b.x); ++x)
    for (int y = std::min(a.y, b.y); y <= std::max(a.y, b.y); ++y)
      for (int z = std::min(a.z, b.z); z <= std::max(a.z, b.z); ++z)
        if (!map.passable({x, y, z})) return false;
  return true;
}

std::optional<double> reference_voxel_distance(const aco::Map& map, aco::Cell start, aco::Cell goal,
                                               int neighbourhood) {
  const std::int64_t w = map.width(), h = map.height(), d = map.depth();
  const auto id = [&](aco::Cell c) { return (c.z * h + c.y) * w + c.x; };
  std::vector<double> dist(static_cast<std::size_t>(w * h * d), std::numeric_limits<double>::infinity());
  using Entry = std::pair<double, std::int64_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
  dist[id(start)] = 0.0;
  open.push({0.0, id(start)});
  while (!open.empty()) {
    const auto [g, v] = open.top();
    open.pop();
    if (g > dist[v]) continue;
    const aco::Cell c{int(v % w), int(v / w % h), int(v / (w * h))};
    if (c == goal) return g;
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          const int axes = (dx != 0) + (dy != 0) + (dz != 0);
          if (axes == 0 || (neighbourhood == 6 && axes > 1) || (neighbourhood == 18 && axes > 2)) continue;
          if (!reference_voxel_move(map, c, dx, dy, dz, false)) continue;
          const aco::Cell n{c.x + dx, c.y + dy, c.z + dz};
          const double step = std::sqrt(double(axes));
          if (g + step < dist[id(n)]) {
            dist[id(n)] = g + step;
            open.push({g + step, id(n)});
          }
        }
  }
  return std::nullopt;
}

CommandResult run(const std::vector<std::string>& argv, const std::vector<std::string>& env) {
  const auto dir = fresh_dir();
  const auto out = dir / "stdout", err = dir / "stderr";
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  CommandResult result;
  if (const pid_t pid = spawn(argv, env, actions); pid > 0) {
    int status = 0;
    waitpid(pid, &status, 0);
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  }
  posix_spawn_file_actions_destroy(&actions);
  result.out = slurp(out);
  result.err = slurp(err);
  std::filesystem::remove_all(dir);
  return result;
}

pid_t start(const std::vector<std::string>& argv, const std::filesystem::path& log,
            const std::vector<std::string>& env) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  const pid_t pid = spawn(argv, env, actions);
  posix_spawn_file_actions_destroy(&actions);
  REQUIRE(pid > 0);
  return pid;
}

void check_same_run(const aco::ColonyResult& a, const aco::ColonyResult& b) {
  CHECK(a.path == b.path);
  CHECK(a.length == b.length);  // exact, not approximate
  CHECK(a.best_so_far == b.best_so_far);
  CHECK(a.iteration_best == b.iteration_best);
  CHECK(a.arrived == b.arrived);
  CHECK(a.ant_steps == b.ant_steps);
  CHECK(a.pheromone == b.pheromone);
  CHECK(a.walks == b.walks);
  CHECK(a.corridors == b.corridors);
  CHECK(a.restarts == b.restarts);
}

void check_anytime_curves(const aco::SearchResult& r, std::uint64_t total_walks) {
  REQUIRE(r.elapsed_s.size() == static_cast<std::size_t>(r.iterations));
  REQUIRE(r.walks.size() == static_cast<std::size_t>(r.iterations));
  REQUIRE(r.iterations > 0);
  CHECK(r.elapsed_s.front() >= 0.0);
  for (std::size_t i = 1; i < r.elapsed_s.size(); ++i) {
    CHECK(r.elapsed_s[i] >= r.elapsed_s[i - 1]);
    CHECK(r.walks[i] > r.walks[i - 1]);
  }
  CHECK(r.walks.front() > 0);
  CHECK(r.walks.back() == total_walks);
}

aco::PipelineSpec pipeline(const aco::Keys& keys) { return aco::resolve_run(keys, plugins()).pipeline; }

CommandResult acoplan(const std::vector<std::string>& args, const std::vector<std::string>& env) {
  std::vector<std::string> argv{ACO_TEST_ACOPLAN};
  argv.insert(argv.end(), args.begin(), args.end());
  return run(argv, env);
}

std::filesystem::path temp_file(const std::string& name, const std::string& content) {
  const auto file = fresh_dir() / name;
  std::ofstream(file) << content;
  return file;
}

// reference_segment_clear does not walk the grid as aco::line_of_sight does: it samples the
// segment densely, exactly in integers (dense enough that every cell whose interior the segment
// meets gets a sample), and checks every grid vertex of the bounding box explicitly.

// Cells whose open interior the segment between the centres of a and b meets (a and b
// included). Sample k of N sits at t = (2k + 1) / (2N); its x is a.x + t * dx, and its cell is
// floor(x + 1/2) = floor((2N * a.x + (2k + 1) * dx + N) / (2N)), exact in integers; a sample on
// a cell border (numerator divisible by 2N) is skipped. A cell's interior is an open t-interval
// with ends in {0, 1, (2m+1)/(2|dx|), (2n+1)/(2|dy|)}, so at least 1/(2|dx||dy| + 2|dx| + 2|dy|)
// wide: N above that puts a sample in every one.
std::set<std::pair<int, int>> reference_cells_entered(aco::Cell a, aco::Cell b) {
  const std::int64_t dx = b.x - a.x, dy = b.y - a.y;
  const std::int64_t adx = std::abs(dx), ady = std::abs(dy);
  const std::int64_t n = 4 * (adx * ady + adx + ady + 1);
  auto floor_div = [](std::int64_t p, std::int64_t q) { return p / q - ((p % q != 0) && ((p < 0) != (q < 0))); };
  std::set<std::pair<int, int>> cells{{a.x, a.y}, {b.x, b.y}};
  for (std::int64_t k = 0; k < n; ++k) {
    const std::int64_t px = 2 * n * a.x + (2 * k + 1) * dx + n;
    const std::int64_t py = 2 * n * a.y + (2 * k + 1) * dy + n;
    if (px % (2 * n) == 0 || py % (2 * n) == 0) continue;  // on a cell border
    cells.insert({int(floor_div(px, 2 * n)), int(floor_div(py, 2 * n))});
  }
  return cells;
}

// Grid vertices (corners shared by four cells) strictly inside the segment, each with the two
// side cells the segment touches there only at that corner.
std::vector<std::pair<aco::Cell, aco::Cell>> reference_vertex_sides(aco::Cell a, aco::Cell b) {
  std::vector<std::pair<aco::Cell, aco::Cell>> sides;
  const std::int64_t dx = b.x - a.x, dy = b.y - a.y;
  const int sx = dx > 0 ? 1 : -1, sy = dy > 0 ? 1 : -1;
  for (int vy = std::min(a.y, b.y) - 1; vy <= std::max(a.y, b.y); ++vy) {
    for (int vx = std::min(a.x, b.x) - 1; vx <= std::max(a.x, b.x); ++vx) {
      // The vertex (vx + 1/2, vy + 1/2), doubled, relative to a's doubled centre.
      const std::int64_t rx = 2 * vx + 1 - 2 * a.x, ry = 2 * vy + 1 - 2 * a.y;
      if (rx * dy - ry * dx != 0) continue;  // not on the line
      const std::int64_t along = rx * dx + ry * dy;
      if (along <= 0 || along >= 2 * (dx * dx + dy * dy)) continue;  // not between the centres
      // The segment runs through quadrants (sx, sy) and (-sx, -sy) of the vertex; the side cells
      // are the other two. The cell in quadrant (qx, qy) is (vx + [qx > 0], vy + [qy > 0]).
      auto quadrant = [&](int qx, int qy) { return aco::Cell{vx + (qx > 0 ? 1 : 0), vy + (qy > 0 ? 1 : 0)}; };
      sides.push_back({quadrant(sx, -sy), quadrant(-sx, sy)});
    }
  }
  return sides;
}

bool reference_segment_clear(const aco::Map& map, aco::Cell a, aco::Cell b, bool corner_cutting) {
  for (const auto& [x, y] : reference_cells_entered(a, b))
    if (!map.passable({x, y})) return false;
  for (const auto& [s1, s2] : reference_vertex_sides(a, b)) {
    const bool f1 = map.passable(s1), f2 = map.passable(s2);
    if (corner_cutting ? (!f1 && !f2) : (!f1 || !f2)) return false;
  }
  return true;
}

std::string walk_problem(const aco::Graph& graph, const aco::Ant& ant, aco::NodeId start, aco::NodeId goal) {
  if (ant.nodes.empty() || ant.nodes.front() != start) return "the walk does not begin at the start";
  if (ant.edges.size() + 1 != ant.nodes.size())
    return "the walk has " + std::to_string(ant.edges.size()) + " edges for " + std::to_string(ant.nodes.size()) +
           " nodes";
  if (std::set<aco::NodeId>(ant.nodes.begin(), ant.nodes.end()).size() != ant.nodes.size()) return "a node repeats";
  for (std::size_t i = 0; i < ant.edges.size(); ++i)
    if (graph.source(ant.edges[i]) != ant.nodes[i] || graph.targets[ant.edges[i]] != ant.nodes[i + 1])
      return "edge " + std::to_string(i) + " does not lead from node " + std::to_string(i) + " to the next";
  if (ant.arrived != (ant.nodes.back() == goal))
    return "arrived is " + std::string(ant.arrived ? "true" : "false") + " but the walk ends at " +
           aco::to_string(graph.cell(ant.nodes.back()));
  if (ant.arrived && std::abs(ant.length - aco::path_length(graph, ant.nodes)) > 1e-9 * (1 + ant.length))
    return "length " + std::to_string(ant.length) + " is not the walk's length";
  return "";
}

aco::ColonyResult run_on_thread_counts(const aco::Graph& graph, aco::NodeId start, aco::NodeId goal,
                                       const aco::ColonySettings& settings, const std::array<std::string, 4>& plugins,
                                       const std::map<std::string, std::string>& update_params) {
  std::vector<aco::ColonyResult> results;
  tbb::global_control allow(tbb::global_control::max_allowed_parallelism, 4);
  for (int threads : {1, 2, 4}) {
    auto init = make<aco::PheromoneInit>("init", plugins[0]);
    auto heuristic = make<aco::Heuristic>("heuristic", plugins[1]);
    auto update = make<aco::PheromoneUpdate>("update", plugins[2], update_params);
    auto deadlock = make<aco::DeadlockPolicy>("deadlock", plugins[3]);
    const aco::ColonyStrategies pipeline{init.get(), heuristic.get(), update.get(), deadlock.get()};
    tbb::task_arena arena(threads);
    arena.execute([&] { results.push_back(aco::run_colony(graph, start, goal, pipeline, settings)); });
  }
  for (std::size_t i = 1; i < results.size(); ++i) check_same_run(results[i], results[0]);
  return results[0];
}

namespace {

// The value of attribute `name` in a tag's text, or "" if it has none.
std::string svg_attribute(const std::string& tag, const std::string& name) {
  for (auto at = tag.find(name + "=\""); at != std::string::npos; at = tag.find(name + "=\"", at + 1)) {
    if (at > 0 && tag[at - 1] != ' ' && tag[at - 1] != '\n') continue;  // the tail of another name (dy in "ody=")
    const auto begin = at + name.size() + 2;
    return tag.substr(begin, tag.find('"', begin) - begin);
  }
  return "";
}

double number_or(const std::string& text, double otherwise) { return text.empty() ? otherwise : std::stod(text); }

// The numbers inside "function(a b c)" or "function(a,b)" in a transform, if it holds that function.
std::vector<double> transform_arguments(const std::string& transform, const std::string& function) {
  const auto at = transform.find(function + "(");
  if (at == std::string::npos) return {};
  std::string inside = transform.substr(at + function.size() + 1, transform.find(')', at) - at - function.size() - 1);
  std::replace(inside.begin(), inside.end(), ',', ' ');
  std::istringstream in(inside);
  std::vector<double> numbers;
  for (double v; in >> v;) numbers.push_back(v);
  return numbers;
}

std::string unescape_xml(std::string text) {
  for (const auto& [entity, character] : {std::pair{"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&amp;", "&"}})
    for (auto at = text.find(entity); at != std::string::npos; at = text.find(entity, at + 1))
      text.replace(at, std::strlen(entity), character);
  return text;
}

}  // namespace

std::string svg_group(const std::string& svg, const std::string& id) {
  const auto begin = svg.find("<g id=\"" + id + "\"");
  REQUIRE(begin != std::string::npos);
  return svg.substr(begin, svg.find("</g>", begin) - begin);
}

std::vector<std::string> texts_outside_view_box(const std::string& svg) {
  const auto root_end = svg.find('>', svg.find("<svg"));
  const std::string root = svg.substr(svg.find("<svg"), root_end - svg.find("<svg"));
  double width = number_or(svg_attribute(root, "width"), 0), height = number_or(svg_attribute(root, "height"), 0);
  if (const auto box = transform_arguments("viewBox(" + svg_attribute(root, "viewBox") + ")", "viewBox");
      box.size() == 4)
    width = box[2], height = box[3];
  const double root_font = number_or(svg_attribute(root, "font-size"), 12);
  std::vector<std::string> outside;
  std::vector<std::pair<double, double>> offsets{{0, 0}};  // the enclosing groups' translations, summed
  for (auto at = svg.find('<', root_end); at != std::string::npos; at = svg.find('<', at + 1)) {
    const auto end = svg.find('>', at);
    const std::string tag = svg.substr(at, end - at + 1);
    if (tag.rfind("<g", 0) == 0 && (tag.size() < 3 || tag[2] == ' ' || tag[2] == '>') && tag[tag.size() - 2] != '/') {
      const auto move = transform_arguments(svg_attribute(tag, "transform"), "translate");
      offsets.emplace_back(offsets.back().first + (move.empty() ? 0 : move[0]),
                           offsets.back().second + (move.size() < 2 ? 0 : move[1]));
    } else if (tag == "</g>") {
      offsets.pop_back();
    } else if (tag.rfind("<text", 0) == 0) {
      const auto close = svg.find("</text>", end);
      const std::string content = unescape_xml(svg.substr(end + 1, close - end - 1));
      const double font = number_or(svg_attribute(tag, "font-size"), root_font);
      const double x = number_or(svg_attribute(tag, "x"), 0),
                   y = number_or(svg_attribute(tag, "y"), 0) + number_or(svg_attribute(tag, "dy"), 0);
      const double w = aco::text_width(content, font);
      const std::string anchor = svg_attribute(tag, "text-anchor");
      const double left = anchor == "end" ? x - w : anchor == "middle" ? x - w / 2 : x;
      const auto rotation = transform_arguments(svg_attribute(tag, "transform"), "rotate");
      const double angle = rotation.empty() ? 0 : rotation[0] * std::acos(-1.0) / 180;
      const double cx = rotation.size() == 3 ? rotation[1] : 0, cy = rotation.size() == 3 ? rotation[2] : 0;
      for (const double corner_x : {left, left + w})
        for (const double corner_y : {y - 0.8 * font, y + 0.25 * font}) {
          const double px =
              cx + (corner_x - cx) * std::cos(angle) - (corner_y - cy) * std::sin(angle) + offsets.back().first;
          const double py =
              cy + (corner_x - cx) * std::sin(angle) + (corner_y - cy) * std::cos(angle) + offsets.back().second;
          if (px < -0.5 || px > width + 0.5 || py < -0.5 || py > height + 0.5) {
            outside.push_back("\"" + content + "\" reaches (" + std::to_string(px) + ", " + std::to_string(py) +
                              ") in a picture of " + std::to_string(width) + " x " + std::to_string(height));
            break;
          }
        }
      at = close;
    }
  }
  return outside;
}

}  // namespace test

#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <nlohmann/json.hpp>

#include "aco/hosts/host_options.hpp"
#include "aco/process/output_file.hpp"
#include "aco/plugin.hpp"
#include "aco/drawing/svg.hpp"
#include "acoplan/acoplan.hpp"
#include "support.hpp"

using Catch::Contains;
using Catch::StartsWith;
using nlohmann::json;

namespace {

const std::string map1 = (test::data_dir() / "maps/classic20/map1.txt").string();
const std::string arena_scen = (test::data_dir() / "maps/movingai/arena.map.scen").string();

json run_json(const std::vector<std::string>& args) {
  auto args_json = args;
  args_json.push_back("--json");
  const auto r = test::acoplan(args_json);
  INFO(r.err);
  REQUIRE((r.exit_code == 0 || r.exit_code == 3));
  return json::parse(r.out);
}

// A run's JSON without what its wall clock measured, which differs from run to run.
json without_times(json j) {
  j.erase("time_ms");
  j.erase("convergence_time_s");
  return j;
}

// An error: exit status 1, nothing on stdout, one message on stderr containing `expected`.
void expect_error(const std::vector<std::string>& args, const std::string& expected) {
  const auto r = test::acoplan(args);
  INFO("stderr: " << r.err);
  CHECK(r.exit_code == 1);
  CHECK(r.out.empty());
  CHECK_THAT(r.err, Contains("acoplan: error: ") && Contains(expected));
}

}  // namespace

TEST_CASE("acoplan --json reports every documented field", "[acoplan]") {
  const json j = run_json({"--map", map1, "--start", "0,0", "--goal", "19,19", "--corner-cutting", "--seed", "3"});
  REQUIRE(j.at("solved").get<bool>());
  for (const char* field :
       {"length", "path", "grid_length", "grid_path", "turns", "iterations", "best_iteration", "time_ms", "seed"})
    CHECK(j.contains(field));
  CHECK(j["seed"] == 3);
  CHECK(j["iterations"] == 100);
  CHECK(j["best_iteration"].get<int>() >= 1);
  CHECK(j["best_iteration"].get<int>() <= 100);
  CHECK(j["time_ms"].get<double>() >= 0.0);
  const auto& grid_path = j["grid_path"];
  CHECK(grid_path.front() == json::array({0, 0}));
  CHECK(grid_path.back() == json::array({19, 19}));
  double length = 0;
  for (std::size_t i = 1; i < grid_path.size(); ++i) {
    const int dx = grid_path[i][0].get<int>() - grid_path[i - 1][0].get<int>();
    const int dy = grid_path[i][1].get<int>() - grid_path[i - 1][1].get<int>();
    REQUIRE(std::max(std::abs(dx), std::abs(dy)) == 1);
    length += std::hypot(dx, dy);
  }
  CHECK(j["grid_length"].get<double>() == Approx(length));
  // robust's taut smoother: never longer than the grid path, never below the any-angle optimum.
  CHECK(j["length"].get<double>() <= length + 1e-9);
  CHECK(j["length"].get<double>() >= j["any_angle_length"].get<double>() - 1e-9);
  CHECK(j["path"].size() <= grid_path.size());
  CHECK(j["grid_length"].get<double>() >= j["optimal_length"].get<double>() - 1e-9);
  CHECK(j["optimal_length"].get<double>() == Approx(34.3848).margin(1e-4));
  CHECK(j["convergence"].size() == 100);
  CHECK(j["convergence_time_s"].size() == 100);
  CHECK(j["convergence_walks"].size() == 100);
  CHECK(j["convergence_walks"].back() == 100 * j["config"]["ants"].get<int>());
  // The configuration: every run key with its resolved value, as --print-config and acobench name them.
  // Naming no pipeline runs the recommended one (data/presets/robust.ini).
  CHECK(j["config"]["update"] == "max_min");
  CHECK(j["config"]["update.rho"] == 0.3);
  CHECK(j["config"]["corner-cutting"] == true);
  CHECK(j["config"]["seed"] == 3);
}

TEST_CASE("acoplan with the start as goal reports no gap and no NaN", "[acoplan]") {
  const auto r = test::acoplan({"--map", map1, "--start", "0,0", "--goal", "0,0"});
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.out, Catch::Contains("gap 0.00 % for the grid path"));
  CHECK_THAT(r.out, Catch::Contains("final path 0.00 % longer"));
  CHECK_THAT(r.out, !Catch::Contains("nan"));
}

TEST_CASE("acoplan is deterministic for a seed, whatever the thread count", "[acoplan][determinism]") {
  const std::vector<std::string> base{"--scen", arena_scen, "--scen-index", "120", "--iterations", "40"};
  auto one = base, two = base;
  one.insert(one.end(), {"--threads", "1"});
  two.insert(two.end(), {"--threads", "2"});
  const json a = without_times(run_json(one)), b = without_times(run_json(two)), c = without_times(run_json(one));
  CHECK(a == b);
  CHECK(a == c);
  auto other_seed = one;
  other_seed.insert(other_seed.end(), {"--seed", "99"});
  CHECK(without_times(run_json(other_seed))["ant_steps"] != a["ant_steps"]);
}

TEST_CASE("acoplan with no arguments plans on the bundled map and prints a summary", "[acoplan]") {
  const auto r = test::acoplan({});
  CHECK(r.exit_code == 0);
  CHECK_THAT(r.out, Contains("classic20/map1.txt") && Contains("result:   length") && Contains("optimum:"));
}

TEST_CASE("acoplan plans Moving AI scenarios and the exact reference", "[acoplan]") {
  const json j = run_json({"--scen", arena_scen, "--scen-index", "100"});
  REQUIRE(j["solved"].get<bool>());
  const json exact = run_json({"--scen", arena_scen, "--scen-index", "100", "--planner", "astar"});
  CHECK(exact["grid_length"].get<double>() == Approx(j["optimal_length"].get<double>()));
  // A* is one iteration building one path, so that it has anytime curves like the others.
  CHECK(exact["iterations"] == 1);
  CHECK(exact["best_iteration"] == 1);
  CHECK(exact["convergence"] == json::array({exact["grid_length"]}));
  CHECK(exact["convergence_walks"] == json::array({1}));
  CHECK(exact["convergence_time_s"].size() == 1);
  CHECK(j["grid_length"].get<double>() >= exact["grid_length"].get<double>() - 1e-9);
  const json classic = run_json({"--planner", "astar"});
  CHECK(classic["grid_length"].get<double>() == Approx(37.8995).margin(1e-4));
}

TEST_CASE("acoplan composes plugins and parameters from the command line and a config file", "[acoplan]") {
  const json mmas =
      run_json({"--update", "max_min", "--update.rho", "0.2", "--update.p_best", "0.1", "--iterations", "30"});
  CHECK(mmas["config"]["update"] == "max_min");
  CHECK(mmas["config"]["update.rho"] == 0.2);
  CHECK(mmas["iterations"] == 30);

  const auto printed =
      test::acoplan({"--update", "acs", "--q0", "0.5", "--update.xi", "0.3", "--ants", "20", "--print-config"});
  REQUIRE(printed.exit_code == 0);
  CHECK_THAT(printed.out, Contains("update = acs") && Contains("[update]") && Contains("xi = 0.3") &&
                              Contains("q0 = 0.5") && Contains("ants = 20"));
  const auto config = test::temp_file("run.ini", printed.out);
  json from_file = run_json({"--config", config.string()});
  json direct = run_json({"--update", "acs", "--q0", "0.5", "--update.xi", "0.3", "--ants", "20"});
  CHECK(without_times(from_file) == without_times(direct));
  // The command line wins over the file.
  CHECK(run_json({"--config", config.string(), "--ants", "7"})["config"]["ants"] == 7);
}

TEST_CASE("acoplan lists and describes plugins, and prints help with plugin options", "[acoplan]") {
  const auto list = test::acoplan({"--list-plugins"});
  CHECK(list.exit_code == 0);
  for (const char* p : {"init/uniform", "heuristic/distance", "update/ant_system", "update/max_min", "update/acs",
                        "deadlock/discard", "smoother/none"})
    CHECK_THAT(list.out, Contains(p));
  const auto described = test::acoplan({"--describe", "max_min"});
  CHECK(described.exit_code == 0);
  CHECK_THAT(described.out, Contains("update/max_min") && Contains("p_best") && Contains("(0:1)"));
  const auto help = test::acoplan({"--update", "acs", "--help"});
  CHECK(help.exit_code == 0);
  CHECK_THAT(help.out, Contains("--update.xi") && Contains("--q0") && Contains("--ants") && Contains("--init.tau0"));
  expect_error({"--describe", "max_mn"}, "no plugin named 'max_mn'; did you mean 'update/max_min'?");
}

TEST_CASE("acoplan --describe takes SLOT/NAME and lists the slots of a name several have", "[acoplan][describe]") {
  for (const std::string slot : {"init", "heuristic"}) {
    const auto described = test::acoplan({"--describe", slot + "/potential_field"});
    CHECK(described.exit_code == 0);
    CHECK_THAT(described.out, StartsWith(slot + "/potential_field "));
  }
  expect_error({"--describe", "potential_field"},
               "--describe: 'potential_field' names a plugin in 2 slots; give its slot too, as SLOT/NAME: "
               "init/potential_field or heuristic/potential_field");
  expect_error({"--describe", "update/potential_field"}, "no plugin named 'update/potential_field'");
  CHECK_THAT(test::acoplan({"--help"}).out, Contains("--describe SLOT/NAME"));
}

// The line of the summary that starts with `label`, or "" if there is none.
std::string summary_line(const std::string& summary, const std::string& label) {
  std::istringstream in(summary);
  for (std::string line; std::getline(in, line);)
    if (line.rfind(label, 0) == 0) return line;
  return "";
}

// --update acs without --q0 used to read like a run with it: the gap differed, the summary not.
TEST_CASE("acoplan's summary shows every setting changed from the defaults and no other", "[acoplan][summary]") {
  const std::vector<std::string> base{"--preset", "ant-system", "--update", "acs", "--iterations", "5"};
  const auto plain = test::acoplan(base);
  REQUIRE(plain.exit_code == 0);
  CHECK(summary_line(plain.out, "settings: ") ==
        "settings: the engine defaults, as --help and --describe SLOT/NAME list them");

  auto changed = base;
  changed.insert(changed.end(), {"--q0", "0.7", "--search", "bidirectional", "--update.rho", "0.2", "--walk-limit", "3",
                                 "--stagnation", "0", "--update.q", "1", "--repeat", "2"});
  const auto r = test::acoplan(changed);
  REQUIRE(r.exit_code == 0);
  const std::string line = summary_line(r.out, "settings: ");
  CHECK(line ==
        "settings: q0=0.7 search=bidirectional walk-limit=3 update.rho=0.2 (changed from the engine defaults), "
        "as --help and --describe SLOT/NAME list them");
  // Given but equal to the default: stagnation 0 and acs's q 1 are not changes. Neither is what
  // another line shows (the colony line's iterations, the pipeline line's update=acs).
  for (const char* unchanged : {"stagnation", "update.q", "iterations", "update="})
    CHECK_THAT(line, !Contains(unchanged));
  // The recommended preset's settings are changes too: a bare acoplan shows what robust sets.
  CHECK_THAT(summary_line(test::acoplan({"--iterations", "5"}).out, "settings: "),
             Contains("fill-dead-ends=true") && Contains("q0=0.7") && Contains("heuristic.floor=0.5"));
  // Another planner shows its own keys on its line; colony settings are not its.
  CHECK(summary_line(test::acoplan({"--planner", "astar", "--q0", "0.5", "--max-slope", "45"}).out, "settings: ") ==
        "settings: max-slope=45 (changed from the engine defaults), as --help and --describe SLOT/NAME list them");
}

// The bundled ROS map_server and PGM height samples, with their READMEs' commands: each loads,
// the colony solves it, and the exact optimum is the one the README states.
TEST_CASE("acoplan loads and solves the bundled ROS and PGM height samples", "[acoplan][sample-maps]") {
  struct Sample {
    std::vector<std::string> args;
    double optimum;
    double lowest, highest;  // of the heights along the path; 0, 0 on a 2D map
  };
  const std::string dir = (test::data_dir() / "maps").string();
  const std::vector<Sample> samples{
      {{"--map", dir + "/ros/office.yaml", "--start", "8,8", "--goal", "90,60"}, 111.7401, 0, 0},
      {{"--map", dir + "/heights/hills.pgm", "--height-scale", "0.05", "--cell-size", "1", "--max-slope", "25",
        "--start", "0,40", "--goal", "60,44"},
       72.2692,
       0,
       12},
      {{"--map", dir + "/heights/hills16.pgm", "--height-scale", "0.001", "--cell-size", "5", "--max-slope", "25",
        "--start", "0,32", "--goal", "95,32"},
       524.0169,
       20,
       60},
  };
  for (const auto& sample : samples) {
    INFO(sample.args[1]);
    const json j = run_json(sample.args);
    REQUIRE(j["solved"].get<bool>());
    CHECK(j["optimal_length"].get<double>() == Approx(sample.optimum).margin(1e-4));
    CHECK(j["grid_length"].get<double>() >= sample.optimum - 1e-4);
    CHECK(j["grid_length"].get<double>() <= 1.05 * sample.optimum);
    for (const auto& point : j["path"]) {
      const double z = point.size() == 3 ? point[2].get<double>() : 0.0;
      CHECK(z >= sample.lowest);
      CHECK(z <= sample.highest);
    }
  }
  // The 16-bit image keeps millimetres: heights along the route are not all whole metres.
  const json route = run_json(samples[2].args)["path"];
  CHECK(std::any_of(route.begin(), route.end(),
                    [](const json& p) { return p[2].get<double>() != std::round(p[2].get<double>()); }));
  // The slope limit is what makes the height sample's route longer than the unlimited one.
  auto unlimited = samples[1].args;
  unlimited[7] = "90";
  CHECK(run_json(unlimited)["optimal_length"].get<double>() == Approx(65.3231).margin(1e-4));
}

TEST_CASE("acoplan writes an SVG picture", "[acoplan]") {
  const auto file = test::temp_file("run.svg", "");
  const auto r = test::acoplan({"--svg", file.string(), "--svg-pheromone"});
  REQUIRE(r.exit_code == 0);
  std::ifstream in(file);
  const std::string svg((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK_THAT(svg, Contains("<svg") && Contains("id=\"grid-path\"") && Contains("id=\"convergence\"") &&
                      Contains("id=\"pheromone\"") && Contains("</svg>"));
}

namespace {

// The part of `svg` from `<g id="ID"` to its closing tag (the groups of the run picture hold no
// nested groups).
std::size_t occurrences(const std::string& text, const std::string& what) {
  std::size_t count = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++count;
  return count;
}

// The y coordinates of the points of every polyline and dot of class `css_class`.
std::vector<double> curve_heights(const std::string& svg, const std::string& css_class) {
  std::vector<double> heights;
  for (auto at = svg.find("class=\"" + css_class + "\""); at != std::string::npos;
       at = svg.find("class=\"" + css_class + "\"", at + 1)) {
    const auto element = svg.rfind('<', at), end = svg.find('>', at);
    const std::string tag = svg.substr(element, end - element);
    if (tag.rfind("<circle", 0) == 0) {
      const auto cy = tag.find("cy=\"");
      heights.push_back(std::stod(tag.substr(cy + 4)));
      continue;
    }
    std::istringstream points(tag.substr(tag.find("points=\"") + 8));
    std::string point;
    while (points >> point && point.find(',') != std::string::npos)
      heights.push_back(std::stod(point.substr(point.find(',') + 1)));
  }
  return heights;
}

}  // namespace

TEST_CASE("acoplan's SVG draws obstacle cells as one rectangle per run with crisp edges", "[acoplan][svg]") {
  // Runs of blocked cells: row 0 has two, row 1 one of four cells, row 2 none, row 3 three single cells.
  const auto grid = test::grid({"##.##.", ".####.", "......", "#.#.#."});
  const aco::Graph graph = aco::build_graph(grid, {});
  aco::RunPicture picture;
  picture.goal = graph.node({5, 2});
  picture.pheromone.assign(static_cast<std::size_t>(graph.num_edges()), 1.0);
  const std::string svg = aco::render_svg(graph, picture);
  const std::string obstacles = test::svg_group(svg, "obstacles");
  CHECK_THAT(obstacles, Contains("shape-rendering=\"crispEdges\""));
  CHECK(occurrences(obstacles, "<rect") == 6);
  CHECK_THAT(obstacles, Contains("<rect x=\"0.5\" y=\"0.5\" width=\"4\" height=\"1\"/>"));
  CHECK_THAT(test::svg_group(svg, "pheromone"), Contains("shape-rendering=\"crispEdges\""));

  // The pheromone field too: on an open map with the same pheromone on every edge, a cell's shade
  // follows its number of neighbours, so each row is three runs: its two end cells and the rest.
  const auto open_grid = test::grid({"........", "........", "........"});
  const aco::Graph open = aco::build_graph(open_grid, {});
  picture.pheromone.assign(static_cast<std::size_t>(open.num_edges()), 1.0);
  CHECK(occurrences(test::svg_group(aco::render_svg(open, picture), "pheromone"), "<rect") == 9);
}

TEST_CASE("acoplan's SVG has a legend for what its map shows, inside the picture", "[acoplan][svg]") {
  const auto grid = test::grid({"..#.", "....", ".#.."});
  const aco::Graph graph = aco::build_graph(grid, {});
  aco::RunPicture picture;
  picture.goal = graph.node({3, 2});
  const std::string plain = aco::render_svg(graph, picture);
  const std::string legend = test::svg_group(plain, "map-legend");
  for (const char* entry :
       {">start<", ">goal<", ">grid path (cell to cell)<", ">path after the smoother<", ">blocked cell<"})
    CHECK_THAT(legend, Contains(entry));
  CHECK_THAT(legend, !Contains("pheromone"));  // not drawn, so not named
  CHECK(test::texts_outside_view_box(plain).empty());
  picture.pheromone.assign(static_cast<std::size_t>(graph.num_edges()), 1.0);
  const std::string with_pheromone = aco::render_svg(graph, picture);
  CHECK_THAT(test::svg_group(with_pheromone, "map-legend"), Contains(">pheromone (darker: more)<"));
  CHECK(test::texts_outside_view_box(with_pheromone).empty());
}

TEST_CASE("acoplan's convergence chart keeps every iteration best inside its frame", "[acoplan][svg]") {
  const auto grid = test::grid({"...."});
  const aco::Graph graph = aco::build_graph(grid, {});
  aco::RunPicture picture;
  picture.goal = 3;
  picture.best_so_far = {50, 50, 40, 40, 38, 38};
  // An iteration far worse than the first, and one in which no ant arrived.
  picture.iteration_best = {50, 120, 40, std::numeric_limits<double>::infinity(), 38, 45};
  const std::string svg = aco::render_svg(graph, picture);
  const std::string chart = svg.substr(svg.find("<g id=\"convergence\""));
  const double frame_height = std::stod(chart.substr(chart.find("height=\"") + 8));
  const auto heights = curve_heights(chart, "iteration-best");
  CHECK(heights.size() == 5);  // every finite value drawn
  for (const double y : heights) {
    INFO("y " << y << " in a frame of height " << frame_height);
    CHECK(y > 0.0);  // inside the frame, not on its edge where the frame's line would hide it
    CHECK(y < frame_height);
  }
  CHECK_THAT(chart, Contains(">120</text>") && Contains(">38</text>"));
  // The iteration without a path leaves a gap: two pieces, not a line across it.
  CHECK(occurrences(chart, "class=\"iteration-best\"") == 2);
}

TEST_CASE("acoplan rejects malformed map files with the file, line and problem", "[acoplan][bad-input]") {
  const std::string ok_rows = "....\n....\n";
  expect_error({"--map", test::temp_file("a.map", "typo octile\nheight 2\nwidth 4\nmap\n" + ok_rows).string(),
                "--start", "0,0", "--goal", "1,1"},
               "a.map:1: bad header line 'typo octile'");
  expect_error({"--map", test::temp_file("b.map", "type octile\nheight 2\nwidth 4\nmap\n....\n...\n").string(),
                "--start", "0,0", "--goal", "1,1"},
               "b.map:6: row 1 has 3 characters, expected 4");
  expect_error({"--map", test::temp_file("c.map", "type octile\nheight 2\nwidth 4\nmap\n..x.\n....\n").string(),
                "--start", "0,0", "--goal", "1,1"},
               "unknown character 'x' at column 2");
  expect_error({"--map", test::temp_file("d.map", "type octile\nheight 3\nwidth 4\nmap\n" + ok_rows).string(),
                "--start", "0,0", "--goal", "1,1"},
               "truncated map: expected 3 rows, found 2");
  expect_error({"--map", test::temp_file("e.txt", "0 0 1\n0 a 0\n").string(), "--start", "0,0", "--goal", "1,0"},
               "e.txt:2: 'a' is not a number");
  expect_error({"--map", test::temp_file("f.txt", "0 0 1\n0 0\n").string(), "--start", "0,0", "--goal", "1,0"},
               "row has 2 values, the first row has 3");
  expect_error({"--map", "/nonexistent/map.map", "--start", "0,0", "--goal", "1,0"},
               "/nonexistent/map.map: cannot open file");
  expect_error({"--map", "/dev/zero", "--start", "0,0", "--goal", "1,0"}, "/dev/zero: not a regular file");
  expect_error({"--map", "/tmp", "--start", "0,0", "--goal", "1,0"}, "/tmp: is a directory, not a file");
}

// A folder read as a config file used to read as an empty one: a run with the defaults, no
// error. /dev/zero never ended.
TEST_CASE("acoplan refuses a voxel world's cell without its z and a 2D map's with one", "[acoplan][bad-input]") {
  const std::string world = (test::data_dir() / "maps/voxel/generated/caves64x64x32-s1.3dmap").string();
  const auto flat = test::acoplan({"--map", world, "--start", "42,24", "--goal", "44,24,22"});
  CHECK(flat.exit_code == 1);
  CHECK_THAT(flat.err,
             Catch::Contains("--start 42,24 has no z, but " + world + " is a voxel world: give its cells as X,Y,Z"));
  const auto layered = test::acoplan({"--map", map1, "--start", "0,0", "--goal", "19,19,0"});
  CHECK(layered.exit_code == 1);
  CHECK_THAT(layered.err,
             Catch::Contains("--goal 19,19,0 has a z, but " + map1 + " is a 2D map: give its cells as X,Y"));
}

TEST_CASE("acoplan refuses a config file that is a folder or a device", "[acoplan][bad-input]") {
  expect_error({"--config", "/tmp"}, "/tmp: is a directory, not a config file");
  expect_error({"--config", "/dev/zero"}, "/dev/zero: not a regular file");
  expect_error({"--config", "/nonexistent/run.ini"}, "/nonexistent/run.ini: cannot open the config file");
}

// Found by the ini_config fuzz harness: acoplan --config with this file never ended, inside
// Boost.ProgramOptions' message for the bad line (aco/hosts/program_options_error.hpp).
TEST_CASE("acoplan names a bad config line, and shows '%' placeholders in any input as typed", "[acoplan][bad-input]") {
  const auto hang = test::temp_file("hang.ini", "beta = 0.3\n%invalid_line%x\n").string();
  expect_error({"--config", hang}, hang + ":2: '%invalid_line%x' is not a 'key = value' line");
  const auto section = test::temp_file("section.ini", "ants = 3\n[]\n").string();
  expect_error({"--config", section}, section + ":2: '[]' names no section");
  // A value Boost checks (a switch) and one acoplan's settings table checks.
  const auto flag = test::temp_file("flag.ini", "print-config = %value%\n").string();
  expect_error({"--config", flag}, flag + ": the argument ('%value%') for option 'print-config' is invalid");
  expect_error({"--config", test::temp_file("json.ini", "json = %value%\n").string()},
               "--json: '%value%' is not a boolean (use true or false)");
  expect_error({"--config", test::temp_file("key.ini", "[%x%]\n%canonical_option% = 1\n").string()},
               "unknown option '--%x%.%canonical_option%'");
  expect_error({"--config", test::temp_file("value.ini", "beta = %value%\n").string()},
               "--beta: '%value%' is not a finite number");
  expect_error({"--%value%", "1"}, "unknown option '--%value%'");
  expect_error({"--beta", "%x%"}, "--beta: '%x%' is not a finite number");
}

TEST_CASE("acoplan refuses real values a double holds without precision or not at all", "[acoplan][bad-input]") {
  // Subnormal: read, but a plugin's arithmetic on it overflowed ("wrote inf") and printing it failed.
  for (const char* key : {"--update.rho", "--beta", "--q0", "--time-limit", "--heuristic.floor", "--init.tau0"})
    expect_error({key, "1e-310"}, std::string(key) + ": 1e-310 is too close to 0 to compute with (a subnormal " +
                                      "number); give 0 or a value of at least 2.2250738585072014e-308 in size");
  expect_error({"--update.rho", "1e-400"}, "--update.rho: 1e-400 is beyond what a double holds");
  expect_error({"--beta", "1e400"}, "--beta: 1e400 is beyond what a double holds");
}

TEST_CASE("acoplan rejects blocked, out-of-range and malformed start and goal cells", "[acoplan][bad-input]") {
  expect_error({"--map", map1, "--start", "6,0", "--goal", "19,19"},
               "start (6,0) is blocked: an obstacle (" + map1 + ")");
  expect_error({"--map", map1, "--start", "0,0", "--goal", "25,3"}, "goal (25,3) is outside the 20x20 map");
  expect_error({"--map", map1, "--start", "-1,0", "--goal", "19,19"}, "start (-1,0) is outside");
  expect_error({"--map", map1, "--start", "3", "--goal", "19,19"}, "--start: '3' is not a cell");
  expect_error({"--map", map1}, "--start and --goal are required");
  expect_error({"--scen", arena_scen, "--scen-index", "100000"}, "scen-index 100000 is out of range");
  expect_error({"--scen", arena_scen, "--start", "1,1"}, "either --scen or --start/--goal");
}

TEST_CASE("an unreachable goal is reported as unsolved with its own exit status", "[acoplan][bad-input]") {
  const auto walled = test::temp_file("walled.txt", "0 1 0\n0 1 0\n0 1 0\n");
  const auto r = test::acoplan({"--map", walled.string(), "--start", "0,0", "--goal", "2,2", "--json"});
  CHECK(r.exit_code == 3);
  const json j = json::parse(r.out);
  CHECK_FALSE(j["solved"].get<bool>());
  CHECK(j["length"].is_null());
  CHECK_THAT(j["reason"].get<std::string>(), Contains("goal (2,2) is not reachable from start (0,0)"));
  const auto text = test::acoplan({"--map", walled.string(), "--start", "0,0", "--goal", "2,2"});
  CHECK(text.exit_code == 3);
  CHECK_THAT(text.out, Contains("NOT SOLVED"));
}

TEST_CASE("parameter ranges keep the plugins' arithmetic finite: no plugin is blamed for a value they allow",
          "[acoplan][bad-input]") {
  // Each was "plugin ... wrote inf (or nan)" before its range was closed at a finite end.
  expect_error({"--update.q", "1e12", "--update.rho", "1e-300"},
               "--update.rho: 1e-300 is outside the range [1e-06, 1]");
  expect_error({"--heuristic", "distance", "--heuristic.min_distance", "1e-300"},
               "--heuristic.min_distance: 1e-300 is outside the range [1e-06, 1]");
  expect_error({"--update", "gaussian", "--update.sigma", "1e-300"},
               "--update.sigma: 1e-300 is outside the range [0.01, 100]");
  // The ends themselves, together with the largest Q, alpha and beta, stay finite.
  for (const std::vector<std::string>& extreme :
       {std::vector<std::string>{"--update.q", "1e12", "--update.rho", "1e-6"},
        {"--heuristic", "distance", "--heuristic.min_distance", "1e-6", "--beta", "50"},
        {"--update", "gaussian", "--update.sigma", "0.01", "--update.q", "1e12", "--update.psi", "1e12"}}) {
    std::vector<std::string> args = {"--map", map1,     "--start", "0,0",          "--goal",
                                     "19,19", "--ants", "5",       "--iterations", "5"};
    args.insert(args.end(), extreme.begin(), extreme.end());
    const auto r = test::acoplan(args);
    INFO(r.err);
    CHECK(r.exit_code == 0);
  }
  // A finite eta raised to beta may still overflow: said as the power's, with the bound.
  const auto power =
      test::acoplan({"--map", map1, "--start", "0,0", "--goal", "19,19", "--heuristic", "potential_field",
                     "--heuristic.a", "1e6", "--heuristic.min_distance", "1e-6", "--beta", "50"});
  CHECK(power.exit_code == 1);
  CHECK_THAT(power.err, Contains("eta^beta overflows on some edge") &&
                            Contains("at beta 50 eta must stay below 1462494") && !Contains("wrote inf"));
}

TEST_CASE("acoplan rejects unknown plugins, unknown options and out-of-range values", "[acoplan][bad-input]") {
  expect_error({"--update", "nope"}, "unknown update plugin 'nope'");
  expect_error({"--update.rhoo", "0.5"}, "unknown option '--update.rhoo'; did you mean '--update.rho'?");
  expect_error(
      {"--update.xi", "0.5"},
      "the update plugin 'max_min' has parameters: rho q p_best best_so_far_every restart_after restart_branching");
  expect_error({"--antz", "5"}, "did you mean '--ants'?");
  expect_error({"--ants", "0"}, "--ants: 0 is outside the range [1, 1000000]");
  expect_error({"--ants", "-3"}, "--ants: -3 is outside the range");
  expect_error({"--ants", "many"}, "--ants: 'many' is not a whole number");
  expect_error({"--update.rho", "1.5"}, "--update.rho: 1.5 is outside the range [1e-06, 1]");
  expect_error({"--update.rho", "-0.1"}, "--update.rho: -0.1 is outside the range [1e-06, 1]");
  expect_error({"--neighbourhood", "12"}, "--neighbourhood: '12' is not one of 4,8,16,6,18,26");
  // acoplan's own settings are checked by their tables.
  expect_error({"--repeat", "0"}, "--repeat: 0 is outside the range [1, 1000000]");
  expect_error({"--threads", "-1"}, "--threads: -1 is outside the range [0, 1024]");
  expect_error({"--json=maybe"}, "--json: 'maybe' is not a boolean (use true or false)");
  expect_error({"--irace-effort", "-1"}, "--irace-effort: -1 is outside the range [0, 1e+12]");
  expect_error({"stray"}, "stray");
  const auto config = test::temp_file("bad.ini", "ants = 10\n[update]\nrhoo = 0.2\n");
  expect_error({"--config", config.string()}, "unknown option '--update.rhoo'; did you mean '--update.rho'?");
  expect_error({"--config", "/nonexistent.ini"}, "/nonexistent.ini: cannot open the config file");
}

TEST_CASE("a plugin folder that is missing or is a file is refused by every host naming which",
          "[acoplan][bad-input]") {
  const std::string plugin = std::string(ACO_TEST_BAD_PLUGIN_DIR) + "/aco_update_wrong_abi.so";
  expect_error({"--plugin-dir", "/no/such/dir"}, "--plugin-dir /no/such/dir: no such folder");
  expect_error({"--plugin-dir", plugin, "--list-plugins"},
               "--plugin-dir " + plugin + ": a file, not a folder; give the folder it is in (--plugin-dir " +
                   ACO_TEST_BAD_PLUGIN_DIR + ")");
  const auto bench = test::run({ACO_TEST_ACOBENCH, "run", "no.yaml", "--plugin-dir", "/no/such/dir"});
  CHECK(bench.exit_code == 1);
  CHECK_THAT(bench.err, Contains("--plugin-dir /no/such/dir: no such folder"));
  const auto sim = test::run({ACO_TEST_ACOSIM, "no.yaml", "--plugin-dir", "/no/such/dir"});
  CHECK(sim.exit_code == 1);
  CHECK_THAT(sim.err, Contains("--plugin-dir /no/such/dir: no such folder"));
}

TEST_CASE("acoplan refuses a plugin built for another ABI version", "[acoplan][bad-input][abi]") {
  expect_error({"--plugin-dir", ACO_TEST_BAD_PLUGIN_DIR, "--update", "wrong_abi"},
               "plugin update/wrong_abi (" + std::string(ACO_TEST_BAD_PLUGIN_DIR) +
                   "/aco_update_wrong_abi.so): ABI 999, host expects " + std::to_string(aco::kPluginAbiVersion));
  const auto list = test::acoplan({"--plugin-dir", ACO_TEST_BAD_PLUGIN_DIR, "--list-plugins"});
  CHECK(list.exit_code == 0);
  CHECK_THAT(list.out, Contains("update/wrong_abi  UNUSABLE") && Contains("ABI 999"));
}

TEST_CASE("a plugin that throws anything, from its factory, a hook or a worker thread, is reported, not an abort",
          "[acoplan][bad-input][boundary]") {
  const std::string dir = ACO_TEST_FAULTY_PLUGIN_DIR;
  expect_error(
      {"--plugin-dir", dir, "--update", "throwing", "--update.in_factory", "true"},
      "plugin update/throwing (" + dir + "/aco_update_throwing.so) failed in its factory: an exception of type int");
  expect_error({"--plugin-dir", dir, "--update", "throwing", "--update.at_iteration", "3"},
               "plugin update/throwing (" + dir +
                   "/aco_update_throwing.so) failed in update() in iteration 3 (0-based, as Context::iteration): an "
                   "exception of type int");
  for (const char* threads : {"1", "2"}) {
    INFO(threads << " threads");
    expect_error(
        {"--plugin-dir", dir, "--heuristic", "throwing", "--threads", threads},
        "plugin heuristic/throwing (" + dir +
            "/aco_heuristic_throwing.so) failed in step_factors() in iteration 0 (0-based, as Context::iteration): "
            "an exception of type int");
  }
}

TEST_CASE("a plugin with an undefined symbol is refused when it loads, the symbol named",
          "[acoplan][bad-input][boundary]") {
  const std::string dir = ACO_TEST_FAULTY_PLUGIN_DIR;
  expect_error({"--plugin-dir", dir, "--update", "incomplete"},
               "plugin update/incomplete (" + dir + "/aco_update_incomplete.so): cannot be loaded: ");
  expect_error({"--plugin-dir", dir, "--update", "incomplete"},
               "undefined symbol: aco_fixture_function_nobody_defines");
}

TEST_CASE("acoplan --repeat runs consecutive seeds and summarises them", "[acoplan]") {
  const json j = run_json({"--repeat", "6", "--seed", "10", "--iterations", "30", "--corner-cutting"});
  REQUIRE(j["runs"].size() == 6);
  double sum = 0, sum_sq = 0;
  for (std::size_t i = 0; i < 6; ++i) {
    const auto& run = j["runs"][i];
    CHECK(run["seed"] == 10 + i);
    REQUIRE(run["solved"].get<bool>());
    sum += run["length"].get<double>();
  }
  const double mean = sum / 6;
  for (const auto& run : j["runs"]) sum_sq += std::pow(run["length"].get<double>() - mean, 2);
  const auto& s = j["summary"];
  CHECK(s["runs"] == 6);
  CHECK(s["solved"] == 6);
  CHECK(s["length"]["mean"].get<double>() == Approx(mean));
  CHECK(s["length"]["sd"].get<double>() == Approx(std::sqrt(sum_sq / 5)).margin(1e-12));
  CHECK(s["turns"].contains("max"));
  CHECK(j["config"]["update"] == "max_min");
  // Run 3 of the repetition is the same as a single run with its seed.
  json single = run_json({"--seed", "13", "--iterations", "30", "--corner-cutting"});
  CHECK(single["grid_path"] == j["runs"][3]["grid_path"]);
  const auto text = test::acoplan({"--repeat", "3", "--iterations", "10"});
  CHECK(text.exit_code == 0);
  CHECK_THAT(text.out, Contains("runs:     3 seeds (1..3), 3 solved") && Contains("best_iteration mean"));
}

// The recommended pipelines users start from (data/presets, docs/large-maps.md) must keep loading
// and planning; what they are worth is measured in docs/results.md, not here.
TEST_CASE("the shipped presets load and plan with the pipeline they document", "[acoplan][presets]") {
  const std::string room = (test::data_dir() / "maps/generated/room64-8-s2.map.scen").string();
  const json robust =
      run_json({"--config", (test::data_dir() / "presets/robust.ini").string(), "--scen", room, "--scen-index", "19"});
  CHECK(robust["solved"].get<bool>());
  CHECK(robust["grid_length"].get<double>() >= robust["optimal_length"].get<double>() - 1e-9);
  CHECK(robust["length"].get<double>() >= robust["any_angle_length"].get<double>() - 1e-9);
  CHECK(robust["config"]["smoother"] == "taut");
  CHECK(robust["config"]["heuristic"] == "progress");
  CHECK(robust["config"]["update"] == "max_min");
  CHECK(robust["config"]["deadlock"] == "backtrack");
  CHECK(robust["config"]["fill-dead-ends"] == true);
  CHECK(robust["config"]["local-search"] == "straighten");
  CHECK(robust["config"]["search"] == "single");
  CHECK(robust["config"]["band-search"] == 16);

  const std::string hills = (test::data_dir() / "terrain/generated/hills40-s101.asc").string();
  const json terrain = run_json({"--config", (test::data_dir() / "presets/terrain.ini").string(), "--map", hills,
                                 "--start", "0,0", "--goal", "39,39"});
  CHECK(terrain["solved"].get<bool>());
  CHECK(terrain["config"]["search"] == "bidirectional");
  CHECK(terrain["length"].get<double>() >= terrain["optimal_length"].get<double>() - 1e-9);
}

TEST_CASE("acoplan in-process: the command line resolves into one RunSpec, run() writes the result", "[acoplan]") {
  const std::vector<std::string> args = {
      "acoplan", "--map",  map1, "--start",      "0,0", "--goal", "19,19", "--update",  "max_min", "--update.rho",
      "0.05",    "--ants", "12", "--iterations", "8",   "--seed", "5",     "--threads", "1",       "--json"};
  std::vector<const char*> argv;
  for (const auto& a : args) argv.push_back(a.c_str());
  acoplan::Request request = acoplan::parse_command_line(static_cast<int>(argv.size()), argv.data());
  CHECK(request.action == acoplan::Request::Action::plan);
  CHECK(request.run.pipeline.at("update").plugin == "max_min");
  CHECK(request.run.pipeline.at("update").parameters.real("rho") == 0.05);
  CHECK(request.run.colony.ants == 12);
  CHECK(request.run.problem.goal == aco::Cell{19, 19});
  CHECK(request.host.threads == 1);
  CHECK(request.output.json);
  std::ostringstream out;
  const int status = acoplan::run(request, out);
  CHECK((status == 0 || status == aco::kExitNoPath));
  const json j = json::parse(out.str());
  CHECK(j["config"]["update.rho"] == 0.05);
  CHECK(j["seed"] == 5);
  CHECK(j["convergence"].size() == 8);
  // The same run through the binary gives the same result.
  std::vector<std::string> binary_args(args.begin() + 1, args.end());
  const json binary = run_json({binary_args.begin(), binary_args.end() - 1});
  CHECK(without_times(binary) == without_times(j));
}

TEST_CASE("every command prints its version and every acobench command its usage", "[acoplan][acobench][acosim]") {
  for (const std::string program : {ACO_TEST_ACOPLAN, ACO_TEST_ACOBENCH, ACO_TEST_ACOSIM}) {
    const auto r = test::run({program, "--version"});
    CHECK(r.exit_code == 0);
    const std::string name = std::filesystem::path(program).filename().string();
    CHECK_THAT(r.out, StartsWith(name + " ") && Contains("(commit ") && Contains(" build, "));
  }
  for (const std::string command : {"run", "merge", "report"}) {
    const auto r = test::run({ACO_TEST_ACOBENCH, command, "--help"});
    CHECK(r.exit_code == 0);
    CHECK_THAT(r.out, Contains("acobench " + command + " "));
  }
}

TEST_CASE("output files are written whole into folders made for them and errors name the file", "[acoplan][output]") {
  const auto folder = test::temp_file("placeholder", "").parent_path() / "new/sub";
  const auto svg = folder / "run.svg";
  const auto r = test::acoplan({"--iterations", "3", "--svg", svg.string()});
  CHECK(r.exit_code == 0);
  std::ifstream in(svg);
  const std::string picture((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK_THAT(picture, Contains("<svg") && Contains("</svg>\n"));
  // Replaced whole, and nothing left beside it.
  aco::write_output_file(svg, "second");
  std::ifstream again(svg);
  CHECK(std::string((std::istreambuf_iterator<char>(again)), std::istreambuf_iterator<char>()) == "second");
  CHECK(std::distance(std::filesystem::directory_iterator(folder), std::filesystem::directory_iterator()) == 1);
  // A device is written in place, never replaced.
  CHECK_NOTHROW(aco::write_output_file("/dev/null", "text"));
  CHECK(std::filesystem::is_character_file("/dev/null"));

  CHECK_THROWS_WITH(aco::write_output_file(folder, "x", "SVG"),
                    folder.string() + ": cannot write the SVG file: it is a folder");
  const auto under_file = svg / "x.csv";
  CHECK_THROWS_WITH(
      aco::write_output_file(under_file, "x", "trajectory CSV"),
      Catch::StartsWith(under_file.string() + ": cannot write the trajectory CSV file: cannot make its folder " +
                        svg.string() + ": "));
  const auto refused = test::acoplan({"--iterations", "3", "--svg", folder.string()});
  CHECK(refused.exit_code == 1);
  CHECK_THAT(refused.err, Contains(folder.string() + ": cannot write the SVG file: it is a folder"));
}

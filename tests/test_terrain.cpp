// Terrain maps: the ESRI ASCII and PGM height loaders, slope limits, 3D step costs, knight moves
// and line of sight on terrain, the terrain picture, and acoplan on the paper 000 look-alikes.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "aco/error.hpp"
#include "aco/graph.hpp"
#include "aco/engine/map_io.hpp"
#include "aco/drawing/svg.hpp"
#include "aco/terrain.hpp"
#include "support.hpp"

using Catch::Contains;

namespace {

aco::TerrainMap esri(const std::string& text, const aco::TerrainOptions& options = {}) {
  std::istringstream in(text);
  return aco::read_esri_ascii(in, "inline.asc", options);
}

// A w x h terrain from rows of heights (row 0 at the top); NaN = no data.
aco::TerrainMap terrain(const std::vector<std::vector<double>>& rows, double cell_size = 1, double max_slope = 90) {
  std::vector<double> heights;
  for (const auto& row : rows) heights.insert(heights.end(), row.begin(), row.end());
  return aco::TerrainMap(static_cast<int>(rows.front().size()), static_cast<int>(rows.size()), cell_size, heights,
                         max_slope, "test terrain");
}

constexpr double kNoData = std::numeric_limits<double>::quiet_NaN();

const std::string kGood =
    "ncols 3\n"
    "nrows 2\n"
    "xllcorner 100\n"
    "yllcorner 200.5\n"
    "cellsize 10\n"
    "NODATA_value -9999\n"
    "1 2 3\n"
    "4 -9999 6.5\n";

std::string error_of(const std::string& text) {
  try {
    esri(text);
  } catch (const aco::Error& e) {
    return e.what();
  }
  return "no error";
}

const std::string epf20_scen = (test::data_dir() / "terrain/epf20.asc.scen").string();

}  // namespace

TEST_CASE("ESRI ASCII grid: heights, cell size, georeference and NODATA", "[terrain]") {
  const aco::TerrainMap map = esri(kGood);
  CHECK(map.width() == 3);
  CHECK(map.height() == 2);
  CHECK(map.cell_size() == 10);
  CHECK(map.name() == "inline.asc");
  CHECK(map.lower_left() == Eigen::Vector2d(100, 200.5));
  // First row of the file = row 0 (north), positions in the file's units.
  CHECK(map.elevation({0, 0}) == 1);
  CHECK(map.elevation({2, 1}) == 6.5);
  CHECK(map.position({2, 1}) == Eigen::Vector3d(20, 10, 6.5));
  CHECK_FALSE(map.has_data({1, 1}));
  CHECK_FALSE(map.passable({1, 1}));
  CHECK(map.blocked_reason({1, 1}) == "NODATA");
  CHECK(map.passable({0, 1}));
  CHECK(map.blocked_reason({0, 1}).empty());
  CHECK(map.blocked_reason({3, 0}) == "outside the map");

  SECTION("keys in any order and any case, centre georeference, default NODATA -9999") {
    const aco::TerrainMap m = esri("CELLSIZE 2\nXLLCENTER 11\nNROWS 1\nyllcenter 21\nNcols 2\n-9999 5\n");
    CHECK(m.width() == 2);
    CHECK(m.height() == 1);
    CHECK(m.lower_left() == Eigen::Vector2d(10, 20));  // centre minus half a cell
    CHECK_FALSE(m.has_data({0, 0}));
    CHECK(m.elevation({1, 0}) == 5);
  }
  SECTION("values need not be one row per line") {
    const aco::TerrainMap m = esri("ncols 2\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 1\n1 2 3\n\n4\n");
    CHECK(m.elevation({0, 1}) == 3);
    CHECK(m.elevation({1, 1}) == 4);
  }
}

TEST_CASE("ESRI ASCII grid: malformed files name the line and the problem", "[terrain]") {
  const std::string header = "ncols 20\nnrows 20\nxllcorner 0\nyllcorner 0\ncellsize 1\n";
  std::string values;
  for (int i = 0; i < 399; ++i) values += "1 ";
  CHECK_THAT(error_of(header + values + "\n"), Contains("inline.asc:6: expected 400 heights") && Contains("found 399"));
  CHECK_THAT(error_of(header + values + "\n1 1\n"),
             Contains("inline.asc:7: expected 400 heights") && Contains("found 401"));
  CHECK_THAT(error_of(header + "1 2 x3\n"), Contains("inline.asc:6: height 'x3' is not a number"));
  CHECK_THAT(error_of(header + "1 nan\n"), Contains("inline.asc:6: height 'nan' is not a number"));
  CHECK_THAT(error_of("ncols 2\nnrows 1\nxllcorner 0\nyllcorner 0\ncellsize 0\n1 2\n"),
             Contains("inline.asc:5: cellsize '0' is not positive"));
  CHECK_THAT(error_of("ncols -2\nnrows 1\nxllcorner 0\nyllcorner 0\ncellsize 1\n1 2\n"),
             Contains("inline.asc:1: ncols '-2' is not a whole number"));
  CHECK_THAT(error_of("ncols 2\nnrows 1\nxllcorner west\n"),
             Contains("inline.asc:3: xllcorner 'west' is not a number"));
  CHECK_THAT(error_of("ncols 2\nnrows 1\nxllcorner 0\nyllcorner 0\n1 2\n"),
             Contains("inline.asc:5: header lacks 'cellsize'"));
  CHECK_THAT(error_of("ncols 2\nnrows 1\nxllcorner 0\nyllcorner 0\ncellsize 1\nrows 3\n1 2\n"),
             Contains("inline.asc:6: unknown header key 'rows'"));
  CHECK_THAT(error_of("ncols 2\nncols 2\n"), Contains("inline.asc:2: header key 'ncols' is given twice"));
  CHECK_THAT(error_of("ncols 2\nnrows 1\nxllcorner 0\nxllcenter 0\nyllcorner 0\ncellsize 1\n1 2\n"),
             Contains("exactly one of 'xllcorner' and 'xllcenter'"));
  CHECK_THAT(error_of("ncols 2 3\n"), Contains("inline.asc:1: header line 'ncols 2 3' should be 'ncols VALUE'"));
  CHECK_THAT(error_of("ncols 2\nnrows 1\nxllcorner 0\nyllcorner 0\ncellsize 1\n"),
             Contains("no heights after the header"));
  // Heights and cell sizes whose 3D step lengths would overflow.
  CHECK_THAT(error_of("ncols 2\nnrows 1\nxllcorner 0\nyllcorner 0\ncellsize 1\n0 1e308\n"),
             Contains("the height 1e+308 of cell (1,0) is beyond +-1e+12"));
  CHECK_THAT(error_of("ncols 2\nnrows 1\nxllcorner 0\nyllcorner 0\ncellsize 1e300\n0 1\n"),
             Contains("cell size 1e+300 is not a positive number up to 1e+12"));
}

TEST_CASE("PGM height images: height = grey * scale, cell size from the options", "[terrain]") {
  const auto file = test::temp_file("heights.pgm", "P2\n3 2\n1000\n0 10 20\n30 1000 50\n");
  const auto map = aco::load_map(file, {90, 0.5, 4});
  const auto* t = dynamic_cast<const aco::TerrainMap*>(map.get());
  REQUIRE(t != nullptr);
  CHECK(t->width() == 3);
  CHECK(t->height() == 2);
  CHECK(t->position({1, 1}) == Eigen::Vector3d(4, 4, 500));
  CHECK(t->position({2, 0}) == Eigen::Vector3d(8, 0, 10));
  REQUIRE_THROWS_WITH(aco::load_height_pgm(file, {90, 0, 1}),
                      Contains("heights.pgm: height scale") && Contains("not a positive number"));
  REQUIRE_THROWS_WITH(aco::load_height_pgm(file, {90, 1, -1}),
                      Contains("heights.pgm: cell size") && Contains("not a positive number"));
}

TEST_CASE("Slope limit: steep steps refused both ways, gentle ones allowed, steep cells blocked", "[terrain]") {
  // Cell size 1. Between columns 0 and 1 the rise is 0.5 (26.6 deg), between 1 and 2 it is 2 (63.4 deg).
  const auto map = terrain({{0, 0.5, 2.5}, {0, 0.5, 2.5}}, 1, 45);
  CHECK(map.step_allowed({0, 0}, {1, 0}));
  CHECK(map.step_allowed({1, 0}, {0, 0}));
  CHECK_FALSE(map.step_allowed({1, 0}, {2, 0}));
  CHECK_FALSE(map.step_allowed({2, 0}, {1, 0}));
  // A diagonal step's run is sqrt(2): rise 2 over 1.414 is 54.7 deg, still too steep.
  CHECK_FALSE(map.step_allowed({1, 0}, {2, 1}));
  // Cell slopes: (0,0) one-sided 0.5 -> 26.6 deg; (1,0) central (2.5 - 0) / 2 -> 51.3 deg; (2,0) one-sided 2 -> 63.4
  // deg.
  CHECK(map.slope_deg({0, 0}) == Approx(std::atan(0.5) * 180 / M_PI));
  CHECK(map.slope_deg({1, 0}) == Approx(std::atan(1.25) * 180 / M_PI));
  CHECK(map.passable({0, 0}));
  CHECK_FALSE(map.passable({1, 0}));
  CHECK(map.blocked_reason({1, 0}) == "too steep: slope 51.3 deg > max 45 deg");
  CHECK(map.blocked_reason({2, 1}) == "too steep: slope 63.4 deg > max 45 deg");

  SECTION("90 deg means no limit") {
    const auto open = terrain({{0, 0.5, 2.5}, {0, 0.5, 2.5}}, 1, 90);
    CHECK(open.step_allowed({1, 0}, {2, 0}));
    CHECK(open.passable({2, 0}));
  }
  SECTION("the cell slope is one-sided next to NODATA and the graph has no edge up the cliff") {
    const auto holed = terrain({{0, kNoData, 0, 3, 3}}, 1, 45);
    CHECK(holed.slope_deg({0, 0}) == 0);  // no neighbour data along x, none along y: flat
    CHECK(holed.slope_deg({2, 0}) == Approx(std::atan(3.0) * 180 / M_PI));
    const aco::Graph g = aco::build_graph(holed, {aco::Neighbourhood::eight, false});
    CHECK(g.find_edge(g.node({2, 0}), g.node({3, 0})) < 0);
    CHECK(g.find_edge(g.node({3, 0}), g.node({2, 0})) < 0);
    CHECK(g.degree(g.node({0, 0})) == 0);
  }
  REQUIRE_THROWS_WITH(terrain({{0, 1}}, 1, 91), Contains("test terrain: maximum slope") && Contains("outside [0, 90]"));
}

TEST_CASE("Terrain step costs are 3D distances", "[terrain]") {
  const auto map = terrain({{10, 13, 10}, {14, 10, 10}}, 4);
  const aco::Graph g = aco::build_graph(map, {aco::Neighbourhood::eight, false});
  const auto cost = [&](aco::Cell a, aco::Cell b) {
    const aco::EdgeId e = g.find_edge(g.node(a), g.node(b));
    REQUIRE(e >= 0);
    return g.cost(e);
  };
  CHECK(cost({0, 0}, {1, 0}) == Approx(5));  // run 4, rise 3
  CHECK(cost({1, 0}, {0, 0}) == Approx(5));
  CHECK(cost({0, 0}, {1, 1}) == Approx(std::sqrt(32.0)));  // diagonal, level
  CHECK(cost({1, 1}, {0, 1}) == Approx(std::sqrt(16.0 + 16.0)));  // run 4, rise 4
  CHECK(cost({2, 0}, {1, 1}) == Approx(std::sqrt(32.0)));
}

TEST_CASE("Knight moves on terrain need the cells they cross passable", "[terrain]") {
  const aco::GraphOptions sixteen{aco::Neighbourhood::sixteen, false};
  auto has_edge = [](const aco::Graph& g, aco::Cell a, aco::Cell b) { return g.find_edge(g.node(a), g.node(b)) >= 0; };
  SECTION("NODATA") {
    // (0,0) -> (2,1) and (0,1) -> (2,0) cross (1,0) and (1,1).
    const aco::Graph level = aco::build_graph(terrain({{5, 5, 5}, {5, 5, 5}}), sixteen);
    CHECK(has_edge(level, {0, 0}, {2, 1}));
    const aco::Graph holed = aco::build_graph(terrain({{5, kNoData, 5}, {5, 5, 5}}), sixteen);
    CHECK_FALSE(has_edge(holed, {0, 0}, {2, 1}));
    CHECK_FALSE(has_edge(holed, {0, 1}, {2, 0}));
  }
  SECTION("too steep") {
    // The peak at (1,0) makes (1,1) too steep (central difference 3 / 2: 56.3 deg > 45); the
    // knight move (0,1) -> (2,2) crosses (1,1) and (1,2), and both its ends are level and flat.
    const std::vector<std::vector<double>> rows = {{0, 3, 0, 0}, {0, 0, 0, 0}, {0, 0, 0, 0}};
    const auto steep = terrain(rows, 1, 45);
    REQUIRE_FALSE(steep.passable({1, 1}));
    REQUIRE(steep.passable({0, 1}));
    REQUIRE(steep.passable({2, 2}));
    CHECK_FALSE(has_edge(aco::build_graph(steep, sixteen), {0, 1}, {2, 2}));
    CHECK(has_edge(aco::build_graph(terrain(rows, 1, 90), sixteen), {0, 1}, {2, 2}));
  }
}

TEST_CASE("The 16-neighbourhood needs room for a knight move", "[terrain][graph]") {
  const aco::GraphOptions sixteen{aco::Neighbourhood::sixteen, false};
  REQUIRE_THROWS_WITH(
      aco::build_graph(test::grid({"..", ".."}), sixteen),
      "16-neighbourhood needs a map at least 3 cells long in one direction and 2 in the other; test grid is 2x2");
  REQUIRE_THROWS_WITH(aco::build_graph(test::grid({"....."}), sixteen), Contains("test grid is 5x1"));
  REQUIRE_THROWS_WITH(aco::build_graph(terrain({{1}, {2}, {3}}), sixteen), Contains("test terrain is 1x3"));
  CHECK(aco::build_graph(test::grid({"...", "..."}), sixteen).num_edges() > 0);
  CHECK(aco::build_graph(test::grid({"..", "..", ".."}), sixteen).num_edges() > 0);
  CHECK(aco::build_graph(test::grid({".."}), {aco::Neighbourhood::eight, false}).num_edges() == 2);
}

TEST_CASE("line_of_sight respects the slope limit between consecutive cells", "[terrain][line_of_sight]") {
  // A ridge at column 2: the climb from column 1 is 1.5 over one cell (56.3 deg), its own slope
  // is 0 (central difference of equal neighbours).
  const auto ridge = terrain({{0, 0, 1.5, 0, 0}, {0, 0, 1.5, 0, 0}, {0, 0, 1.5, 0, 0}}, 1, 60);
  const auto limited = terrain({{0, 0, 1.5, 0, 0}, {0, 0, 1.5, 0, 0}, {0, 0, 1.5, 0, 0}}, 1, 50);
  for (bool cc : {false, true}) {
    REQUIRE(limited.passable({2, 1}));
    CHECK(aco::line_of_sight(ridge, {0, 1}, {4, 1}, cc));
    CHECK_FALSE(aco::line_of_sight(limited, {0, 1}, {4, 1}, cc));
    CHECK_FALSE(aco::line_of_sight(limited, {4, 0}, {0, 2}, cc));
    CHECK(aco::line_of_sight(limited, {0, 0}, {1, 2}, cc));  // never reaches the ridge
    // Same answers as on an occupancy grid where the ridge is not there at all.
    CHECK(aco::line_of_sight(ridge, {0, 0}, {4, 2}, cc) ==
          aco::line_of_sight(test::grid({".....", ".....", "....."}), {0, 0}, {4, 2}, cc));
  }
}

TEST_CASE("The SVG of a terrain shows shading, contours and a height legend", "[terrain][svg]") {
  const auto map = terrain({{800, 850, 900, 950}, {820, 870, kNoData, 990}, {840, 890, 940, 1000}}, 10);
  const aco::Graph g = aco::build_graph(map, {aco::Neighbourhood::eight, false});
  aco::RunPicture picture;
  picture.start = g.node({0, 0});
  picture.goal = g.node({3, 2});
  picture.grid_path = {g.node({0, 0}), g.node({1, 1}), g.node({2, 2}), g.node({3, 2})};
  picture.path = aco::Waypoints{g.position(picture.grid_path[0]), g.position(picture.grid_path[3])};
  const std::string svg = aco::render_svg(g, picture);
  CHECK_THAT(svg, Contains("<g id=\"terrain\"") && Contains("<g id=\"contours\"") && Contains("class=\"contour\"") &&
                      Contains("id=\"height-legend\"") && Contains(">800</text>") && Contains(">1000</text>") &&
                      Contains("url(#height-ramp)"));
  // Shading: one colour band per height step (heights here span 4 bands or more).
  const auto shading =
      svg.substr(svg.find("<g id=\"terrain\""), svg.find("<g id=\"contours\"") - svg.find("<g id=\"terrain\""));
  std::set<std::string> fills;
  for (auto at = shading.find("fill=\"#"); at != std::string::npos; at = shading.find("fill=\"#", at + 1))
    fills.insert(shading.substr(at + 6, 7));
  CHECK(fills.size() >= 4);
  // Paths in cells, not in map units: the goal is drawn at cell (3,2), not at (30,20).
  CHECK_THAT(svg, Contains("cx=\"3\" cy=\"2\""));
  CHECK_THAT(svg,
             Contains("<g id=\"obstacles\" fill=\"#333\" shape-rendering=\"crispEdges\">\n<rect x=\"1.5\" y=\"0.5\""));
  // The map's legend under the height legend, which names the blocked cells itself.
  const std::string map_legend = svg.substr(svg.find("<g id=\"map-legend\""));
  CHECK_THAT(map_legend, Contains(">start<") && Contains(">path after the smoother<") && !Contains("blocked"));
  CHECK(test::texts_outside_view_box(svg).empty());

  SECTION("flat maps are drawn as before") {
    const auto grid = test::grid({"...", ".#."});
    const aco::Graph flat = aco::build_graph(grid, {});
    aco::RunPicture p;
    p.goal = 2;
    const std::string plain = aco::render_svg(flat, p);
    CHECK_THAT(plain, !Contains("terrain") && !Contains("contour") && !Contains("height-legend"));
    const auto level = terrain({{5, 5, 5}, {5, 5, 5}});
    CHECK_THAT(aco::render_svg(aco::build_graph(level, {}), p), !Contains("contour"));
  }
}

TEST_CASE("A map drawn alone is the run picture's map, without marks, its legend inside", "[terrain][svg]") {
  const auto map = terrain({{800, 850, 900, 950}, {820, 870, kNoData, 990}, {840, 890, 940, 1000}}, 10);
  const aco::Graph g = aco::build_graph(map, {aco::Neighbourhood::eight, false});
  const std::string alone = aco::render_map_svg(g);
  aco::RunPicture run;
  run.goal = g.node({3, 2});
  for (const char* id : {"terrain", "contours", "obstacles"}) {
    INFO(id);
    CHECK(test::svg_group(alone, id) == test::svg_group(aco::render_svg(g, run), id));
  }
  CHECK_THAT(alone, !Contains("<circle") && !Contains("convergence") && !Contains("map-legend") &&
                        Contains("id=\"height-legend\""));
  CHECK(test::texts_outside_view_box(alone).empty());
}

TEST_CASE("acoplan plans on the paper 000 terrain look-alike", "[terrain][acoplan]") {
  // The grid path's waypoints (terrain's taut smoother follows the surface between cells).
  const auto r = test::acoplan({"--scen", epf20_scen, "--json", "--update", "acs", "--smoother", "none"});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto j = nlohmann::json::parse(r.out);
  REQUIRE(j["solved"].get<bool>());
  const auto map = aco::load_esri_ascii(test::data_dir() / "terrain/epf20.asc", {});
  const auto scenarios = aco::load_scenarios(epf20_scen);
  CHECK(j["optimal_length"].get<double>() == Approx(scenarios.at(0).optimal_length).epsilon(1e-7));
  CHECK(j["length"].get<double>() >= j["optimal_length"].get<double>() - 1e-9);
  for (const auto& p : j["path"]) {
    REQUIRE(p.size() == 3);
    const aco::Cell c{static_cast<int>(std::lround(p[0].get<double>() / 10)),
                      static_cast<int>(std::lround(p[1].get<double>() / 10))};
    CHECK(p[2].get<double>() == map.elevation(c));
  }
  CHECK(j["path"].front() == nlohmann::json::array({0.0, 100.0, map.elevation({0, 10})}));
}

TEST_CASE("acoplan on terrain: blocked start or goal and malformed files are clear errors", "[terrain][acoplan]") {
  const auto asc = test::temp_file("holed.asc",
                                   "ncols 4\nnrows 3\nxllcorner 0\nyllcorner 0\ncellsize 1\nNODATA_value -1\n"
                                   "0 0 0 0\n-1 0 0 5\n0 0 0 5\n");
  auto expect_error = [](const std::vector<std::string>& args, const std::string& expected) {
    const auto r = test::acoplan(args);
    INFO("stderr: " << r.err);
    CHECK(r.exit_code == 1);
    CHECK(r.out.empty());
    CHECK_THAT(r.err, Contains(expected));
  };
  expect_error({"--map", asc.string(), "--start", "0,1", "--goal", "2,0"},
               "start (0,1) is blocked: NODATA (" + asc.string() + ")");
  expect_error({"--map", asc.string(), "--start", "0,0", "--goal", "3,1", "--max-slope", "60"},
               "goal (3,1) is blocked: too steep: slope 79.9 deg > max 60 deg");  // atan(hypot(5, 2.5))
  expect_error({"--map", asc.string(), "--start", "0,0", "--goal", "3,1", "--max-slope", "91"}, "--max-slope");
  const auto bad = test::temp_file("bad.asc", "ncols 2\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 1\n1 2\n3 x\n");
  expect_error({"--map", bad.string(), "--start", "0,0", "--goal", "1,1"},
               bad.string() + ":7: height 'x' is not a number");
  // Without a slope limit the steep cell is fine, and the path ends on it.
  const auto r = test::acoplan({"--map", asc.string(), "--start", "0,0", "--goal", "3,1", "--planner", "astar"});
  CHECK(r.exit_code == 0);
}

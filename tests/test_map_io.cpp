// Map and scenario loaders: Moving AI .map/.scen, 0/1 matrices, ROS map_server YAML + PGM.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "aco/error.hpp"
#include "aco/engine/map_io.hpp"
#include "support.hpp"

namespace fs = std::filesystem;

namespace {

aco::OccupancyGrid movingai(const std::string& text, const std::string& name = "inline.map") {
  std::istringstream in(text);
  return aco::read_movingai_map(in, name);
}

aco::OccupancyGrid matrix(const std::string& text, const std::string& name = "inline.txt") {
  std::istringstream in(text);
  return aco::read_matrix_map(in, name);
}

std::vector<aco::Scenario> scenarios(const std::string& text, const std::string& name = "inline.scen") {
  std::istringstream in(text);
  return aco::read_scenarios(in, name);
}

// Writes a file (binary, exact bytes) next to another one.
fs::path write_beside(const fs::path& first, const std::string& name, const std::string& content) {
  const fs::path file = first.parent_path() / name;
  std::ofstream out(file, std::ios::binary);
  out.write(content.data(), static_cast<std::streamsize>(content.size()));
  return file;
}

std::string bytes(std::initializer_list<int> values) {
  std::string s;
  for (int v : values) s.push_back(static_cast<char>(static_cast<unsigned char>(v)));
  return s;
}

// A YAML file plus its PGM image in one temporary folder; returns the YAML path.
fs::path ros_map(const std::string& yaml, const std::string& pgm_name, const std::string& pgm) {
  const fs::path y = test::temp_file("map.yaml", yaml);
  write_beside(y, pgm_name, pgm);
  return y;
}

std::size_t count_lines(const fs::path& file) {
  std::ifstream in(file);
  std::size_t n = 0;
  for (std::string line; std::getline(in, line);)
    if (line.find_first_not_of(" \t\r") != std::string::npos) ++n;
  return n;
}

const std::string kMovingAiHeader = "type octile\nheight 2\nwidth 4\nmap\n";

}  // namespace

// ---------------------------------------------------------------------------------------------
// Moving AI maps

TEST_CASE("Moving AI arena.map loads with the right size and cells", "[map_io]") {
  const fs::path file = test::data_dir() / "maps/movingai/arena.map";
  std::ifstream in(file);
  REQUIRE(in);
  const aco::OccupancyGrid g = aco::read_movingai_map(in, file.string());
  CHECK(g.width() == 49);
  CHECK(g.height() == 49);
  CHECK(g.name() == file.string());
  // Row 0 is all trees.
  for (int x = 0; x < 49; ++x) CHECK_FALSE(g.passable({x, 0}));
  // Row 1: "TTT............TTTT.TTT...TTTT.TTTT............TT"
  CHECK(g.blocked({0, 1}));
  CHECK(g.blocked({2, 1}));
  CHECK(g.passable({3, 1}));
  CHECK(g.blocked({15, 1}));
  CHECK(g.passable({19, 1}));
  CHECK(g.blocked({47, 1}));
  // Row 7: "T.......................TT......................T"
  CHECK(g.passable({1, 7}));
  CHECK(g.passable({23, 7}));
  CHECK(g.blocked({24, 7}));
  CHECK(g.blocked({25, 7}));
  CHECK(g.passable({26, 7}));
  CHECK(g.blocked({48, 7}));
  // Outside the map is never passable.
  CHECK_FALSE(g.passable({-1, 3}));
  CHECK_FALSE(g.passable({49, 3}));
  CHECK_FALSE(g.passable({3, 49}));
  // The file has 2054 '.' and 347 'T'.
  int free = 0;
  for (int y = 0; y < 49; ++y)
    for (int x = 0; x < 49; ++x) free += g.passable({x, y}) ? 1 : 0;
  CHECK(free == 2054);
}

TEST_CASE("Moving AI passable and blocked characters", "[map_io]") {
  const aco::OccupancyGrid g = movingai(kMovingAiHeader + ".GS@\nOTW.\n");
  REQUIRE(g.width() == 4);
  REQUIRE(g.height() == 2);
  CHECK(g.passable({0, 0}));  // .
  CHECK(g.passable({1, 0}));  // G
  CHECK(g.passable({2, 0}));  // S
  CHECK(g.blocked({3, 0}));  // @
  CHECK(g.blocked({0, 1}));  // O
  CHECK(g.blocked({1, 1}));  // T
  CHECK(g.blocked({2, 1}));  // W
  CHECK(g.passable({3, 1}));  // .
}

TEST_CASE("Moving AI header order, CRLF line ends and trailing blank lines are accepted", "[map_io]") {
  SECTION("header keys in another order") {
    const auto g = movingai("width 3\ntype octile\nheight 1\nmap\n.@.\n");
    CHECK(g.width() == 3);
    CHECK(g.height() == 1);
    CHECK(g.blocked({1, 0}));
  }
  SECTION("Windows line ends") {
    const auto g = movingai("type octile\r\nheight 2\r\nwidth 2\r\nmap\r\n.@\r\n@.\r\n");
    CHECK(g.width() == 2);
    CHECK(g.passable({0, 0}));
    CHECK(g.blocked({1, 0}));
    CHECK(g.blocked({0, 1}));
    CHECK(g.passable({1, 1}));
  }
  SECTION("blank lines after the rows") {
    const auto g = movingai(kMovingAiHeader + "....\n@@@@\n\n  \n");
    CHECK(g.height() == 2);
    CHECK(g.blocked({2, 1}));
  }
}

TEST_CASE("Malformed Moving AI maps are rejected with a precise message", "[map_io]") {
  SECTION("wrong header keyword") {
    REQUIRE_THROWS_AS(movingai("typo octile\nheight 2\nwidth 4\nmap\n....\n....\n", "bad.map"), aco::Error);
    REQUIRE_THROWS_WITH(movingai("typo octile\nheight 2\nwidth 4\nmap\n....\n....\n", "bad.map"),
                        Catch::Contains("bad.map:1:") && Catch::Contains("bad header line 'typo octile'"));
  }
  SECTION("unsupported map type") {
    REQUIRE_THROWS_WITH(movingai("type hex\nheight 2\nwidth 4\nmap\n....\n....\n", "bad.map"),
                        Catch::Contains("bad.map:1:") && Catch::Contains("map type 'hex' is not supported"));
  }
  SECTION("missing width") {
    REQUIRE_THROWS_WITH(movingai("type octile\nheight 2\nmap\n....\n....\n", "bad.map"),
                        Catch::Contains("bad.map:3:") && Catch::Contains("lacks a 'type', 'height' or 'width'"));
  }
  SECTION("missing type") {
    REQUIRE_THROWS_WITH(movingai("height 2\nwidth 4\nmap\n....\n....\n"),
                        Catch::Contains("lacks a 'type', 'height' or 'width'"));
  }
  SECTION("non-numeric height") {
    REQUIRE_THROWS_WITH(
        movingai("type octile\nheight two\nwidth 4\nmap\n....\n....\n", "bad.map"),
        Catch::Contains("bad.map:2:") && Catch::Contains("height 'two'") && Catch::Contains("not a whole number"));
  }
  SECTION("zero or negative width") {
    REQUIRE_THROWS_WITH(movingai("type octile\nheight 2\nwidth 0\nmap\n"), Catch::Contains("width '0'"));
    REQUIRE_THROWS_WITH(movingai("type octile\nheight 2\nwidth -4\nmap\n"), Catch::Contains("width '-4'"));
  }
  SECTION("row of the wrong length") {
    REQUIRE_THROWS_WITH(movingai(kMovingAiHeader + "....\n...\n", "bad.map"),
                        Catch::Contains("bad.map:6:") && Catch::Contains("row 1 has 3 characters, expected 4"));
    REQUIRE_THROWS_WITH(movingai(kMovingAiHeader + ".....\n....\n"), Catch::Contains("row 0 has 5 characters"));
  }
  SECTION("unknown character") {
    REQUIRE_THROWS_WITH(
        movingai(kMovingAiHeader + "....\n..x.\n", "bad.map"),
        Catch::Contains("bad.map:6:") && Catch::Contains("unknown character 'x'") && Catch::Contains("column 2"));
  }
  SECTION("truncated map") {
    REQUIRE_THROWS_WITH(movingai("type octile\nheight 3\nwidth 4\nmap\n....\n....\n"),
                        Catch::Contains("truncated map") && Catch::Contains("expected 3 rows, found 2"));
  }
  SECTION("text after the rows") {
    REQUIRE_THROWS_WITH(movingai(kMovingAiHeader + "....\n....\n\n....\n", "bad.map"),
                        Catch::Contains("bad.map:8:") && Catch::Contains("unexpected text after the 2 map rows"));
  }
  SECTION("empty input") {
    REQUIRE_THROWS_AS(movingai(""), aco::Error);
    REQUIRE_THROWS_WITH(movingai("", "empty.map"), Catch::Contains("empty.map") && Catch::Contains("truncated header"));
  }
  SECTION("header without 'map' line") {
    REQUIRE_THROWS_WITH(movingai("type octile\nheight 2\nwidth 4\n"), Catch::Contains("truncated header"));
  }
}

// ---------------------------------------------------------------------------------------------
// 0/1 matrices

TEST_CASE("Matrix maps: 0 free, 1 blocked, row 0 at the top", "[map_io]") {
  const auto g = matrix("0 1 0\n1 0 0\n");
  REQUIRE(g.width() == 3);
  REQUIRE(g.height() == 2);
  CHECK(g.passable({0, 0}));
  CHECK(g.blocked({1, 0}));
  CHECK(g.passable({2, 0}));
  CHECK(g.blocked({0, 1}));
  CHECK(g.passable({1, 1}));
  CHECK(g.passable({2, 1}));
  // Tabs, extra spaces, CRLF and blank lines around the matrix are fine.
  const auto h = matrix("\n  1\t0 \r\n0   1\r\n\n\n");
  REQUIRE(h.width() == 2);
  REQUIRE(h.height() == 2);
  CHECK(h.blocked({0, 0}));
  CHECK(h.passable({1, 0}));
  CHECK(h.passable({0, 1}));
  CHECK(h.blocked({1, 1}));
}

TEST_CASE("The classic map1.txt loads as a 20x20 matrix", "[map_io]") {
  const fs::path file = test::data_dir() / "maps/classic20/map1.txt";
  std::ifstream in(file);
  REQUIRE(in);
  const auto g = aco::read_matrix_map(in, file.string());
  CHECK(g.width() == 20);
  CHECK(g.height() == 20);
  CHECK(g.passable({0, 0}));
  CHECK(g.blocked({6, 0}));
  CHECK(g.blocked({8, 0}));
  CHECK(g.passable({9, 0}));
  CHECK(g.blocked({1, 1}));
  CHECK(g.blocked({0, 14}));  // row 15 of the file starts "1 1 1 1"
  CHECK(g.passable({19, 19}));
}

TEST_CASE("Malformed matrix maps are rejected with a precise message", "[map_io]") {
  SECTION("non-numeric token") {
    REQUIRE_THROWS_AS(matrix("0 0\n0 x\n"), aco::Error);
    REQUIRE_THROWS_WITH(matrix("0 0\n0 x\n", "bad.txt"),
                        Catch::Contains("bad.txt:2:") && Catch::Contains("'x' is not a number"));
  }
  SECTION("value other than 0 or 1") {
    REQUIRE_THROWS_WITH(matrix("0 2\n0 0\n", "bad.txt"),
                        Catch::Contains("bad.txt:1:") && Catch::Contains("value 2 is neither 0"));
  }
  SECTION("rows of different length") {
    REQUIRE_THROWS_WITH(matrix("0 0 0\n0 0\n", "bad.txt"),
                        Catch::Contains("bad.txt:2:") && Catch::Contains("row has 2 values, the first row has 3"));
  }
  SECTION("rows after a blank line") {
    REQUIRE_THROWS_WITH(matrix("0 0\n\n0 0\n", "bad.txt"),
                        Catch::Contains("bad.txt:3:") && Catch::Contains("continue after a blank line"));
  }
  SECTION("empty file") {
    REQUIRE_THROWS_WITH(matrix("", "empty.txt"), Catch::Contains("empty.txt") && Catch::Contains("no matrix rows"));
    REQUIRE_THROWS_WITH(matrix("\n  \n", "blank.txt"), Catch::Contains("no matrix rows"));
  }
}

// ---------------------------------------------------------------------------------------------
// Scenarios

TEST_CASE("Moving AI arena.map.scen loads", "[map_io]") {
  const fs::path file = test::data_dir() / "maps/movingai/arena.map.scen";
  const auto list = aco::load_scenarios(file);
  REQUIRE(list.size() == count_lines(file) - 1);  // all lines but "version 1"
  CHECK(list.size() == 160);
  const aco::Scenario& first = list.front();
  CHECK(first.bucket == 0);
  CHECK(first.map_path == "maps/dao/arena.map");
  CHECK(first.width == 49);
  CHECK(first.height == 49);
  CHECK(first.start == aco::Cell{1, 11});
  CHECK(first.goal == aco::Cell{1, 12});
  CHECK(first.optimal_length == Approx(1.0));
  // "0 maps/dao/arena.map 49 49 1 13 4 12 3.41421"
  CHECK(list[2].start == aco::Cell{1, 13});
  CHECK(list[2].goal == aco::Cell{4, 12});
  CHECK(list[2].optimal_length == Approx(3.41421));
  // Last line: "15 maps/dao/arena.map 49 49 1 7 47 46 62.1543"
  const aco::Scenario& last = list.back();
  CHECK(last.bucket == 15);
  CHECK(last.start == aco::Cell{1, 7});
  CHECK(last.goal == aco::Cell{47, 46});
  CHECK(last.optimal_length == Approx(62.1543));
}

TEST_CASE("Scenario lines may be space separated and blank lines are skipped", "[map_io]") {
  const auto list = scenarios("version 1\n\n3 a.map 10 12 1 2 3 4 5.5\n\n");
  REQUIRE(list.size() == 1);
  CHECK(list[0].bucket == 3);
  CHECK(list[0].map_path == "a.map");
  CHECK(list[0].width == 10);
  CHECK(list[0].height == 12);
  CHECK(list[0].start == aco::Cell{1, 2});
  CHECK(list[0].goal == aco::Cell{3, 4});
  CHECK(list[0].optimal_length == 5.5);
  CHECK(scenarios("version 1\n").empty());
}

TEST_CASE("scenario_map_file strips .scen and rejects other names", "[map_io]") {
  CHECK(aco::scenario_map_file("x/arena.map.scen") == fs::path("x/arena.map"));
  CHECK(aco::scenario_map_file("/a/b/maze512-1-0.map.scen") == fs::path("/a/b/maze512-1-0.map"));
  REQUIRE_THROWS_AS(aco::scenario_map_file("x/arena.map"), aco::Error);
  REQUIRE_THROWS_WITH(aco::scenario_map_file("x/arena.map"),
                      Catch::Contains("x/arena.map") && Catch::Contains("must end in .scen"));
}

TEST_CASE("Malformed scenario files are rejected with a precise message", "[map_io]") {
  const std::string good = "0\ta.map\t10\t10\t1\t2\t3\t4\t2.5\n";
  SECTION("missing version line") {
    REQUIRE_THROWS_AS(scenarios(good), aco::Error);
    REQUIRE_THROWS_WITH(scenarios(good, "bad.scen"),
                        Catch::Contains("bad.scen:1:") && Catch::Contains("expected 'version 1'"));
  }
  SECTION("unknown version") {
    REQUIRE_THROWS_WITH(scenarios("version 2\n" + good, "bad.scen"),
                        Catch::Contains("bad.scen:1:") && Catch::Contains("expected 'version 1', found 'version 2'"));
    CHECK(scenarios("version 1.0\n" + good, "ok.scen").size() == 1);
  }
  SECTION("empty file") {
    REQUIRE_THROWS_WITH(scenarios("", "bad.scen"),
                        Catch::Contains("bad.scen") && Catch::Contains("empty scenario file"));
  }
  SECTION("a line with 8 fields") {
    REQUIRE_THROWS_WITH(
        scenarios("version 1\n" + good + "0\ta.map\t10\t10\t1\t2\t3\t4\n", "bad.scen"),
        Catch::Contains("bad.scen:3:") && Catch::Contains("expected 9 fields") && Catch::Contains("found 8"));
  }
  SECTION("a non-numeric field") {
    REQUIRE_THROWS_WITH(scenarios("version 1\n0\ta.map\t10\t10\tone\t2\t3\t4\t2.5\n", "bad.scen"),
                        Catch::Contains("bad.scen:2:") && Catch::Contains("malformed scenario line"));
    REQUIRE_THROWS_WITH(scenarios("version 1\n0\ta.map\t10\t10\t1\t2\t3\t4\tlong\n"),
                        Catch::Contains("malformed scenario line"));
  }
  SECTION("a negative optimal length") {
    REQUIRE_THROWS_WITH(scenarios("version 1\n0\ta.map\t10\t10\t1\t2\t3\t4\t-1\n"),
                        Catch::Contains("malformed scenario line"));
  }
  SECTION("a missing file") {
    REQUIRE_THROWS_WITH(aco::load_scenarios("/nonexistent/none.map.scen"), Catch::Contains("cannot open file"));
  }
}

// ---------------------------------------------------------------------------------------------
// ROS map_server YAML + PGM

TEST_CASE("ROS map with an ASCII (P2) PGM", "[map_io]") {
  // 4x2 image: black, white, mid grey, just-free grey / white, black, just-unknown grey, white
  // p = (255 - v) / 255: 128 -> 0.498 (unknown), 210 -> 0.176 (free), 200 -> 0.216 (unknown).
  const std::string pgm = "P2\n# a comment\n4 2\n255\n0 255 128 210\n255 0 200 255\n";
  const fs::path yaml = ros_map(
      "image: map.pgm\nresolution: 0.05\norigin: [-1.5, 2.0, 0.25]\nnegate: 0\n"
      "occupied_thresh: 0.65\nfree_thresh: 0.196\n",
      "map.pgm", pgm);
  const aco::OccupancyGrid g = aco::load_ros_map(yaml);
  REQUIRE(g.width() == 4);
  REQUIRE(g.height() == 2);
  CHECK(g.blocked({0, 0}));  // black: occupied
  CHECK(g.passable({1, 0}));  // white: free
  CHECK(g.blocked({2, 0}));  // mid grey: unknown counts as blocked
  CHECK(g.passable({3, 0}));  // below free_thresh
  CHECK(g.passable({0, 1}));
  CHECK(g.blocked({1, 1}));
  CHECK(g.blocked({2, 1}));  // just above free_thresh: unknown
  CHECK(g.passable({3, 1}));
  CHECK(g.geometry().resolution == Approx(0.05));
  CHECK(g.geometry().origin.x() == Approx(-1.5));
  CHECK(g.geometry().origin.y() == Approx(2.0));
  CHECK(g.geometry().origin.z() == Approx(0.25));

  const aco::GreyImage image = aco::load_pgm(yaml.parent_path() / "map.pgm");
  CHECK(image.width == 4);
  CHECK(image.height == 2);
  CHECK(image.maxval == 255);
  CHECK(image.pixels == std::vector<int>{0, 255, 128, 210, 255, 0, 200, 255});
}

TEST_CASE("ROS map with a binary (P5) PGM, negate and thresholds", "[map_io]") {
  // 3x2 image; the first byte is a newline (10) to make sure raw data is not skipped as whitespace.
  const std::string pgm = "P5\n3 2\n255\n" + bytes({10, 255, 128, 0, 35, 250});
  SECTION("negate 0") {
    const auto g = aco::load_ros_map(ros_map("image: map.pgm\nresolution: 1.0\norigin: [0, 0, 0]\n", "map.pgm", pgm));
    REQUIRE(g.width() == 3);
    REQUIRE(g.height() == 2);
    CHECK(g.blocked({0, 0}));  // 10: nearly black
    CHECK(g.passable({1, 0}));  // 255
    CHECK(g.blocked({2, 0}));  // 128: unknown
    CHECK(g.blocked({0, 1}));  // 0
    CHECK(g.blocked({1, 1}));  // 35
    CHECK(g.passable({2, 1}));  // 250
    CHECK(g.geometry().resolution == 1.0);
    CHECK(g.geometry().origin.isZero());
  }
  SECTION("negate 1 inverts") {
    const auto g =
        aco::load_ros_map(ros_map("image: map.pgm\nresolution: 1.0\norigin: [0, 0, 0]\nnegate: 1\n", "map.pgm", pgm));
    CHECK(g.passable({0, 0}));  // 10 -> p = 0.04
    CHECK(g.blocked({1, 0}));  // 255 -> p = 1
    CHECK(g.blocked({2, 0}));  // 128: still unknown
    CHECK(g.passable({0, 1}));  // 0
    CHECK(g.passable({1, 1}));  // 35 -> p = 0.137
    CHECK(g.blocked({2, 1}));  // 250
  }
  SECTION("a higher free_thresh frees mid grey") {
    const auto g = aco::load_ros_map(
        ros_map("image: map.pgm\nresolution: 1.0\norigin: [0, 0, 0]\nfree_thresh: 0.6\noccupied_thresh: 0.9\n",
                "map.pgm", pgm));
    CHECK(g.passable({2, 0}));  // 128 -> p = 0.498 < 0.6
    CHECK(g.blocked({0, 1}));
  }
  SECTION("load_pgm reads the raw bytes") {
    const fs::path file = test::temp_file("raw.pgm", pgm);
    const auto image = aco::load_pgm(file);
    CHECK(image.maxval == 255);
    CHECK(image.pixels == std::vector<int>{10, 255, 128, 0, 35, 250});
  }
}

TEST_CASE("PGM with a small maxval is scaled by maxval", "[map_io]") {
  // maxval 15: 15 white, 0 black, 8 -> p = 0.467 (unknown), 13 -> p = 0.133 (free)
  const auto g = aco::load_ros_map(
      ros_map("image: m.pgm\nresolution: 0.1\norigin: [0.0, 0.0, 0.0]\n", "m.pgm", "P2 4 1 15 15 0 8 13\n"));
  REQUIRE(g.width() == 4);
  REQUIRE(g.height() == 1);
  CHECK(g.passable({0, 0}));
  CHECK(g.blocked({1, 0}));
  CHECK(g.blocked({2, 0}));
  CHECK(g.passable({3, 0}));
}

TEST_CASE("16-bit P5 PGM is big-endian", "[map_io]") {
  // Values 0x0000, 0xFFFF, 0xFF00, 0x00FF: a little-endian reader would swap the last two.
  const std::string pgm = "P5\n2 2\n65535\n" + bytes({0x00, 0x00, 0xFF, 0xFF, 0xFF, 0x00, 0x00, 0xFF});
  const fs::path yaml = ros_map("image: deep.pgm\nresolution: 0.5\norigin: [1, 2, 0]\n", "deep.pgm", pgm);
  const auto image = aco::load_pgm(yaml.parent_path() / "deep.pgm");
  CHECK(image.maxval == 65535);
  CHECK(image.pixels == std::vector<int>{0, 65535, 65280, 255});
  const auto g = aco::load_ros_map(yaml);
  CHECK(g.blocked({0, 0}));
  CHECK(g.passable({1, 0}));
  CHECK(g.passable({0, 1}));  // 65280: nearly white
  CHECK(g.blocked({1, 1}));  // 255 of 65535: nearly black
  CHECK(g.geometry().origin.x() == 1.0);
  CHECK(g.geometry().origin.y() == 2.0);
}

TEST_CASE("ROS map image given by an absolute path", "[map_io]") {
  const fs::path pgm = test::temp_file("abs.pgm", "P2\n2 1\n255\n255 0\n");
  const fs::path yaml = test::temp_file("abs.yaml", "image: " + pgm.string() + "\nresolution: 1\norigin: [0, 0, 0]\n");
  const auto g = aco::load_ros_map(yaml);
  CHECK(g.passable({0, 0}));
  CHECK(g.blocked({1, 0}));
}

TEST_CASE("Malformed ROS maps and PGM images are rejected with a precise message", "[map_io]") {
  const std::string pgm = "P2\n2 2\n255\n0 255\n255 0\n";
  SECTION("missing image key") {
    const auto yaml = ros_map("resolution: 0.05\norigin: [0, 0, 0]\n", "map.pgm", pgm);
    REQUIRE_THROWS_AS(aco::load_ros_map(yaml), aco::Error);
    REQUIRE_THROWS_WITH(aco::load_ros_map(yaml),
                        Catch::Contains(yaml.string()) && Catch::Contains("missing key 'image'"));
  }
  SECTION("missing resolution key") {
    const auto yaml = ros_map("image: map.pgm\norigin: [0, 0, 0]\n", "map.pgm", pgm);
    REQUIRE_THROWS_WITH(aco::load_ros_map(yaml), Catch::Contains("missing key 'resolution'"));
  }
  SECTION("value of the wrong type") {
    const auto yaml = ros_map("image: map.pgm\nresolution: fine\norigin: [0, 0, 0]\n", "map.pgm", pgm);
    REQUIRE_THROWS_WITH(aco::load_ros_map(yaml), Catch::Contains(yaml.string() + ":2:") &&
                                                     Catch::Contains("key 'resolution'") &&
                                                     Catch::Contains("wrong type"));
  }
  SECTION("bad magic in the PGM") {
    const auto yaml = ros_map("image: map.pgm\nresolution: 1\norigin: [0, 0, 0]\n", "map.pgm", "P6\n2 2\n255\n");
    REQUIRE_THROWS_WITH(aco::load_ros_map(yaml),
                        Catch::Contains("map.pgm") && Catch::Contains("not a PGM image") && Catch::Contains("'P6'"));
    REQUIRE_THROWS_WITH(aco::load_pgm(yaml.parent_path() / "map.pgm"), Catch::Contains("magic 'P6'"));
  }
  SECTION("bad PGM header") {
    const fs::path file = test::temp_file("h.pgm", "P2\n2 x\n255\n0 0 0 0\n");
    REQUIRE_THROWS_WITH(aco::load_pgm(file), Catch::Contains("bad PGM header") && Catch::Contains("height 'x'"));
    const fs::path big = test::temp_file("big.pgm", "P2\n1 1\n70000\n0\n");
    REQUIRE_THROWS_WITH(aco::load_pgm(big), Catch::Contains("bad PGM header"));
  }
  SECTION("truncated binary PGM data") {
    const auto yaml = ros_map("image: map.pgm\nresolution: 1\norigin: [0, 0, 0]\n", "map.pgm",
                              "P5\n3 2\n255\n" + bytes({0, 255, 0, 255}));
    REQUIRE_THROWS_WITH(aco::load_ros_map(yaml),
                        Catch::Contains("map.pgm") && Catch::Contains("truncated PGM data (4 of 6 bytes)"));
  }
  SECTION("truncated ASCII PGM data") {
    const fs::path file = test::temp_file("t.pgm", "P2\n2 2\n255\n0 255 0\n");
    REQUIRE_THROWS_WITH(aco::load_pgm(file), Catch::Contains("truncated PGM data (3 of 4 values)"));
  }
  SECTION("PGM value above maxval") {
    const fs::path file = test::temp_file("v.pgm", "P2\n2 1\n100\n0 101\n");
    REQUIRE_THROWS_WITH(aco::load_pgm(file), Catch::Contains("101 exceeds maxval"));
  }
  SECTION("origin with two numbers") {
    const auto yaml = ros_map("image: map.pgm\nresolution: 1\norigin: [0.0, 1.0]\n", "map.pgm", pgm);
    REQUIRE_THROWS_WITH(aco::load_ros_map(yaml),
                        Catch::Contains(yaml.string()) && Catch::Contains("origin must be a list of three numbers"));
  }
  SECTION("image that is not a .pgm") {
    const auto yaml = ros_map("image: map.png\nresolution: 1\norigin: [0, 0, 0]\n", "map.png", pgm);
    REQUIRE_THROWS_WITH(aco::load_ros_map(yaml), Catch::Contains("image 'map.png' is not a .pgm file"));
  }
  SECTION("missing image file") {
    const auto yaml = test::temp_file("lonely.yaml", "image: none.pgm\nresolution: 1\norigin: [0, 0, 0]\n");
    REQUIRE_THROWS_WITH(aco::load_ros_map(yaml), Catch::Contains("none.pgm") && Catch::Contains("cannot open file"));
  }
  SECTION("invalid YAML syntax") {
    const auto yaml = ros_map("image: map.pgm\nresolution: 1\norigin: [0, 0, 0\n", "map.pgm", pgm);
    REQUIRE_THROWS_AS(aco::load_ros_map(yaml), aco::Error);
    REQUIRE_THROWS_WITH(aco::load_ros_map(yaml), Catch::Contains(yaml.string()) && Catch::Contains("invalid YAML"));
  }
  SECTION("YAML that is not a mapping") {
    const auto yaml = ros_map("- image\n- map.pgm\n", "map.pgm", pgm);
    REQUIRE_THROWS_WITH(aco::load_ros_map(yaml), Catch::Contains("expected a YAML mapping"));
  }
  SECTION("bad negate, thresholds and mode") {
    const std::string head = "image: map.pgm\nresolution: 1\norigin: [0, 0, 0]\n";
    REQUIRE_THROWS_WITH(aco::load_ros_map(ros_map(head + "negate: 2\n", "map.pgm", pgm)),
                        Catch::Contains("negate must be 0 or 1"));
    REQUIRE_THROWS_WITH(aco::load_ros_map(ros_map(head + "free_thresh: 0.8\noccupied_thresh: 0.6\n", "map.pgm", pgm)),
                        Catch::Contains("thresholds must satisfy"));
    REQUIRE_THROWS_WITH(aco::load_ros_map(ros_map(head + "mode: fancy\n", "map.pgm", pgm)),
                        Catch::Contains("mode 'fancy'"));
    REQUIRE_THROWS_WITH(
        aco::load_ros_map(ros_map("image: map.pgm\nresolution: 0\norigin: [0, 0, 0]\n", "map.pgm", pgm)),
        Catch::Contains("resolution must be positive"));
  }
}

// ---------------------------------------------------------------------------------------------
// load_map dispatch

TEST_CASE("load_map picks the format by extension", "[map_io][slow]") {
  SECTION(".map is Moving AI") {
    const auto map = aco::load_map(test::data_dir() / "maps/movingai/arena.map");
    REQUIRE(map);
    CHECK(map->width() == 49);
    CHECK(map->height() == 49);
    CHECK_FALSE(map->passable({24, 7}));
    CHECK(map->passable({3, 1}));
  }
  SECTION(".txt is a 0/1 matrix") {
    const auto map = aco::load_map(test::data_dir() / "maps/classic20/map1.txt");
    REQUIRE(map);
    CHECK(map->width() == 20);
    CHECK(map->height() == 20);
    CHECK_FALSE(map->passable({6, 0}));
    CHECK(map->passable({0, 0}));
  }
  SECTION(".yaml and .yml are ROS maps") {
    const auto yaml = ros_map("image: map.pgm\nresolution: 0.25\norigin: [3, 4, 0]\n", "map.pgm", "P2 2 1 255 0 255\n");
    const auto map = aco::load_map(yaml);
    REQUIRE(map);
    CHECK(map->width() == 2);
    CHECK(map->height() == 1);
    CHECK_FALSE(map->passable({0, 0}));
    CHECK(map->passable({1, 0}));
    const auto* grid = dynamic_cast<const aco::OccupancyGrid*>(map.get());
    REQUIRE(grid != nullptr);
    CHECK(grid->geometry().resolution == 0.25);
    const fs::path yml = write_beside(yaml, "other.yml", "image: map.pgm\nresolution: 1\norigin: [0, 0, 0]\n");
    const auto other = aco::load_map(yml);
    CHECK(other->width() == 2);
    CHECK(other->passable({1, 0}));
  }
  SECTION("a Moving AI map under .map, but matrix text is not accepted as .map") {
    const fs::path file = test::temp_file("m.map", "0 1\n1 0\n");
    REQUIRE_THROWS_WITH(aco::load_map(file), Catch::Contains("m.map:1:") && Catch::Contains("bad header line"));
  }
  SECTION("any other extension is a matrix") {
    const fs::path file = test::temp_file("grid.dat", "0 1\n1 0\n");
    const auto map = aco::load_map(file);
    CHECK(map->width() == 2);
    CHECK_FALSE(map->passable({1, 0}));
    CHECK(map->passable({1, 1}));
  }
  SECTION("a file that does not exist") {
    for (const char* name : {"/nonexistent/aco/none.map", "/nonexistent/aco/none.txt", "/nonexistent/aco/none.yaml"}) {
      INFO(name);
      REQUIRE_THROWS_AS(aco::load_map(name), aco::Error);
      REQUIRE_THROWS_WITH(aco::load_map(name), Catch::Contains(name) && Catch::Contains("cannot open file"));
    }
  }
  SECTION("a directory or a device, whatever its name says: refused before reading (/dev/zero never ends)") {
    const auto dir = test::temp_file("unused", "").parent_path();
    for (const char* ext : {".map", ".txt", ".yaml", ".asc", ".pgm"}) {
      INFO(ext);
      const auto folder = dir / (std::string("folder") + ext);
      std::filesystem::create_directories(folder);
      REQUIRE_THROWS_WITH(aco::load_map(folder), Catch::Contains(folder.string()) && Catch::Contains("is a directory"));
      const auto device = dir / (std::string("zero") + ext);
      std::filesystem::create_symlink("/dev/zero", device);
      REQUIRE_THROWS_WITH(aco::load_map(device),
                          Catch::Contains(device.string()) && Catch::Contains("not a regular file"));
    }
    REQUIRE_THROWS_WITH(aco::load_scenarios("/dev/zero"), Catch::Contains("not a regular file"));
  }
  SECTION("one endless line (17 MiB, no newline) is refused, not read into memory whole") {
    for (const char* name : {"long.map", "long.txt", "long.asc", "long.map.scen"}) {
      INFO(name);
      const auto file = test::temp_file(name, "0 1 " + std::string(17 << 20, '0'));
      const auto load = [&] {
        return std::string(name) == "long.map.scen" ? (aco::load_scenarios(file), 0) : (aco::load_map(file), 0);
      };
      REQUIRE_THROWS_WITH(load(), Catch::Contains(file.string() + ":1: a line longer than 16 MiB"));
    }
  }
}

// The unit test of map/shapes: it loads the plugin from the library the build made.
#define CATCH_CONFIG_MAIN
#include "aco/sdk/testing.hpp"

TEST_CASE("map/shapes passes the conformance checks", "[shapes]") { aco::testing::check_conformance(PLUGIN_FILE); }

TEST_CASE("map/shapes rasterises the room at its resolution", "[shapes]") {
  const auto reader = aco::testing::create<aco::MapReader>(PLUGIN_FILE, {{"resolution", "0.5"}});
  const auto map = reader->read(ROOM_FILE, {});
  CHECK(map->width() == 20);  // 10 m at 0.5 m per cell
  CHECK(map->height() == 16);  // 8 m
  CHECK(map->passable({0, 0}));
  CHECK_FALSE(map->passable({4, 0}));  // the wall from the top: x 2..3 m
  CHECK_FALSE(map->passable({12, 15}));  // the wall from the bottom: x 6..7 m
  CHECK_FALSE(map->passable({17, 4}));  // the pillar's centre (8.5, 2) m
  CHECK(map->passable({19, 15}));
  const auto fine = aco::testing::create<aco::MapReader>(PLUGIN_FILE, {{"resolution", "0.25"}})->read(ROOM_FILE, {});
  CHECK(fine->width() == 40);
}

TEST_CASE("map/shapes names the file and the line of a mistake", "[shapes]") {
  const auto reader = aco::testing::create<aco::MapReader>(PLUGIN_FILE);
  CHECK_THROWS_WITH(reader->read("no/such/room.shapes", {}), Catch::Contains("no/such/room.shapes"));
}

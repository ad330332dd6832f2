// aco::Trail: the pheromone with a lazy scale and bounds (MAX-MIN's evaporation and limits in
// O(1) per iteration), and plain per-edge values for every other rule.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <vector>

#include "aco/strategies.hpp"

TEST_CASE("a trail nobody scaled or bounded is its stored values", "[trail]") {
  std::vector<double> stored{1.0, 2.5, 0.0};
  aco::Trail trail(stored);
  CHECK(trail.plain());
  CHECK(trail.values().data() == stored.data());
  trail.set(1, 4.0);
  CHECK(stored[1] == 4.0);
  CHECK(trail[0] == 1.0);
  CHECK(trail[2] == 0.0);
}

TEST_CASE("evaporation and bounds apply where tau is read, and values() applies them to every edge", "[trail]") {
  std::vector<double> stored{1.0, 0.5, 0.01, 4.0};
  aco::Trail trail(stored);
  trail.evaporate(0.5);
  trail.bound(0.1, 1.0);
  CHECK_FALSE(trail.plain());
  CHECK(stored == std::vector<double>{1.0, 0.5, 0.01, 4.0});  // nothing written per edge yet
  CHECK(trail[0] == 0.5);
  CHECK(trail[1] == 0.25);
  CHECK(trail[2] == 0.1);  // below the lower bound
  CHECK(trail[3] == 1.0);  // above the upper one
  // set() is read back as written, within the bounds.
  trail.set(1, 0.75);
  CHECK(trail[1] == Approx(0.75));
  trail.set(0, 7.0);
  CHECK(trail[0] == 1.0);
  const std::vector<double> read{trail[0], trail[1], trail[2], trail[3]};
  const auto values = trail.values();
  CHECK(std::vector<double>(values.begin(), values.end()) == read);
  CHECK(trail.scale() == 1.0);
  // The bounds stay in force: a plain value written beyond them is read within them.
  values[2] = 0.0;
  CHECK(trail[2] == 0.1);
}

TEST_CASE("a trail evaporated for thousands of iterations keeps its values", "[trail]") {
  std::vector<double> stored{1.0, 3.0};
  aco::Trail trail(stored);
  for (int i = 0; i < 2000; ++i) {
    trail.evaporate(0.3);
    CHECK(trail.scale() >= 1e-100);  // the stored values are rescaled before the scale underflows
    trail.set(1, trail[1] + 1.0);  // a deposit every iteration: its sum converges to 1 / 0.3
  }
  CHECK(trail[0] == Approx(std::pow(0.7, 2000)).margin(1e-300));
  CHECK(trail[1] == Approx(0.7 / 0.3 + 1.0));
  trail.evaporate(1.0);  // everything gone at once
  CHECK(trail[0] == 0.0);
  CHECK(trail[1] == 0.0);
  trail.fill(2.0);
  CHECK(trail[1] == 2.0);
  CHECK(trail.scale() == 1.0);
}

TEST_CASE("values() leaves a negative or NaN value for the engine's check to see", "[trail]") {
  std::vector<double> stored{1.0, 1.0};
  aco::Trail trail(stored);
  trail.evaporate(0.5);
  trail.bound(0.1, 1.0);
  trail.set(0, -1.0);
  trail.set(1, std::numeric_limits<double>::quiet_NaN());
  const auto values = trail.values();
  CHECK(values[0] < 0.0);
  CHECK(std::isnan(values[1]));
}

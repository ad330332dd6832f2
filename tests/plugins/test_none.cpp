#include <catch2/catch.hpp>

#include "support.hpp"

TEST_CASE("the none smoother returns the grid path's cell centres unchanged", "[plugin][none]") {
  const auto map = test::grid({"...", "..."});
  const aco::Graph graph = aco::build_graph(map, {});
  auto smoother = test::make<aco::Smoother>("smoother", "none");
  const std::vector<aco::NodeId> path{graph.node({0, 0}), graph.node({1, 1}), graph.node({2, 1})};
  const auto points = smoother->smooth(test::context(graph, {0, 0}, {2, 1}), path);
  REQUIRE(points.size() == 3);
  CHECK(points[0] == Eigen::Vector3d(0, 0, 0));
  CHECK(points[1] == Eigen::Vector3d(1, 1, 0));
  CHECK(points[2] == Eigen::Vector3d(2, 1, 0));
}

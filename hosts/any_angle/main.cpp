// aco-any-angle: for the problems of a Moving AI scenario file, the octile optimum the file states,
// basic Theta*'s length and the exact any-angle optimum (aco/any_angle.hpp), with their ratios.
//   aco-any-angle MAP.scen [--index N]... [--all | --sample K | --longest K] [--time]
#include <algorithm>
#include <boost/program_options.hpp>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <numeric>
#include <optional>
#include <string>
#include <vector>

#include "aco/any_angle.hpp"
#include "aco/astar.hpp"
#include "aco/error.hpp"
#include "aco/graph.hpp"
#include "aco/hosts/host_options.hpp"
#include "aco/engine/map_io.hpp"
#include "aco/process/version.hpp"

namespace po = boost::program_options;

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Which scenarios (0-based) the options name, in order.
std::vector<std::size_t> chosen(const po::variables_map& vm, const std::vector<aco::Scenario>& scenarios) {
  const std::size_t n = scenarios.size();
  std::vector<std::size_t> picked;
  if (vm.count("index"))
    for (const int i : vm["index"].as<std::vector<int>>()) {
      if (i < 0 || static_cast<std::size_t>(i) >= n)
        throw aco::Error("--index " + std::to_string(i) + ": the file has scenarios 0 to " + std::to_string(n - 1));
      picked.push_back(static_cast<std::size_t>(i));
    }
  if (vm["all"].as<bool>())
    for (std::size_t i = 0; i < n; ++i) picked.push_back(i);
  if (vm.count("sample")) {  // K evenly spread, the last one always
    const int k = vm["sample"].as<int>();
    if (k < 1) throw aco::Error("--sample takes a whole number of at least 1");
    const std::size_t count = std::min<std::size_t>(k, n);
    for (std::size_t j = 0; j < count; ++j) picked.push_back(count == 1 ? n - 1 : j * (n - 1) / (count - 1));
  }
  if (vm.count("longest")) {  // the K of the largest octile optimum, as the file lists them
    const int k = vm["longest"].as<int>();
    if (k < 1) throw aco::Error("--longest takes a whole number of at least 1");
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return scenarios[a].optimal_length > scenarios[b].optimal_length;
    });
    order.resize(std::min<std::size_t>(k, n));
    std::sort(order.begin(), order.end());
    picked.insert(picked.end(), order.begin(), order.end());
  }
  if (picked.empty()) throw aco::Error("name the scenarios: --index N, --all, --sample K or --longest K");
  return picked;
}

}  // namespace

int main(int argc, char** argv) {
  return aco::run_command("aco-any-angle", [&] {
    std::string scen;
    po::options_description options(
        "aco-any-angle: the octile optimum of a Moving AI scenario (8-neighbourhood, no corner cutting, as the file "
        "states it), basic Theta*'s length and the exact any-angle optimum, the lower bound of every continuous path "
        "(docs/maps.md).\n\nUsage: aco-any-angle MAP.scen [options]\n\nOptions");
    options.add_options()("help,h", "print this help and exit")(
        "version", "print the framework's version, commit, build type and compiler and exit")(
        "index", po::value<std::vector<int>>()->value_name("N"),
        "scenario N (0-based, as acoplan's --scen-index); repeatable")("all", po::bool_switch(),
                                                                       "every scenario of the file")(
        "sample", po::value<int>()->value_name("K"), "K scenarios evenly spread over the file, the last one always")(
        "longest", po::value<int>()->value_name("K"), "the K scenarios of the largest octile optimum")(
        "time", po::bool_switch(), "add each search's wall-clock time in milliseconds (Theta*, any-angle)")(
        "waypoints", po::bool_switch(), "add the any-angle path's waypoints")(
        "no-theta-star", po::bool_switch(),
        "skip Theta* (its column reads -): it alone takes seconds on 2048x2048 maps");
    po::options_description hidden;
    hidden.add_options()("scen", po::value(&scen));
    po::options_description all;
    all.add(options).add(hidden);
    po::positional_options_description positional;
    positional.add("scen", 1);
    po::variables_map vm;
    po::store(po::command_line_parser(argc, argv).options(all).positional(positional).run(), vm);
    po::notify(vm);
    if (vm.count("help")) {
      std::cout << options;
      return aco::kExitOk;
    }
    if (vm.count("version")) {
      std::cout << aco::version_text("aco-any-angle") << "\n";
      return aco::kExitOk;
    }
    if (scen.empty()) throw aco::Error("give a scenario file (MAP.scen); --help lists the options");
    const auto scenarios = aco::load_scenarios(scen);
    if (scenarios.empty()) throw aco::Error(scen + ": no scenarios");
    const std::vector<std::size_t> picked = chosen(vm, scenarios);
    const bool timed = vm["time"].as<bool>(), waypoints = vm["waypoints"].as<bool>();
    const bool with_theta = !vm["no-theta-star"].as<bool>();

    const auto map = aco::load_map(aco::scenario_map_file(scen));
    const aco::Graph graph = aco::build_graph(*map, {aco::Neighbourhood::eight, false});
    aco::AnyAngleSearch search(*map);
    std::printf("# %s (%dx%d): octile = the file's optimum; theta* and any-angle in cell units\n", map->name().c_str(),
                map->width(), map->height());
    std::printf("%-6s %-13s %-13s %12s %12s %12s %8s%s\n", "index", "start", "goal", "octile", "theta*", "any-angle",
                "ratio", timed ? "  theta*_ms any-angle_ms" : "");
    std::setvbuf(stdout, nullptr, _IOLBF, 0);  // a row as soon as it is known
    std::vector<double> ratios, theta_ms, exact_ms;
    for (const std::size_t i : picked) {
      const aco::Scenario& s = scenarios[i];
      if (!map->passable(s.start) || !map->passable(s.goal))
        throw aco::Error(scen + ": scenario " + std::to_string(i) + " starts or ends on a blocked cell");
      auto t0 = std::chrono::steady_clock::now();
      std::optional<aco::AnyAnglePath> theta;
      if (with_theta) {
        theta = aco::theta_star(graph, graph.node(s.start), graph.node(s.goal));
        theta_ms.push_back(1e3 * seconds_since(t0));
      }
      t0 = std::chrono::steady_clock::now();
      const auto exact = search.find(s.start, s.goal);
      exact_ms.push_back(1e3 * seconds_since(t0));
      const double ratio = exact && s.optimal_length > 0 ? exact->length / s.optimal_length : 1.0;
      if (exact) ratios.push_back(ratio);
      // A length, or "-" for none (unreachable, or Theta* skipped).
      const auto length = [](const std::optional<aco::AnyAnglePath>& path) {
        char text[32] = "-";
        if (path) std::snprintf(text, sizeof text, "%.6f", path->length);
        return std::string(text);
      };
      char times[64] = "", theta_time[32] = "-";
      if (with_theta) std::snprintf(theta_time, sizeof theta_time, "%.2f", theta_ms.back());
      if (timed) std::snprintf(times, sizeof times, "  %9s %12.2f", theta_time, exact_ms.back());
      std::printf("%-6zu %-13s %-13s %12.6f %12s %12s %8.5f%s\n", i, aco::to_string(s.start).c_str(),
                  aco::to_string(s.goal).c_str(), s.optimal_length, length(theta).c_str(), length(exact).c_str(), ratio,
                  times);
      if (waypoints && exact) {
        std::printf("       waypoints:");
        for (const auto& p : exact->waypoints) std::printf(" (%g,%g)", p.x(), p.y());
        std::printf("\n");
      }
    }
    if (picked.size() > 1 && !ratios.empty()) {
      const double mean = std::accumulate(ratios.begin(), ratios.end(), 0.0) / ratios.size();
      std::printf("# %zu scenarios: any-angle/octile mean %.5f min %.5f", picked.size(), mean,
                  *std::min_element(ratios.begin(), ratios.end()));
      const auto mean_max = [](const char* what, const std::vector<double>& ms) {
        if (!ms.empty())
          std::printf("; %s ms mean %.1f max %.1f", what, std::accumulate(ms.begin(), ms.end(), 0.0) / ms.size(),
                      *std::max_element(ms.begin(), ms.end()));
      };
      if (timed) {
        mean_max("any-angle", exact_ms);
        mean_max("theta*", theta_ms);
      }
      std::printf("\n");
    }
    return aco::kExitOk;
  });
}

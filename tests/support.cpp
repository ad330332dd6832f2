#include "support.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <fstream>
#include <sstream>

#include "aco/error.hpp"
#include "aco/map_io.hpp"

extern char** environ;

namespace test {

std::filesystem::path data_dir() { return ACO_TEST_DATA_DIR; }
std::filesystem::path shared_data_dir() { return ACO_TEST_SHARED_DATA_DIR; }

aco::OccupancyGrid classic_map(int n) {
  const auto file = data_dir() / "maps/classic20" / ("map" + std::to_string(n) + ".txt");
  std::ifstream in(file);
  return aco::read_matrix_map(in, file.string());
}

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
    a.length += graph.costs[e];
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

CommandResult run(const std::vector<std::string>& argv, const std::vector<std::string>& env) {
  const auto dir = fresh_dir();
  const auto out = dir / "stdout", err = dir / "stderr";
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
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
  CommandResult result;
  if (posix_spawn(&pid, args[0], &actions, nullptr, args.data(), envp.data()) == 0) {
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

}  // namespace test

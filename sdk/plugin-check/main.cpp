// aco-plugin-check FILE.so...: the conformance checks (aco/conformance.hpp) on every plugin in
// each file, one line per check; exits 1 if any check failed, 2 on a usage error.
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#include "aco/conformance.hpp"

int main(int argc, char** argv) {
  const std::string usage =
      "usage: aco-plugin-check [--integer-cap N] [--set NAME=VALUE]... FILE.so...\n"
      "Runs every plugin in each file at its defaults and at the ends of its parameter ranges on tiny maps and\n"
      "checks that its values are finite and non-negative, that it is deterministic per seed, and that 1 and 4\n"
      "threads give the same result. Whole-number range ends above N (default 100) are run at N. --set gives a\n"
      "parameter the value every run starts from (a text parameter, such as the python plugins' class).\n";
  aco::conformance::Options options;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h") {
      std::cout << usage;
      return 0;
    }
    if (arg == "--integer-cap") {
      char* end = nullptr;
      const long long cap = i + 1 < argc ? std::strtoll(argv[i + 1], &end, 10) : 0;
      if (i + 1 >= argc || *end != '\0' || cap < 1) {
        std::cerr << "aco-plugin-check: --integer-cap needs a whole number >= 1\n" << usage;
        return 2;
      }
      options.integer_cap = cap;
      ++i;
    } else if (arg == "--set") {
      const std::string setting = i + 1 < argc ? argv[i + 1] : "";
      const auto equals = setting.find('=');
      if (equals == std::string::npos || equals == 0) {
        std::cerr << "aco-plugin-check: --set needs NAME=VALUE\n" << usage;
        return 2;
      }
      options.fixed[setting.substr(0, equals)] = setting.substr(equals + 1);
      ++i;
    } else if (arg.rfind("--", 0) == 0) {
      std::cerr << "aco-plugin-check: unknown option " << arg << "\n" << usage;
      return 2;
    } else {
      files.push_back(arg);
    }
  }
  if (files.empty()) {
    std::cerr << usage;
    return 2;
  }
  int checks = 0, failed = 0;
  try {
    for (const auto& file : files)
      failed += aco::conformance::check_file(file, options, [&](const aco::conformance::CheckResult& result) {
        ++checks;
        std::cout << result.line() << std::endl;
      });
  } catch (const std::exception& e) {
    std::cerr << "aco-plugin-check: error: " << e.what() << "\n";
    return 1;
  }
  std::cout << "aco-plugin-check: " << checks << " checks, " << failed << " failed\n";
  return failed == 0 ? 0 : 1;
}

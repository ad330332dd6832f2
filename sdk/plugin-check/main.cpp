// aco-plugin-check FILE.so|FOLDER...: the conformance checks (aco/sdk/conformance.hpp) on every plugin
// in each file (a folder: each aco_*.so in it), on 2D maps and, for a plugin that claims them, on
// voxel worlds ("3D ..." lines), one line per check, then the failures again;
// exits 1 (aco::kExitError) if any check failed, 2 (aco::kExitUsage) on a usage error.
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "aco/sdk/conformance.hpp"
#include "aco/hosts/host_options.hpp"
#include "aco/process/version.hpp"

int main(int argc, char** argv) {
  return aco::run_command("aco-plugin-check", [&] {
    const std::string usage =
        "usage: aco-plugin-check [--integer-cap N] [--set NAME=VALUE]... FILE.so|FOLDER...   (or --version)\n"
        "Runs every plugin in each file at its defaults and at the ends of its parameter ranges on tiny maps and\n"
        "checks that its values are finite and non-negative, that it is deterministic per seed, that 1 and 4\n"
        "threads give the same result, and that an object reused for another run gives what a fresh one gives.\n"
        "A plugin that claims voxel worlds (supports_voxel_worlds()) is checked again on small voxel worlds\n"
        "(26-neighbourhood): lines '3D values', '3D deterministic', '3D threads', '3D reused'; one that does not\n"
        "gets a line 'SKIP ... 3D: not run in 3D'.\n"
        "Whole-number range ends above N (default 100) are run at N. --set gives a parameter the value every run\n"
        "starts from (a text parameter, such as the python plugins' class). A FOLDER checks every plugin library\n"
        "(aco_*.so) in it.\n";
    aco::conformance::Options options;
    std::vector<std::string> files;
    for (int i = 1; i < argc; ++i) {
      const std::string arg = argv[i];
      if (arg == "--help" || arg == "-h") {
        std::cout << usage;
        return aco::kExitOk;
      }
      if (arg == "--version") {
        std::cout << aco::version_text("aco-plugin-check") << "\n";
        return aco::kExitOk;
      }
      if (arg == "--integer-cap") {
        char* end = nullptr;
        const long long cap = i + 1 < argc ? std::strtoll(argv[i + 1], &end, 10) : 0;
        if (i + 1 >= argc || *end != '\0' || cap < 1) {
          std::cerr << "aco-plugin-check: --integer-cap needs a whole number >= 1\n" << usage;
          return aco::kExitUsage;
        }
        options.integer_cap = cap;
        ++i;
      } else if (arg == "--set") {
        const std::string setting = i + 1 < argc ? argv[i + 1] : "";
        const auto equals = setting.find('=');
        if (equals == std::string::npos || equals == 0) {
          std::cerr << "aco-plugin-check: --set needs NAME=VALUE\n" << usage;
          return aco::kExitUsage;
        }
        options.fixed[setting.substr(0, equals)] = setting.substr(equals + 1);
        ++i;
      } else if (arg.rfind("--", 0) == 0) {
        std::cerr << "aco-plugin-check: unknown option " << arg << "\n" << usage;
        return aco::kExitUsage;
      } else if (std::filesystem::is_directory(arg)) {
        std::vector<std::string> in_folder;
        for (const auto& entry : std::filesystem::directory_iterator(arg)) {
          const std::string name = entry.path().filename().string();
          if (name.rfind("aco_", 0) == 0 && entry.path().extension() == ".so")
            in_folder.push_back(entry.path().string());
        }
        if (in_folder.empty()) {
          std::cerr << "aco-plugin-check: " << arg << ": a folder with no plugin library (aco_*.so) in it\n";
          return aco::kExitUsage;
        }
        std::sort(in_folder.begin(), in_folder.end());
        files.insert(files.end(), in_folder.begin(), in_folder.end());
      } else {
        files.push_back(arg);
      }
    }
    if (files.empty()) {
      std::cerr << usage;
      return aco::kExitUsage;
    }
    int checks = 0, failed = 0;
    std::vector<std::string> failures;
    for (const auto& file : files) {
      try {
        failed += aco::conformance::check_file(file, options, [&](const aco::conformance::CheckResult& result) {
          ++checks;
          std::cout << result.line() << std::endl;
          if (result.status == aco::conformance::CheckResult::Status::fail) failures.push_back(result.line());
        });
      } catch (const std::exception& e) {  // a file that is no plugin, or cannot load: the others are still checked
        const std::string line = "FAIL " + file + " loads: " + e.what();
        std::cout << line << std::endl;
        failures.push_back(line);
        ++checks, ++failed;
      }
    }
    std::cout << "aco-plugin-check: " << checks << " checks, " << failed << " failed\n";
    for (const auto& failure : failures) std::cout << "  " << failure << "\n";
    return failed == 0 ? aco::kExitOk : aco::kExitError;
  });
}

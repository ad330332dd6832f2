// acoplan: one planning run, composed from runtime plugins on the command line.
#include <iostream>

#include "aco/crash_report.hpp"
#include "aco/plugin_guard.hpp"
#include "acoplan.hpp"

int main(int argc, char** argv) {
  aco::report_crashes("acoplan");
  try {
    acoplan::Request request = acoplan::parse_command_line(argc, argv);
    return acoplan::run(request, std::cout);
  } catch (...) {  // anything, a std::exception or not, is reported and exits 1
    std::cerr << "acoplan: error: " << aco::describe_current_exception() << "\n";
  }
  return acoplan::kExitError;
}

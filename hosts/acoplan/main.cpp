// acoplan: one planning run, composed from runtime plugins on the command line.
#include <iostream>

#include "acoplan.hpp"

int main(int argc, char** argv) {
  try {
    acoplan::Request request = acoplan::parse_command_line(argc, argv);
    return acoplan::run(request, std::cout);
  } catch (const std::exception& e) {
    std::cerr << "acoplan: error: " << e.what() << "\n";
  }
  return acoplan::kExitError;
}

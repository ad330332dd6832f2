// acoplan: one planning run, composed from runtime plugins on the command line.
#include <iostream>

#include "aco/hosts/host_options.hpp"
#include "acoplan.hpp"

int main(int argc, char** argv) {
  return aco::run_command("acoplan", [&] {
    acoplan::Request request = acoplan::parse_command_line(argc, argv);
    return acoplan::run(request, std::cout);
  });
}

#pragma once
// Boost.ProgramOptions' errors build their message in what(), replacing each "%name%"
// placeholder of a template with text, much of it the user's (an option as typed, a value, a
// config file line), until no "%name%" is left: text that contains its own placeholder
// ("acosim --batch %value%") loops forever, and text naming a later one is rewritten. Report
// these errors with program_options_message(), never with what().
#include <boost/program_options/errors.hpp>
#include <string>

namespace aco {

// Boost's message with the user's text shown as typed. Escapes that text inside `e`.
std::string program_options_message(boost::program_options::error& e);

}  // namespace aco

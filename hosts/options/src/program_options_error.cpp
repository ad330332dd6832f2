#include "aco/hosts/program_options_error.hpp"

#include <algorithm>

namespace aco {
namespace {

namespace po = boost::program_options;

// error_with_option_name keeps the text it substitutes in a protected map; a pointer to that
// member, taken through a subclass, reaches it in any error.
struct SubstitutionsOf : po::error_with_option_name {
  static auto member() { return &SubstitutionsOf::m_substitutions; }
};

// Stands for '%' in that text while Boost formats: no placeholder contains it.
constexpr char kPercent = '\x01';

}  // namespace

std::string program_options_message(po::error& e) {
  auto* named = dynamic_cast<po::error_with_option_name*>(&e);
  if (!named) return e.what();  // its message was complete when thrown
  for (auto& [placeholder, text] : named->*SubstitutionsOf::member())
    std::replace(text.begin(), text.end(), '%', kPercent);
  std::string message = named->what();
  std::replace(message.begin(), message.end(), kPercent, '%');
  return message;
}

}  // namespace aco

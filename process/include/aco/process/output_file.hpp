#pragma once
// Every file a command writes (pictures, trajectories, parameter files) is written one way: its
// folder made when missing, the text written beside it and renamed over it when complete, so a
// reader (or a run stopped halfway) never leaves half a file where a whole one was; a failure
// names the file and the reason.
#include <boost/config.hpp>
#include <filesystem>
#include <string>
#include <string_view>

namespace aco {

// Writes `text` to `file`. A device, pipe or other non-regular file (/dev/stdout) is written in
// place, since it cannot be replaced. Throws Error "FILE: cannot write the KIND file: REASON"
// (`kind`: "SVG", "trajectory CSV", ...; empty: "cannot write the file").
BOOST_SYMBOL_VISIBLE void write_output_file(const std::filesystem::path& file, std::string_view text,
                                            const std::string& kind = "");

}  // namespace aco

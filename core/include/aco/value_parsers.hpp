#pragma once
// Values as people write them in the hosts' options and the experiment files: sizes of memory and
// times in seconds. Each parser's error names the option (or key) it read.
#include <boost/config.hpp>
#include <cstdint>
#include <string>

namespace aco {

// A size as --max-memory takes it: bytes ("1048576") or a whole number with a binary unit K, M,
// G or T, optionally followed by B or iB, any case ("512M", "4G", "2GiB"). Zero, negative,
// fractional, overflowing or unknown-unit sizes are an Error naming `option`.
BOOST_SYMBOL_VISIBLE std::uint64_t parse_memory_size(const std::string& text,
                                                     const std::string& option = "--max-memory");

// A time limit as --trial-timeout, --variation-timeout and an experiment's trial-timeout take it:
// seconds, a positive number ("30", "0.5"). Anything else is an Error naming `option`.
BOOST_SYMBOL_VISIBLE double parse_seconds(const std::string& text, const std::string& option);

}  // namespace aco

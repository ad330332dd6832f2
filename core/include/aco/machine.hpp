#pragma once
// What the system tells about this machine and this process (Linux's /proc, sysconf,
// gethostname, the affinity mask), read here and nowhere else. What cannot be read is 0, "" or
// NaN, as each says; only this_program() throws.
#include <sys/types.h>

#include <boost/config.hpp>
#include <cstdint>
#include <string>

namespace aco {

// --- the machine ---

// Its name ("" if unknown).
BOOST_SYMBOL_VISIBLE std::string hostname();
// The CPU model and thread count, "<model name> (<n> threads)", as OMPL's benchmarks record their
// cpuinfo: for reading results, not for using them.
BOOST_SYMBOL_VISIBLE std::string cpu_description();
// The memory available to new work without swapping (MemAvailable of /proc/meminfo), bytes; 0 if it
// cannot be read.
BOOST_SYMBOL_VISIBLE std::uint64_t available_memory();
// The physical memory (sysconf), bytes; 0 if unknown.
BOOST_SYMBOL_VISIBLE std::uint64_t physical_memory();

// --- processes ---

// The CPUs this process may use: its affinity mask, which a launcher such as mpirun or srun may
// have narrowed (every CPU, at least 1, where the mask cannot be read).
BOOST_SYMBOL_VISIBLE int usable_cpus();
// The resident memory of process `pid`, bytes (0 if it cannot be read).
BOOST_SYMBOL_VISIBLE std::uint64_t resident_memory(pid_t pid);
// The file of the program this process runs (/proc/self/exe's target); an Error if it cannot be
// found.
BOOST_SYMBOL_VISIBLE std::string this_program();
// The peak resident memory of this process since it started or reset_peak_memory(), MiB; NaN
// where the system does not tell it (no /proc/self/status).
BOOST_SYMBOL_VISIBLE double peak_memory_mib();
// Starts the peak over from the memory resident now (Linux's /proc/self/clear_refs); false where
// the system cannot.
BOOST_SYMBOL_VISIBLE bool reset_peak_memory();

}  // namespace aco

#pragma once
// The plugin record: what a host needs to list a plugin and to decide whether it may load it,
// readable from the library file without loading it (loading runs the library's initialisers,
// and a library built for another ABI or standard library, or a corrupted one, may crash in them).
//
// ACO_PLUGIN writes one record per plugin into the ELF section ".aco_plugins": NUL-separated
// text fields
//
//   ACOP \0 <plugin ABI> \0 <standard library> \0 <compiler> \0 <build> \0 <slot> \0 <name> \0 <version> \0 <summary>
//   \0
//
// Records of several plugins in one library follow each other, perhaps with NUL padding between.
// The first two fields keep their meaning in every ABI version; the others may change with it.
#include <cstddef>  // defines the standard library's identifying macros used below
#include <cstdint>
#include <string>

#define ACO_PLUGIN_RECORD_SECTION ".aco_plugins"
#define ACO_PLUGIN_RECORD_MAGIC "ACOP"

// Which standard library, and which of its ABIs, a plugin's std::string, std::vector... follow.
// Host and plugin must agree on it; the compiler need not be the same (clang with libstdc++ is
// compatible with g++). libstdc++'s old string ABI (_GLIBCXX_USE_CXX11_ABI=0) mangles and lays out
// std::string differently, and libc++ is another library altogether.
#if defined(_LIBCPP_VERSION)
#define ACO_PLUGIN_STDLIB "libc++"
#elif defined(__GLIBCXX__) && _GLIBCXX_USE_CXX11_ABI
#define ACO_PLUGIN_STDLIB "libstdc++ (C++11 string ABI)"
#elif defined(__GLIBCXX__)
#define ACO_PLUGIN_STDLIB "libstdc++ (old string ABI, _GLIBCXX_USE_CXX11_ABI=0)"
#else
#define ACO_PLUGIN_STDLIB "unknown standard library"
#endif

// How the code that expands it was compiled (GCC and clang define __OPTIMIZE__ from -O1 on, CMake's
// Release and RelWithDebInfo define NDEBUG): the times of an unoptimised (Debug) build mean little,
// and acobench's report warns of one. The plugin record and acobench's results database carry it.
#if defined(__OPTIMIZE__) && defined(NDEBUG)
#define ACO_BUILD_OPTIMISATION "optimised"
#elif defined(__OPTIMIZE__)
#define ACO_BUILD_OPTIMISATION "optimised, assertions on"
#else
#define ACO_BUILD_OPTIMISATION "unoptimised"
#endif

namespace aco {

// Whether a build of ACO_BUILD_OPTIMISATION's text is an unoptimised one.
inline bool unoptimised(const std::string& build) { return build.rfind("unoptimised", 0) == 0; }

struct PluginRecord {
  std::string abi;  // as written: a number, unless the library is not what it claims
  std::string stdlib;
  std::string compiler;  // __VERSION__ of the compiler that built the plugin, for information
  std::string build;  // ACO_BUILD_OPTIMISATION as the plugin was compiled
  std::string slot;
  std::string name;
  std::string version;
  std::string summary;
};

// The standard-library marker of this framework's build.
inline constexpr const char* kHostStdlib = ACO_PLUGIN_STDLIB;

}  // namespace aco

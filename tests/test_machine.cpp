// What the system tells about this machine and this process (aco/machine.hpp).
#include <sys/mman.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cstring>
#include <filesystem>
#include <string>

#include "aco/machine.hpp"

TEST_CASE("the machine's name, CPU and memory are read", "[machine]") {
  char name[256] = {};
  REQUIRE(gethostname(name, sizeof name - 1) == 0);
  CHECK(aco::hostname() == name);
  CHECK_THAT(aco::cpu_description(), Catch::EndsWith(" threads)"));
  CHECK(aco::available_memory() > 0);
  CHECK(aco::physical_memory() >= aco::available_memory());
  CHECK(aco::usable_cpus() >= 1);
}

TEST_CASE("a process's resident memory and program file are read", "[machine]") {
  CHECK(aco::resident_memory(getpid()) > 0);
  CHECK(aco::resident_memory(-1) == 0);  // no such process
  CHECK(std::filesystem::equivalent(aco::this_program(), "/proc/self/exe"));
}

TEST_CASE("a process's peak memory rises with what it touches and starts over when reset", "[machine]") {
  constexpr double kBlockMib = 64;
  REQUIRE(aco::reset_peak_memory());
  const double before = aco::peak_memory_mib();
  REQUIRE(before > 0);
  // Mapped and unmapped directly: a block from the allocator may stay resident once freed
  // (AddressSanitizer keeps freed memory in quarantine).
  const std::size_t size = static_cast<std::size_t>(kBlockMib * 1024 * 1024);
  void* block = mmap(nullptr, size, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  REQUIRE(block != MAP_FAILED);
  std::memset(block, 1, size);  // touched: resident
  CHECK(aco::peak_memory_mib() >= before + kBlockMib - 1);
  REQUIRE(munmap(block, size) == 0);
  REQUIRE(aco::reset_peak_memory());  // the block is given back: the peak is what is resident now
  CHECK(aco::peak_memory_mib() < before + kBlockMib / 2);
}

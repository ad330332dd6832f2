// Values as people write them in options and experiment files (aco/value_parsers.hpp).
#include <catch2/catch.hpp>

#include <string>

#include "aco/memory_limit.hpp"
#include "aco/value_parsers.hpp"

using Catch::Contains;

TEST_CASE("memory sizes: bytes or K, M, G, T (binary), anything else refused", "[memory][bad-input]") {
  CHECK(aco::parse_memory_size("1048576") == 1048576);
  CHECK(aco::parse_memory_size("512M") == 512ull << 20);
  CHECK(aco::parse_memory_size("4G") == 4ull << 30);
  CHECK(aco::parse_memory_size("4g") == 4ull << 30);
  CHECK(aco::parse_memory_size("2GiB") == 2ull << 30);
  CHECK(aco::parse_memory_size("3kb") == 3ull << 10);
  CHECK(aco::parse_memory_size("1T") == 1ull << 40);
  for (const char* bad :
       {"", "0", "0G", "-1", "-4G", "1.5G", "4X", "G", "4 G", " 4G", "4GB2", "17179869184T", "99999999999999999999"})
    CHECK_THROWS_WITH(aco::parse_memory_size(bad), Contains("--max-memory: '" + std::string(bad) + "'"));
  CHECK_THROWS_WITH(aco::parse_memory_size("17179869184T"), Contains("too large"));
  CHECK_THROWS_WITH(aco::parse_memory_size("4X"), Contains("unknown unit"));
  CHECK(aco::format_bytes(100) == "100 bytes");
  CHECK(aco::format_bytes(3ull << 29) == "1.5 GiB");
  CHECK(aco::format_bytes(512ull << 20) == "512 MiB");
}

TEST_CASE("times in seconds: a positive number, anything else refused", "[bad-input]") {
  CHECK(aco::parse_seconds("30", "--trial-timeout") == 30.0);
  CHECK(aco::parse_seconds("0.5", "--trial-timeout") == 0.5);
  CHECK(aco::parse_seconds("1e3", "--trial-timeout") == 1000.0);
  for (const char* bad : {"", "0", "-1", "soon", "5s", " 5", "inf", "nan"})
    CHECK_THROWS_WITH(aco::parse_seconds(bad, "trial-timeout"),
                      Contains("trial-timeout: '" + std::string(bad) + "' is not a time in seconds"));
}

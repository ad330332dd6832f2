#pragma once
// The hosts' --threads option: at most N worker threads while a ThreadLimit lives (0 = all
// cores). Results never depend on it (ants and trials draw from their own random streams).
#include <tbb/global_control.h>

#include <cstdint>
#include <optional>

namespace aco {

class ThreadLimit {
 public:
  explicit ThreadLimit(std::int64_t threads) {
    if (threads > 0) limit_.emplace(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
  }

 private:
  std::optional<tbb::global_control> limit_;
};

}  // namespace aco

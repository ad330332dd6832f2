#pragma once
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>

namespace aco::colony_detail {

// The run's time limit (ColonySettings::time_limit), seen inside an iteration: on a large map one
// iteration's walks take seconds, so an ant looks at the clock every kMovesPerLook moves, and once
// one has seen the limit pass, every ant stops where it is (a walk cut short has not arrived).
class Deadline {
 public:
  using Clock = std::chrono::steady_clock;
  // About 0.1 ms of walking (20-70 ns a move); the clock costs about 20 ns a look.
  static constexpr std::uint64_t kMovesPerLook = 2048;

  Deadline(Clock::time_point started, double seconds)
      : limited_(seconds > 0.0),
        end_(started + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds))) {}

  // Whether the limit has passed, the clock read on every kMovesPerLook-th move of a walk.
  bool passed(std::uint64_t moves) const {
    if (!limited_) return false;
    if (passed_.load(std::memory_order_relaxed)) return true;
    return moves % kMovesPerLook == 0 && look();
  }
  bool passed() const { return limited_ && (passed_.load(std::memory_order_relaxed) || look()); }
  // Ends the search this much earlier, for work after it, but takes at most half of the time
  // left: the walks must still have some. Before the walks begin.
  void hold_back(Clock::duration reserve) const {
    if (limited_) end_ -= std::min(reserve, std::max(Clock::duration::zero(), (end_ - Clock::now()) / 2));
  }

 private:
  bool look() const {
    if (Clock::now() < end_) return false;
    passed_.store(true, std::memory_order_relaxed);
    return true;
  }

  bool limited_;
  mutable Clock::time_point end_;
  mutable std::atomic<bool> passed_{false};
};

}  // namespace aco::colony_detail

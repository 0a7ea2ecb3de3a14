// The end of a solve's time budget, for the long loops inside one iteration (line searches,
// damping retries, building a large normal matrix) to give up at, not only between iterations.
#pragma once

#include <chrono>

namespace ik {

class Deadline {
 public:
  using Clock = std::chrono::steady_clock;
  // A deadline that never passes (no time budget).
  Deadline() = default;
  explicit Deadline(Clock::time_point end) : end_(end), set_(true) {}
  // Reads the clock (in WebAssembly a call out to JavaScript, about 65 ns).
  bool passed() const { return set_ && Clock::now() >= end_; }

 private:
  Clock::time_point end_{};
  bool set_ = false;
};

}  // namespace ik

// A solve's time budget: the seconds spent inside start() and step() calls, each call timed from
// its beginning to one closing clock read, and the deadline by which the running call must give up.
#pragma once

#include <chrono>

#include "deadline.h"

namespace ik {

class TimeBudget {
 public:
  using Clock = std::chrono::steady_clock;

  // A new solve with a budget of `seconds` (0 or infinity: none); nothing spent yet.
  void reset(double seconds) {
    budget_ = seconds;
    spent_ = 0;
  }
  // A call began at `begin` (the time it counts from).
  void open(Clock::time_point begin) { call_start_ = begin; }
  // Reads the clock once and adds the time since the open call began to the time spent.
  void close();

  // Seconds spent in closed calls.
  double spent() const { return spent_; }
  // A finite budget is set.
  bool limited() const;
  // A finite budget is set and the closed calls have spent it.
  bool used_up() const { return limited() && spent_ >= budget_; }
  // When the open call must give up: its start plus what the budget has left (never without a
  // budget, or with more than a year left).
  Deadline deadline() const;
  // When the open call began, and the last closing clock read.
  Clock::time_point call_start() const { return call_start_; }
  Clock::time_point last_read() const { return last_read_; }

 private:
  double budget_ = 0, spent_ = 0;
  Clock::time_point call_start_{}, last_read_{};
};

}  // namespace ik

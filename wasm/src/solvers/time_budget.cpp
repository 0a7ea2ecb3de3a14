#include "time_budget.h"

#include <cmath>

namespace ik {

void TimeBudget::close() {
  last_read_ = Clock::now();
  spent_ += std::chrono::duration<double>(last_read_ - call_start_).count();
}

bool TimeBudget::limited() const { return budget_ > 0 && !std::isinf(budget_); }

Deadline TimeBudget::deadline() const {
  constexpr double kYear = 3.2e7;  // seconds; a longer budget is none (and would overflow the clock)
  if (!limited() || budget_ - spent_ > kYear) return Deadline();
  const auto left = std::chrono::duration<double>(budget_ - spent_);
  return Deadline(call_start_ + std::chrono::duration_cast<Clock::duration>(left));
}

}  // namespace ik

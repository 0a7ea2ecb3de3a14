// Time to success: how long a method takes to reach its targets, counting only the solves that did.
// A method that gives up early has a short mean time over all its solves; here it can no longer look
// faster than one that succeeds. Per row: the median and p95 time of the successful solves, and the
// share of the (reachable) samples solved within 1, 10 and 100 ms. Times in seconds.
import { median, quantile } from './statistics.js';

/** The budgets of the "solved within" columns, seconds. */
export const SUCCESS_BUDGETS_S = [1e-3, 1e-2, 1e-1] as const;

export interface TimeToSuccess {
  /** Median and 95th percentile of the successful solves' times, seconds; null when none succeeded. */
  t_success_median_s: number | null;
  t_success_p95_s: number | null;
  /** Share of the judged (reachable) samples that succeeded within 1, 10 and 100 ms. */
  success_within_1ms: number;
  success_within_10ms: number;
  success_within_100ms: number;
}

/**
 * Time to success over `judged` solves (the reachable ones): `seconds[k]` each solve's time,
 * `succeeded[k]` whether it reached its target. Shares are NaN when nothing was judged.
 */
export function timeToSuccess(seconds: readonly number[], succeeded: readonly boolean[]): TimeToSuccess {
  const times = seconds.filter((_, k) => succeeded[k]);
  const within = (budget: number): number =>
    seconds.length ? times.filter((t) => t <= budget).length / seconds.length : NaN;
  return {
    t_success_median_s: times.length ? median(times) : null,
    t_success_p95_s: times.length ? quantile(times, 0.95) : null,
    success_within_1ms: within(SUCCESS_BUDGETS_S[0]),
    success_within_10ms: within(SUCCESS_BUDGETS_S[1]),
    success_within_100ms: within(SUCCESS_BUDGETS_S[2]),
  };
}

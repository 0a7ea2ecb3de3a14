// The restart policy our solvers apply, given to a peer by the harness: when a run ends off target
// with time left, the peer solves again from the next restart start, the same quasi-random points
// inside the limits our solvers restart from (IkRig.restartStart, seed 1 like their default), at
// most `restarts` times within the one time budget of the solve, and the best result is kept.
// A peer's run ends on its own exits (CCD's stall rule, closed-chain-ik's stall and diverge
// tests); those play the part of our solvers' stall rule. Chained solves (drag, reach) never
// restart: the benchmark runs them with restarts 0, as the page drags.
import { isOnTarget } from '../evaluate.js';
import type { SolveResult } from '../metrics.js';
import type { Runner, RunSettings, SolveInput } from '../runner.js';

export class RestartingRunner implements Runner {
  /**
   * `inner`: the peer; `startOf(k)`: the k-th restart start (k >= 1, degrees); `restarts`: how many
   * at most per solve. `settings`: the run's on-target test and time budget.
   */
  constructor(
    private readonly inner: Runner,
    private readonly startOf: (k: number) => Float64Array,
    private readonly settings: RunSettings,
    private readonly restarts: number,
    private readonly onDispose: () => void = () => {},
  ) {}

  solve(input: SolveInput): SolveResult {
    const budget = input.budgetSeconds ?? this.settings.timeBudgetSeconds;
    const t0 = performance.now();
    let best = this.inner.solve({ ...input, budgetSeconds: budget });
    if (input.start === null || this.restarts === 0) return best;
    let iterations = best.iterations;
    for (let k = 1; k <= this.restarts && !this.reached(best); k++) {
      const left = budget - (performance.now() - t0) / 1000;
      if (left <= 0) break;
      const last = this.inner.solve({ ...input, start: this.startOf(k), budgetSeconds: left });
      iterations += last.iterations;
      if ((this.reached(last) && !this.reached(best)) || last.E < best.E) best = last;
    }
    const seconds = (performance.now() - t0) / 1000;
    const outOfTime = !this.reached(best) && seconds >= budget;
    return { ...best, iterations, seconds, stopReason: outOfTime ? 'timeout' : best.stopReason };
  }

  dispose(): void {
    this.inner.dispose();
    this.onDispose();
  }

  private reached(r: SolveResult): boolean {
    return isOnTarget(this.settings, r.E, r.tipDistance, r.rotErrDeg);
  }
}

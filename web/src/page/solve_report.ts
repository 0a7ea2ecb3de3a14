// What the page's side column reports of the solves: the stats of each per-frame solve and step
// (with the tip error in screen pixels and the pinned effectors' drift), E at a pose nobody
// solved, the live convergence plot, and the slowest per-frame solve since the rig loaded.
import { Vector3 } from 'three';

import { largestTipDistance } from '../ik/tip_distance.js';
import type { LiveController } from '../view/live_controller.js';
import type { MethodList } from '../live/methods.js';
import type { SolveOutcome } from '../live/method_solver.js';
import type { PageSettings } from './page_settings.js';
import { ConvergencePlot } from './plots.js';
import { emptyStatsValues, StatsPanel, type StatsValues } from './stats.js';

/** The slowest per-frame solve: page ms, ms inside the solver, iterations, stop reason. */
export interface SlowestSolve {
  ms: number;
  solverMs: number;
  iterations: number;
  stopReason: string;
}

const v = new Vector3();

/** The solvers' orientation tolerance (the option orientationToleranceDeg's default), degrees. */
const ORIENTATION_TOLERANCE_DEG = 0.5;

export class SolveReport {
  readonly stats: StatsPanel;
  readonly plot: ConvergencePlot;
  /** The slowest per-frame solve since the rig loaded, or null. */
  slowest: SlowestSolve | null = null;
  /** Each method's last E history for the plot (its start; the plot is told the length). */
  private readonly histories = new Map<string, Float64Array>();
  /** The stats of the last solve (one record, rewritten by each). */
  private readonly values: StatsValues = emptyStatsValues();

  /** The stats and the plot go into `side`; `controller` shows the rig, `settings` name the method. */
  constructor(
    side: HTMLElement,
    methods: MethodList,
    private readonly controller: LiveController,
    private readonly settings: PageSettings,
  ) {
    this.stats = new StatsPanel(side);
    this.plot = new ConvergencePlot(side, methods);
  }

  /**
   * The plot shows the method's last solve that ran iterations. Read now, not when the plot draws:
   * by then a later solve that started on target (0 iterations) may have replaced it.
   */
  private plotLastSolve(): void {
    const method = this.settings.method,
      session = this.controller.live?.session;
    if (!session || session.lastIterations(method) === 0) return;
    // Copied into a buffer kept per method (grown when short): no new array per frame.
    let buffer = this.histories.get(method) ?? new Float64Array(64);
    let n = session.copyHistory(method, buffer);
    if (n > buffer.length) {
      buffer = new Float64Array(Math.max(n, 2 * buffer.length));
      n = session.copyHistory(method, buffer);
    }
    this.histories.set(method, buffer);
    this.plot.record(method, buffer, n);
  }

  /** A per-frame solve: its outcome, main-thread ms and the tips at the new pose (3 per effector). */
  solved(outcome: SolveOutcome, ms: number, tips: Float64Array): void {
    if (ms > (this.slowest?.ms ?? -1))
      this.slowest = {
        ms,
        solverMs: outcome.elapsedSeconds * 1000,
        iterations: outcome.iterations,
        stopReason: outcome.stopReason,
      };
    this.plotLastSolve();
    this.stats.show(this.valuesOf(outcome, ms, tips));
  }

  /** One step of step mode: its outcome and main-thread ms. */
  stepped(outcome: SolveOutcome, ms: number): void {
    const tips = this.controller.live?.session.tips();
    if (!tips) return;
    this.plotLastSolve();
    this.stats.showStep(this.valuesOf(outcome, ms, tips));
  }

  /**
   * Step mode, after the problem changed: the pose on screen measured against the new targets, its
   * status "not solved yet" unless it is on them, 0 iterations, no gradient and no time (nothing
   * ran). Written a few times a second while a target is dragged.
   */
  pending(): void {
    const session = this.controller.live?.session;
    if (!session) return;
    const tips = session.tips();
    const s = this.sharedValues(tips, session.targets);
    s.iterations = 0;
    s.E = session.objective();
    s.gradNorm = NaN;
    s.tipDistance = largestTipDistance(tips, session.targets);
    s.orientationErrorDeg = session.orientationErrorDeg();
    s.reached = s.tipDistance < this.settings.tipTolerance && !(s.orientationErrorDeg >= ORIENTATION_TOLERANCE_DEG);
    s.stopReason = 'not_started';
    s.outOfReach = s.orientationOutOfReach = false;
    s.ms = NaN;
    this.stats.showPending(s);
  }

  /**
   * Shows E at the current pose at once (a reset, a new rig, method, limits or effectors), before
   * the next frame's solve reports on it; in step mode, where no solve follows, it stays.
   */
  showIdle(): void {
    const live = this.controller.live;
    if (live) this.stats.showIdle(this.settings.method, live.session.objective(), this.settings.paperMode);
  }

  /** A new rig: empty stats and plot. */
  reset(): void {
    this.stats.reset();
    this.plot.clear();
    this.slowest = null;
    this.showIdle();
  }

  dispose(): void {
    this.plot.dispose();
  }

  /** The stats of one solve. Pinned: every effector but the selected target's (the one dragged, or last dragged). */
  private valuesOf(outcome: SolveOutcome, ms: number, tips: Float64Array): StatsValues {
    const s = this.sharedValues(tips, this.controller.live?.session.targets ?? tips);
    s.iterations = outcome.iterations;
    s.E = outcome.E;
    s.gradNorm = outcome.gradNorm;
    s.reached = outcome.reached;
    s.tipDistance = outcome.tipDistance;
    s.orientationErrorDeg = this.controller.live?.session.orientationErrorDeg() ?? NaN;
    s.stopReason = outcome.stopReason;
    s.outOfReach = outcome.outOfReach;
    s.orientationOutOfReach = outcome.orientationOutOfReach;
    s.ms = ms;
    return s;
  }

  /**
   * The stats record with what a solve and a pose nobody solved share written: the method, paper
   * mode, the pixels per rig unit at the selected target and the pinned effectors' drift (`tips`
   * from `targets`, the selected target's left out).
   */
  private sharedValues(tips: Float64Array, targets: Float64Array): StatsValues {
    const selected = this.controller.handles.selected;
    const k = Math.min(selected ?? 0, targets.length / 3 - 1);
    const s = this.values;
    s.method = this.settings.method;
    s.paperMode = this.settings.paperMode;
    s.pixelsPerUnit = k < 0 ? NaN : this.controller.stage.pixelsPerUnit(v.fromArray(targets, 3 * k));
    s.pinnedDrift = largestTipDistance(tips, targets, selected ?? -1);
    return s;
  }
}

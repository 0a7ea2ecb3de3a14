// Step mode (teaching): the per-frame solve stops and each S (or "one iteration", or the slow
// tick) takes one iteration of the current method from the pose on screen. The previous iterate
// shows as a ghost, and the step-info box says what the iteration did: E before and after and the
// step's length |ΔA| in degrees. Dragging a target, or any change, starts a new solve.
import { errorText } from '../live/error_text.js';
import type { LiveController } from '../view/live_controller.js';
import type { MethodList } from '../live/methods.js';
import type { IkSession } from '../live/session.js';
import type { SolveOutcome } from '../live/method_solver.js';
import { statusWords } from '../live/status_words.js';
import type { PageSettings } from './page_settings.js';

/** What the page does with a step. */
export interface StepHooks {
  /** One step was taken: its outcome and main-thread milliseconds. */
  stepped(outcome: SolveOutcome, ms: number): void;
  /** The step threw: `message` says why. */
  failed(message: string): void;
  /** Step mode was switched on by a step (the panel shows it). */
  switchedOn(): void;
  /** In step mode the problem changed (a target dragged): the pose on screen has not been solved for it. */
  pending(): void;
}

interface StepReport {
  outcome: SolveOutcome;
  ms: number;
  /** The pose before the step (the ghost), degrees. */
  before: Float64Array;
  /** |A_k+1 - A_k|, degrees. */
  stepLength: number;
  /** One line for the step-info box. */
  text: string;
}

/** True while a solve has not stopped ('' from a solver that reports no state). */
function isRunning(reason: string): boolean {
  return reason === '' || reason === 'running';
}

/**
 * One iteration of `method` from the session's pose (which becomes the iterate). `restart` begins
 * a new solve first (after the targets, the method or the pose changed); `label` names the method.
 */
function takeStep(
  session: IkSession,
  method: string,
  label: string,
  settings: PageSettings,
  restart: boolean,
): StepReport {
  if (restart || session.steppingMethod !== method) {
    const { gradientTolerance, tipTolerance, paperMode, strictPriority } = settings;
    session.beginSteps(method, {
      gradientTolerance,
      tipTolerance,
      paperMode,
      strictPriority,
      maxIterations: settings.compareMaxIterations,
      timeBudgetMs: Infinity,
      restarts: 0,
    });
  }
  const before = session.angles.slice();
  const E0 = session.objective();
  const t0 = performance.now();
  const outcome = session.step();
  const ms = performance.now() - t0;
  let len = 0;
  for (let j = 0; j < before.length; j++) len += (outcome.angles[j] - before[j]) ** 2;
  const stepLength = Math.sqrt(len);
  const state = isRunning(outcome.stopReason)
    ? 'running'
    : `stopped: ${statusWords(outcome, settings.paperMode).text} [${outcome.stopReason}]`;
  const text =
    `${label}${settings.paperMode ? ' (paper mode)' : ''}, iteration ${outcome.iterations}: E ${E0.toExponential(2)} → ${outcome.E.toExponential(2)}; ` +
    `|ΔA| = ${stepLength.toPrecision(3)}° (${state}). Faint bones: the previous iterate.`;
  return { outcome, ms, before, stepLength, text };
}

export class StepMode {
  /** The next step begins a new solve. */
  private dirty = true;
  private lastTick = 0;

  constructor(
    /** The step-info box (its data-iterations holds the last step's iteration count). */
    private readonly info: HTMLElement,
    private readonly settings: PageSettings,
    private readonly methods: MethodList,
    private readonly controller: LiveController,
    private readonly hooks: StepHooks,
  ) {}

  /**
   * The problem or the pose changed: the next step starts a new solve, the ghost goes, and in step
   * mode the stats show the pose on screen against the new targets (no per-frame solve follows).
   */
  restart(): void {
    this.dirty = true;
    if (!this.settings.stepMode) return;
    this.controller.live?.showGhost(null);
    this.hooks.pending();
    this.showInfo('The targets moved: press S (or “one iteration”) for an iteration towards them.');
    this.info.dataset.iterations = '0';
  }

  /** The step-mode switch changed (settings.stepMode): the per-frame solve stops or resumes. */
  switched(): void {
    const on = this.settings.stepMode;
    this.dirty = true;
    this.controller.solving = !on;
    if (on) {
      this.showInfo(
        'step mode: press S (or “one iteration”) to take one iteration; drag a target to pose a new problem',
      );
      return;
    }
    this.controller.live?.session.endSteps();
    this.controller.live?.showGhost(null);
    this.showInfo('');
    this.controller.invalidate();
  }

  /** Every frame: the slow tick takes a step every stepIntervalMs milliseconds. */
  tick(): void {
    const s = this.settings;
    if (!s.stepMode || !s.autoStep) return;
    const now = performance.now();
    if (now - this.lastTick < s.stepIntervalMs) return;
    this.lastTick = now;
    this.step();
  }

  /** One iteration of the current method (switching step mode on first). */
  step(): void {
    const live = this.controller.live;
    if (!live || this.controller.paused) return;
    if (!this.settings.stepMode) {
      this.settings.stepMode = true;
      this.controller.solving = false;
      this.hooks.switchedOn();
    }
    if (live.session.effectors().length === 0) return;
    const method = this.settings.method;
    try {
      const r = takeStep(live.session, method, this.methods.label(method), this.settings, this.dirty);
      this.dirty = false;
      live.showGhost(r.stepLength > 0 ? r.before : null);
      this.hooks.stepped(r.outcome, r.ms);
      this.showInfo(r.text);
      this.info.dataset.iterations = String(r.outcome.iterations);
      this.controller.redraw();
    } catch (e) {
      this.hooks.failed(`solver error: ${errorText(e)}`);
    }
  }

  /** Empties the step-info box (a new rig, a reset). */
  clearInfo(): void {
    this.showInfo('');
  }

  private showInfo(text: string): void {
    this.info.textContent = text;
    this.info.hidden = text === '';
  }
}

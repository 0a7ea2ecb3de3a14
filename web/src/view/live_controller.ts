// One live rig on a three.js stage, as both the page and the widget show it: the stage, the
// targets' gizmo, clicks on targets, and the frame loop. While a target is dragged, or after
// something changed, each frame solves from the current pose within the frame's budget (restarts
// off) and goes on next frame when the budget stopped it; the view is redrawn only when the pose,
// the targets or the selection changed. Targets may carry orientation goals (the rotate gizmo
// sets them; setOrientationGoal() turns them on or off). With pole handles on (setPoleHandles),
// each limb (pole_limbs.ts) has a pole handle the gizmo can take; its position is the limb's pole
// goal, sent with every solve (with them off, no poles are sent). The front ends hear of solves,
// errors and clicks through LiveEvents; everything else (stats, panels, status lines) is theirs.
import { Quaternion, Vector3 } from 'three';

import { Handles } from './handles.js';
import { listenForClicks, type ViewClick } from './picking.js';
import { Stage } from './stage.js';
import { errorText } from '../live/error_text.js';
import type { LiveRig } from './live_rig.js';
import { FRAME_LM_MU, FRAME_STEPS_BEFORE_BUDGET, solveFrame, type FrameTiming } from '../live/live_solve.js';
import { poleLimbs } from '../live/pole_limbs.js';
import { initialPole } from '../live/pole_placement.js';
import { restorePose, type PoseState } from '../live/pose_state.js';
import type { IkSession } from '../live/session.js';
import type { SolveOutcome, SolveSettings } from '../live/method_solver.js';
import { applyStillBody } from '../live/still_body.js';

/** What the per-frame solve reads every frame (the page's panel edits its settings in place). */
export interface FrameSettings {
  /** The method solving every frame: a name from the core's registry. */
  method: string;
  /** ||grad E|| tolerance, rig units^2 per degree. */
  gradientTolerance: number;
  /** On target within this distance of every target, rig units. */
  tipTolerance: number;
  /** Iterations per frame. */
  maxIterations: number;
  /** Milliseconds per frame. */
  timeBudgetMs: number;
  /** The report's algorithms. */
  paperMode: boolean;
  /** Strict priority between targets (SolveSettings.strictPriority); default true. */
  strictPriority?: boolean;
  /**
   * While a target is dragged, the other effectors keep the orientation they had when the drag
   * began, as well as their position (IkSession.pinOrientations); default true. Not in paper mode.
   */
  pinOrientations?: boolean;
  /** The farthest a joint moves in one frame, rig units (SolveSettings.maxJointMove; the rig's drag tolerances give it). Default 0: no cap. */
  maxJointMove?: number;
  /**
   * On a rig without a humanoid map, the bones the dragged target's chain does not need alone keep
   * their pose (a soft pull towards the solve's start; still_body.ts): lifting a paw moves its leg
   * only. Default true. Not in paper mode; a humanoid is solved as without it.
   */
  stillBody?: boolean;
}

/** What the controller tells its front end. Only `failed` is required. */
export interface LiveEvents {
  /**
   * After each per-frame solve: its outcome (the same object's fields may be rewritten by the next
   * solve), its main-thread milliseconds and the tips at the new pose (3 numbers per end effector,
   * in an array the next frame rewrites: copy what you keep).
   */
  solved?(outcome: SolveOutcome, ms: number, tips: Float64Array): void;
  /** A solve threw: `message` says why. No solve follows until something changes. */
  failed(message: string): void;
  /** The problem or the pose changed (a target moved, invalidate(), reset(), setEffectors()). */
  changed?(): void;
  /** The gizmo moved to another target (or none, or a pole handle), or a target's orientation goal was turned on or off. */
  targetChanged?(): void;
  /** A click or tap on the view that hit no target (a target hit takes the gizmo). */
  clicked?(click: ViewClick): void;
  /** Dragging a target started (true) or stopped (false). */
  dragging?(on: boolean): void;
  /** After the view was redrawn from the session. */
  redrawn?(): void;
  /** First thing in every frame while a rig is shown and the controller is not paused. */
  tick?(): void;
}

const v = new Vector3();

export class LiveController {
  readonly stage: Stage;
  readonly handles: Handles;
  /** False: no per-frame solve (the page's step mode); edits are still drawn. */
  solving = true;
  /** True: no solve and no redraw (the page's compare is using the session). */
  paused = false;
  private current: LiveRig | null = null;
  private needsSolve = false;
  /** The last frame had a target dragged (the drag's first frame pinned the orientations). */
  private pinnedDrag = false;
  private needsRedraw = false;
  /**
   * The target whose drag the last solve was part of, when its budget stopped it before the
   * problem was solved (else null): the solves that finish a drag solve it as the drag did (a
   * floating humanoid's hips stay free, hips_target.ts) after the mouse is released.
   */
  private dragTail: number | null = null;
  private readonly timing: FrameTiming = { ms: 0, again: false };
  /**
   * The next solve is the first of a rig shown: it runs once untimed first (and its pose is put
   * back), so the time shown is a solve's, not the WebAssembly's and JavaScript's warm-up (the
   * lamp's first solve read 6.7 ms for 0 iterations in Chromium; warmed, 0.07 ms).
   */
  private warmUp = false;
  private readonly solveSettings: SolveSettings = {
    gradientTolerance: 0,
    tipTolerance: 0,
    maxIterations: 0,
    timeBudgetMs: 0,
    restarts: 0,
    paperMode: false,
    stepsBeforeBudget: FRAME_STEPS_BEFORE_BUDGET,
  };
  private readonly stopClicks: () => void;
  private polesOn = false;
  /** The limbs' joints (elbow, knee) at the last redraw, 3 per pole, rig units: where the pole lines start. */
  private poleJoints = new Float64Array(0);
  /** The tips after a frame's solve, 3 per effector (rewritten every frame; resized when the effectors change). */
  private tips = new Float64Array(0);

  /** Makes a stage in `container`; `settings` are read every frame (and may be edited in place). */
  constructor(
    container: HTMLElement,
    readonly settings: FrameSettings,
    private readonly events: LiveEvents,
  ) {
    this.stage = new Stage(container);
    const handles = new Handles(this.stage); // before the orbit connects: a drag on the gizmo must not orbit
    this.handles = handles;
    this.stage.connectOrbit();
    handles.onTargetMoved = (k, x, y, z) => this.moveTarget(k, x, y, z);
    handles.onTargetTurned = (k, q) => this.turnTarget(k, q);
    handles.onPoleMoved = (j, x, y, z) => this.movePole(j, x, y, z);
    handles.currentRotation = (k, out) => this.currentRotation(k, out);
    handles.onSelected = () => this.events.targetChanged?.();
    handles.onDragging = (on) => this.events.dragging?.(on);
    this.stopClicks = listenForClicks(
      this.stage.canvas,
      this.stage.camera,
      () => handles.dragging || handles.hovering,
      (c) => this.click(c),
    );
    this.stage.onFrame(() => this.frame());
  }

  /** The rig shown, or null. */
  get live(): LiveRig | null {
    return this.current;
  }

  /**
   * Shows `live` instead of the rig shown (which is disposed); the controller owns it from now on.
   * A solve follows at the next frame.
   */
  show(live: LiveRig): void {
    this.removeRig();
    this.current = live;
    this.dragTail = null;
    this.stage.scene.add(...live.objects);
    this.handles.setRigSize(live.view.size);
    this.handles.select(null);
    this.handles.setTargets(live.session.targets);
    this.handles.setPivot(live.view.boneBase(0, v));
    this.placePoles(false);
    this.stage.frame(live.view.bounds()); // and draws it
    // A first solve: it stops before a step (the targets sit on the tips), so the status says so.
    this.needsSolve = true;
    this.warmUp = true;
    this.needsRedraw = true;
  }

  /** Something the solve depends on changed (settings, method, limits): solve again and redraw. */
  invalidate(): void {
    this.needsSolve = true;
    this.needsRedraw = true;
    this.events.changed?.();
  }

  /** Redraw next frame (the pose or the selection changed outside the per-frame solve). */
  redraw(): void {
    this.needsRedraw = true;
  }

  /**
   * Back to the rest pose with the targets on the rest tips, no orientation goals and the poles
   * placed anew. A solve follows: it stops at once, on target, so the stats describe the rest pose.
   */
  reset(): void {
    const live = this.current;
    if (!live) return;
    live.session.reset();
    this.dragTail = null;
    live.showGhost(null);
    this.handles.setTargets(live.session.targets);
    this.placePoles(false);
    this.invalidate();
    this.events.targetChanged?.();
  }

  /**
   * Makes `state` (pose_state.ts) the rig's pose, effectors, targets and goals, as undo, redo and a
   * pose file do. Poles follow the pole-handle switch: a limb the state had a pole for keeps it.
   * The pose is shown as it was, then solved from: a pose on target stays as it is (the solve stops
   * before a step) and the stats describe it; one off target goes on as the page would have.
   * Throws, changing nothing, for another rig's state.
   */
  restore(state: PoseState): void {
    const live = this.current;
    if (!live) return;
    restorePose(live.session, state);
    this.dragTail = null;
    live.showGhost(null);
    this.handles.setTargets(live.session.targets);
    this.placePoles(true);
    this.invalidate();
    this.events.targetChanged?.();
  }

  /** Whether target k (effector index) has an orientation goal. */
  orientationGoal(k: number): boolean {
    return this.current?.session.goals.orientation[k] === 1;
  }

  /**
   * Turns target k's orientation goal on (at the effector's current frame, so nothing jumps until
   * the target is turned) or off, and solves again.
   */
  setOrientationGoal(k: number, on: boolean): void {
    const session = this.current?.session;
    if (!session || k < 0 || k >= session.goals.count || this.orientationGoal(k) === on) return;
    session.setOrientationGoal(k, on);
    this.invalidate();
    this.events.targetChanged?.();
  }

  /** Whether the limbs show pole handles (and their poles are sent with every solve). */
  get poleHandles(): boolean {
    return this.polesOn;
  }

  /**
   * Pole handles on (each limb's pole placed anew where its joint bends, pole_placement.ts) or off
   * (no poles sent), for this rig and the ones shown after it; solves again.
   */
  setPoleHandles(on: boolean): void {
    if (on === this.polesOn) return;
    this.polesOn = on;
    if (!this.current) return;
    this.placePoles(false);
    this.invalidate();
    this.events.targetChanged?.();
  }

  /**
   * Makes `bones` (bone indices) the end effectors: kept ones keep their targets, new ones get a
   * target on their tip; the limbs' poles follow (a limb kept keeps its pole). `select`: the
   * target (effector index) to put the gizmo on. A solve follows, so the stats describe the new set.
   */
  setEffectors(bones: readonly number[], select?: number): void {
    const live = this.current;
    if (!live) return;
    live.session.setEffectors(bones);
    this.dragTail = null;
    this.handles.setTargets(live.session.targets);
    this.placePoles(true);
    if (select !== undefined) this.handles.select(select);
    this.invalidate();
  }

  dispose(): void {
    this.removeRig();
    this.stopClicks();
    this.handles.dispose();
    this.stage.dispose();
  }

  private removeRig(): void {
    const old = this.current;
    if (!old) return;
    for (const o of old.objects) o.removeFromParent();
    old.dispose();
    this.current = null;
  }

  /** Target k (effector index) moved to (x, y, z), rig units. */
  private moveTarget(k: number, x: number, y: number, z: number): void {
    const t = this.current?.session.targets;
    if (!t) return;
    t[3 * k] = x;
    t[3 * k + 1] = y;
    t[3 * k + 2] = z;
    this.invalidate();
  }

  /** Pole j moved to (x, y, z), rig units. */
  private movePole(j: number, x: number, y: number, z: number): void {
    const p = this.current?.session.goals.polePoints;
    if (!p || 3 * j >= p.length) return;
    p[3 * j] = x;
    p[3 * j + 1] = y;
    p[3 * j + 2] = z;
    this.invalidate();
  }

  /**
   * The limbs' poles for the rig shown and its effectors (none with pole handles off), and their
   * handles. `keep`: a limb that had a pole keeps it; the others' start where their joints bend.
   */
  private placePoles(keep: boolean): void {
    const live = this.current;
    if (!live) return;
    const { session } = live;
    const goals = session.goals;
    const limbs = this.polesOn ? poleLimbs(session.spec, session.effectors(), live.source.humanoid) : [];
    const poses = limbs.length ? session.poses() : null;
    const points = new Float64Array(3 * limbs.length);
    const had = Array.from(goals.poleBones);
    limbs.forEach((limb, j) => {
      const old = keep ? had.indexOf(limb.bone) : -1;
      points.set(
        old >= 0 ? goals.polePoints.subarray(3 * old, 3 * old + 3) : initialPole(session.spec, poses!, limb),
        3 * j,
      );
    });
    goals.setPoles(
      limbs.map((l) => l.bone),
      points,
    );
    this.poleJoints = new Float64Array(points.length);
    this.handles.setPoles(limbs.length);
    this.needsRedraw = true;
  }

  /** Target k's position goal on (its tip goes to the target, the default) or off (an orientation-only goal), and solves again. */
  setPositionGoal(k: number, on: boolean): void {
    const goals = this.current?.session.goals;
    if (!goals || k < 0 || k >= goals.count || (goals.position[k] === 1) === on) return;
    goals.setPosition(k, on);
    this.invalidate();
    this.events.targetChanged?.();
  }

  /** Target k (effector index) turned to `q` (rig coordinates): its orientation goal, on from now. */
  private turnTarget(k: number, q: Quaternion): void {
    const session = this.current?.session;
    if (!session) return;
    const was = this.orientationGoal(k);
    const r = session.goals.rotations;
    r[4 * k] = q.x;
    r[4 * k + 1] = q.y;
    r[4 * k + 2] = q.z;
    r[4 * k + 3] = q.w;
    if (!was) session.goals.setOrientation(k, true);
    this.invalidate();
    if (!was) this.events.targetChanged?.();
  }

  /** Effector k's current bone-frame rotation, rig coordinates (identity when there is no such effector). */
  private currentRotation(k: number, out: Quaternion): void {
    const session = this.current?.session;
    if (!session || k >= session.goals.count) {
      out.identity();
      return;
    }
    out.fromArray(session.tipRotations(), 4 * k);
  }

  private click(c: ViewClick): void {
    if (!this.current) return;
    const target = this.handles.pick(c.raycaster);
    const pole = target === null ? this.handles.pickPole(c.raycaster) : null;
    if (target !== null) this.handles.select(target);
    else if (pole !== null) this.handles.selectPole(pole);
    else this.events.clicked?.(c);
  }

  /** Moves the pole handles to the poles and their lines' ends to the limbs' joints as drawn now (no allocation). */
  private syncPoles(live: LiveRig): void {
    const goals = live.session.goals;
    const bones = goals.poleBones,
      joints = this.poleJoints;
    if (joints.length !== 3 * bones.length) return;
    for (let j = 0; j < bones.length; j++) {
      live.view.boneBase(bones[j], v);
      joints[3 * j] = v.x;
      joints[3 * j + 1] = v.y;
      joints[3 * j + 2] = v.z;
    }
    this.handles.syncPoles(goals.polePoints, joints);
  }

  private frame(): void {
    const live = this.current;
    if (!live || this.paused) return;
    this.events.tick?.();
    this.pinOrientations(live.session);
    let tips: Float64Array | null = null;
    if (this.solving && (this.needsSolve || this.handles.dragging)) tips = this.solve(live.session);
    if (this.needsRedraw) {
      this.needsRedraw = false;
      this.stage.invalidate();
      live.redraw();
      const s = live.session;
      this.handles.sync(s.targets, tips ?? s.tips(this.tipsBuffer(s)), s.goals.orientation, s.goals.rotations);
      if (this.handles.poles.count > 0) this.syncPoles(live);
      this.events.redrawn?.();
    }
  }

  /**
   * A target drag's first frame pins the other effectors' frames at the pose it starts from
   * (FrameSettings.pinOrientations); they are freed once the drag and the solves that finish it
   * are over. A pole's drag pins nothing: the limb turns, its hand free to turn with it.
   */
  private pinOrientations(session: IkSession): void {
    const pin = (this.settings.pinOrientations ?? true) && !this.settings.paperMode;
    const targetDrag = this.handles.dragging && this.handles.selected !== null;
    if (pin && targetDrag && !this.pinnedDrag) {
      session.yielding = this.handles.selected ?? -1; // the dragged target: solve() sets the same
      session.pinOrientations(true);
    } else if (!pin || (!targetDrag && !this.needsSolve)) session.pinOrientations(false);
    this.pinnedDrag = targetDrag;
  }

  /**
   * The target (effector index) a solve now serves the drag of: the one the gizmo drags, or the one
   * last dragged while the solves that finish its drag go on (dragTail); null for none.
   */
  private draggedTarget(): number | null {
    const selected = this.handles.selected;
    if (this.handles.dragging) return selected;
    return this.dragTail !== null && this.dragTail === selected ? selected : null;
  }

  /** The frame's tips buffer, sized for `session`'s effectors. */
  private tipsBuffer(session: IkSession): Float64Array {
    const n = 3 * session.effectors().length;
    if (this.tips.length !== n) this.tips = new Float64Array(n);
    return this.tips;
  }

  /**
   * One per-frame solve; returns the tips at the new pose (the controller's buffer, rewritten
   * next frame), or null when nothing was solved.
   */
  private solve(session: IkSession): Float64Array | null {
    if (session.effectors().length === 0) {
      this.needsSolve = false;
      return null;
    }
    // The selected target (the one dragged, or last dragged) gives way; the others stay pinned.
    session.yielding = this.handles.selected ?? -1;
    const hips = this.current?.hipsTarget;
    const dragged = this.draggedTarget();
    hips?.beforeSolve(session, dragged);
    const s = this.settings,
      f = this.solveSettings;
    f.rootUnit = this.current?.rootUnit ?? 1;
    f.gradientTolerance = s.gradientTolerance;
    f.tipTolerance = s.tipTolerance;
    f.maxIterations = s.maxIterations;
    f.timeBudgetMs = s.timeBudgetMs;
    f.paperMode = s.paperMode;
    f.lmInitialMu = s.paperMode ? undefined : FRAME_LM_MU;
    f.strictPriority = s.strictPriority ?? true;
    f.maxJointMove = s.paperMode ? 0 : (s.maxJointMove ?? 0);
    applyStillBody(session, s.stillBody ?? true, this.current?.source.humanoid !== undefined, f);
    hips?.applyCarry(session, f);
    this.needsRedraw = true;
    if (this.warmUp) {
      this.warmUp = false;
      const kept = session.angles.slice();
      try {
        solveFrame(session, s.method, f, this.timing);
      } catch {
        // the timed solve below meets the same error and reports it
      }
      session.angles.set(kept);
    }
    let outcome: SolveOutcome;
    try {
      outcome = solveFrame(session, s.method, f, this.timing);
    } catch (e) {
      this.needsSolve = false;
      this.dragTail = null;
      this.events.failed(`solver error: ${errorText(e)}`);
      return null;
    }
    this.needsSolve = this.timing.again;
    this.dragTail = this.timing.again ? dragged : null;
    const tips = session.tips(this.tipsBuffer(session));
    hips?.afterSolve(session, tips);
    this.events.solved?.(outcome, this.timing.ms, tips);
    return tips;
  }
}

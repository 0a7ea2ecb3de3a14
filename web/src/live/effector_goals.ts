// What each end effector of a live session should reach beyond its target position: whether it
// has a position goal (on by default) and an orientation goal (off by default), the goal
// orientations, and the limbs' poles (bend hints, none by default: the page's pole handles). Orientations are unit quaternions [x, y, z, w] of the effector bone's frame in
// RIG coordinates, which are also the three.js scene's coordinates (the page and the widget draw
// the rig's poses unchanged: glTF scene space for glTF rigs, the file's own units for A7 rigs).
// The Goals object for the solver (web/src/ik/goals.ts) is made only when the flags or the arrays
// change; its positions, orientations and pole points are views into the session's arrays, so
// moving or turning a target or moving a pole rewrites numbers in place and the per-frame solve
// allocates nothing here.
import {
  GOAL_STRIDE,
  POLE_STRIDE,
  type EffectorGoal,
  type Goals,
  type PackedGoals,
  type PoleGoal,
} from '../ik/goals.js';

export class EffectorGoals {
  /** 1 where effector k has a position goal (its target), per effector. */
  position: Uint8Array;
  /** 1 where effector k has an orientation goal, per effector. */
  orientation: Uint8Array;
  /** The orientation goals, 4 per effector [x, y, z, w], rig coordinates (kept while a goal is off). */
  rotations: Float64Array;
  /** The limbs with a pole: their lower bones (forearm, shin), in pole order; empty: no poles are sent. */
  poleBones = new Int32Array(0);
  /** The poles, 3 per limb [x, y, z], rig units (moving a pole rewrites them in place). */
  polePoints = new Float64Array(0);
  /**
   * Pinned orientations while a target is dragged (pin()): 4 per effector [x, y, z, w], the
   * frames the effectors had when the drag began; null: none. An effector without an orientation
   * goal of its own keeps its pinned one where keepsFrame says so, unless it is the one dragged
   * (the yielding effector).
   */
  pinned: Float64Array | null = null;
  /** While pinned: 1 where effector k keeps its frame as well as its place (pinned_frames.ts). */
  keepsFrame = new Uint8Array(0);
  /**
   * Per bone, the factor of its rest pull (Goals.stiffness, 0..1000; read only by a solve with
   * SolveSettings.restWeight > 0, still_body.ts sets it); empty: all 1. Sent with the packed goals only.
   */
  stiffness: Float64Array = new Float64Array(0);
  private cached: Goals | null = null;
  private pack: PackedGoals | null = null;
  private cachedFor: Float64Array | null = null;
  private cachedYielding = -1;

  /** Goals for `count` effectors: position goals only. */
  constructor(count: number) {
    this.position = new Uint8Array(count).fill(1);
    this.orientation = new Uint8Array(count);
    this.rotations = new Float64Array(4 * count);
    for (let k = 0; k < count; k++) this.rotations[4 * k + 3] = 1;
  }

  /** Number of effectors. */
  get count(): number {
    return this.position.length;
  }

  /** True when some effector has an orientation goal or lacks a position goal, or a limb has a pole (the solve needs Goals). */
  get beyondPositions(): boolean {
    if (this.poleBones.length > 0 || this.pinned) return true;
    for (let k = 0; k < this.count; k++) if (this.orientation[k] || !this.position[k]) return true;
    return false;
  }

  /** True when some effector has an orientation goal. */
  get anyOrientation(): boolean {
    return this.orientation.includes(1);
  }

  /** Turns effector k's orientation goal on at `q` ([x, y, z, w], rig coordinates; omitted: the one kept) or off. */
  setOrientation(k: number, on: boolean, q?: ArrayLike<number>): void {
    if (q) this.rotations.set(q, 4 * k);
    if (this.orientation[k] !== Number(on)) this.changed();
    this.orientation[k] = on ? 1 : 0;
  }

  /**
   * Poles for the limbs ending in `bones` (their lower bones, which must have a parent) at `points`
   * (3 per bone, rig units); empty arrays: no poles. Both are copied.
   */
  setPoles(bones: ArrayLike<number>, points: ArrayLike<number>): void {
    if (points.length !== 3 * bones.length)
      throw new Error(`${bones.length} poles need ${3 * bones.length} numbers, not ${points.length}`);
    this.poleBones = Int32Array.from(bones);
    this.polePoints = Float64Array.from(points);
    this.changed();
  }

  /**
   * Pins the orientation of each effector k with `keep[k]` = 1 at `rotations` (4 per effector
   * [x, y, z, w], rig coordinates: the frames at the drag's start; both copied).
   */
  pin(rotations: ArrayLike<number>, keep: ArrayLike<number>): void {
    if (rotations.length !== 4 * this.count)
      throw new Error(`${this.count} effectors need ${4 * this.count} numbers, not ${rotations.length}`);
    this.pinned = Float64Array.from(rotations);
    this.keepsFrame = Uint8Array.from(keep);
    this.changed();
  }

  /** While pinned (pin()), effector k keeps its pinned frame as well as its place. */
  keepFrame(k: number): void {
    if (k < 0 || k >= this.keepsFrame.length || this.keepsFrame[k] === 1) return;
    this.keepsFrame[k] = 1;
    this.changed();
  }

  /** Frees the pinned orientations (pin()). */
  unpin(): void {
    this.pinned = null;
    this.keepsFrame = new Uint8Array(0);
    this.changed();
  }

  /** Turns effector k's position goal on or off. */
  setPosition(k: number, on: boolean): void {
    if (this.position[k] !== Number(on)) this.changed();
    this.position[k] = on ? 1 : 0;
  }

  /**
   * The same goals for effectors `bones` (bone indices, new order) where `before` (the old bone
   * order) had them; new effectors get a position goal only.
   */
  remapped(before: ArrayLike<number>, bones: readonly number[]): EffectorGoals {
    const next = new EffectorGoals(bones.length);
    const old = Array.from(before);
    bones.forEach((b, k) => {
      const j = old.indexOf(b);
      if (j < 0) return;
      next.position[k] = this.position[j];
      next.orientation[k] = this.orientation[j];
      next.rotations.set(this.rotations.subarray(4 * j, 4 * j + 4), 4 * k);
    });
    next.setPoles(this.poleBones, this.polePoints);
    return next;
  }

  /** A copy (for a session with other limits). */
  clone(): EffectorGoals {
    const c = new EffectorGoals(this.count);
    c.position.set(this.position);
    c.orientation.set(this.orientation);
    c.rotations.set(this.rotations);
    c.setPoles(this.poleBones, this.polePoints);
    return c;
  }

  /**
   * The Goals for the solver: effector k (bone `bones[k]`) aims at `targets` (3 per effector, rig
   * units) and, where on, at its orientation; effector `yielding` (-1: none) gives way first when
   * not every goal can be met (EffectorGoal.yields); while pinned, every other effector without an
   * orientation goal that keeps its frame (pin()) holds its pinned orientation as it holds its
   * position (strict priority gives the orientation up first); the poles, if any. The same object until a
   * flag, the yielding effector or the poles' limbs change or `targets` is another array (its
   * numbers are read at each solve).
   */
  goals(bones: ArrayLike<number>, targets: Float64Array, yielding = -1): Goals {
    if (this.cached && this.cachedFor === targets && this.cachedYielding === yielding) return this.cached;
    const effectors: EffectorGoal[] = [];
    for (let k = 0; k < this.count; k++) {
      const g: EffectorGoal = { bone: bones[k] };
      if (k === yielding) g.yields = true;
      if (this.position[k]) g.position = targets.subarray(3 * k, 3 * k + 3);
      if (this.orientation[k]) g.orientation = this.rotations.subarray(4 * k, 4 * k + 4);
      else if (this.pinned && this.keepsFrame[k] && k !== yielding)
        g.orientation = this.pinned.subarray(4 * k, 4 * k + 4);
      effectors.push(g);
    }
    const poles: PoleGoal[] = [];
    for (let j = 0; j < this.poleBones.length; j++)
      poles.push({ bone: this.poleBones[j], point: this.polePoints.subarray(3 * j, 3 * j + 3) });
    this.cached = poles.length ? { effectors, poles } : { effectors };
    this.cachedFor = targets;
    this.cachedYielding = yielding;
    return this.cached;
  }

  /**
   * The same goals as goals(), packed as the core takes them (PackedGoals, in the effectors'
   * order): one record whose numbers are rewritten at each call from `targets` (3 per effector,
   * rig units), the orientations and the poles, so the per-frame solve allocates nothing and
   * skips checking a Goals object (the session's goals are well formed by construction).
   */
  packed(targets: Float64Array, yielding = -1): PackedGoals {
    const m = this.count,
      poles = this.poleBones.length;
    let p = this.pack;
    if (!p || p.target.length !== 3 * m || p.poles.length !== POLE_STRIDE * poles) {
      const none = new Float64Array(0);
      p = this.pack = {
        packed: new Float64Array(GOAL_STRIDE * m),
        target: new Float64Array(3 * m),
        lengthScale: 0,
        poles: new Float64Array(POLE_STRIDE * poles),
        stiffness: none,
      };
    }
    for (let k = 0; k < m; k++) {
      const o = GOAL_STRIDE * k;
      const turn = this.orientation[k]
        ? this.rotations
        : this.pinned && this.keepsFrame[k] && k !== yielding
          ? this.pinned
          : null;
      p.packed[o] = this.position[k];
      p.packed[o + 1] = turn ? 1 : 0;
      for (let i = 0; i < 4; i++) p.packed[o + 2 + i] = turn ? turn[4 * k + i] : 0;
      p.packed[o + 6] = k === yielding ? 1 : 0;
      for (let i = 0; i < 3; i++) p.target[3 * k + i] = this.position[k] ? targets[3 * k + i] : 0;
    }
    p.stiffness = this.stiffness;
    for (let j = 0; j < poles; j++) {
      const o = POLE_STRIDE * j;
      p.poles[o] = this.poleBones[j];
      for (let i = 0; i < 3; i++) p.poles[o + 1 + i] = this.polePoints[3 * j + i];
      p.poles[o + 4] = 1;
    }
    return p;
  }

  private changed(): void {
    this.cached = null;
  }
}

// Goals beyond plain tip positions: per end effector a position, an orientation, or both, each
// with a weight. IkSolver.start() and solve() take them in place of a target array.
//
// Units: positions in rig units; orientations as unit quaternions [x, y, z, w] of the effector
// bone's frame in rig coordinates (IkRig.tipRotations() gives the current ones); weights are
// plain factors (1: a position goal counts as a plain target). An orientation row is the
// rotation vector (radians) of R_target^T R_tip times a length scale (rig units per radian,
// default the rig's reach), so position and orientation errors add in the same units
// (wasm/src/goals.h).
import { toFloat64 } from './inputs.js';
import type { IkRig, Numbers } from './rig.js';

/** One end effector's goal. */
export interface EffectorGoal {
  /** The effector: its bone's name or index. It must be one of the rig's end effectors. */
  bone: string | number;
  /** Where its tip should be: 3 numbers within +-1e9, rig units. Omitted: no position goal. */
  position?: Numbers;
  /** Its bone frame's orientation: a quaternion [x, y, z, w] (any nonzero length). Omitted: none. */
  orientation?: Numbers;
  /**
   * Weight of both goals, >= 0. Default 1. Weights are relative: the core divides every goal's
   * weight by the largest one, so weights of 1e10 on every goal solve as weights of 1.
   */
  weight?: number;
  /** Weight of the position goal; overrides `weight`. */
  positionWeight?: number;
  /** Weight of the orientation goal; overrides `weight`. */
  orientationWeight?: number;
  /**
   * Strict priority (solver option strictPriority): this effector's goals give way first when not
   * every goal can be met, as the one a user drags while the others stay pinned: the solve holds
   * the others and brings this one as close as its freedom allows. Default false.
   */
  yields?: boolean;
}

/**
 * A bend hint (pole target) for the two-bone limb ending in `bone`: its parent's head (shoulder,
 * hip), its own head (elbow, knee) and its tip (wrist, ankle). The elbow or knee turns towards
 * `point` about the shoulder-wrist line; a soft wish that never moves a reachable tip
 * (wasm/src/pole_residual.h).
 */
export interface PoleGoal {
  /** The limb's lower bone (forearm, shin): its name or index. It must have a parent. */
  bone: string | number;
  /** The pole: 3 numbers, rig units. */
  point: Numbers;
  /** In 0..1000 (a soft pull's largest weight). Default 1; 0: no hint. */
  weight?: number;
}

/** What a solve should reach. Effectors not listed have no goal (their chains move freely). */
export interface Goals {
  effectors: readonly EffectorGoal[];
  /** Rig units per radian of orientation error, at most 1e9. Default 0: the rig's reach (its longest chain). */
  lengthScale?: number;
  /** Bend hints, soft. */
  poles?: readonly PoleGoal[];
  /**
   * Per bone (by name or index), how strongly it keeps to its rest pose under the solver option
   * restWeight (> 0): a factor in 0..1000 on its rest pull, default 1; 0 lets it move freely.
   * Without restWeight it has no effect.
   */
  stiffness?: Readonly<Record<string, number>>;
}

/** Goals packed as the core takes them (wasm/bindings/goal_input.h). */
export interface PackedGoals {
  /** 7 per effector in the rig's effector order: positionWeight, orientationWeight, qx, qy, qz, qw, yields (0 or 1). */
  packed: Float64Array;
  /** 3 per effector: the positions (0 where an effector has no position goal), rig units. */
  target: Float64Array;
  lengthScale: number;
  /** 5 per pole: bone index, x, y, z (rig units), weight. */
  poles: Float64Array;
  /** One factor per bone, or none (all 1). */
  stiffness: Float64Array;
}

export const GOAL_STRIDE = 7;
export const POLE_STRIDE = 5;

const GOAL_FIELDS = new Set([
  'bone',
  'position',
  'orientation',
  'weight',
  'positionWeight',
  'orientationWeight',
  'yields',
]);
const GOALS_FIELDS = new Set(['effectors', 'lengthScale', 'poles', 'stiffness']);
const POLE_FIELDS = new Set(['bone', 'point', 'weight']);

/** Is `value` a Goals object (rather than a target array)? */
export function isGoals(value: unknown): value is Goals {
  return typeof value === 'object' && value !== null && !Array.isArray(value) && !ArrayBuffer.isView(value);
}

/** Is `value` goals packed already (PackedGoals) rather than a Goals object or a target array? */
export function isPackedGoals(value: unknown): value is PackedGoals {
  return isGoals(value) && (value as Partial<PackedGoals>).packed instanceof Float64Array;
}

/** The index of bone `bone` (a name or an index) in `rig`, or an Error naming `what`. */
export function boneIndex(rig: IkRig, bone: unknown, what: string): number {
  if (typeof bone === 'number') {
    if (Number.isInteger(bone) && bone >= 0 && bone < rig.numBones) return bone;
    throw new Error(`${what} is ${bone}, not a bone index in 0..${rig.numBones - 1}`);
  }
  if (typeof bone !== 'string') throw new Error(`${what} must be a bone name or index, not ${typeof bone}`);
  const index = (rig.spec.names ?? []).indexOf(bone);
  if (index < 0 || index >= rig.numBones) throw new Error(`${what} "${bone.slice(0, 60)}" is not a bone of this rig`);
  return index;
}

function boneName(rig: IkRig, bone: number): string {
  return rig.spec.names?.[bone] ?? `bone ${bone}`;
}

function weightOf(value: unknown, fallback: number, what: string): number {
  if (value === undefined) return fallback;
  if (typeof value !== 'number' || !Number.isFinite(value) || value < 0)
    throw new Error(`${what} must be a finite number >= 0, not ${String(value).slice(0, 40)}`);
  return value;
}

/**
 * `goals` checked against `rig` and packed for the core. Throws an Error naming the goal and
 * field: an unknown field, a bone that is not an end effector (or named twice), a position that
 * is not 3 finite numbers, an orientation that is not 4 finite numbers of nonzero length, a
 * weight that is negative or not finite.
 */
export function packGoals(rig: IkRig, goals: Goals): PackedGoals {
  if (!isGoals(goals)) throw new Error('goals must be an object like { effectors: [{ bone, position, orientation }] }');
  for (const key of Object.keys(goals))
    if (!GOALS_FIELDS.has(key))
      throw new Error(`unknown goals field "${key.slice(0, 60)}" (known: ${[...GOALS_FIELDS].join(', ')})`);
  const list: unknown = goals.effectors;
  if (!Array.isArray(list)) throw new Error('goals.effectors must be an array of { bone, position?, orientation? }');
  const lengthScale = weightOf(goals.lengthScale, 0, 'goals.lengthScale');
  const effectors = Array.from(rig.effectors());
  const m = effectors.length;
  const packed = new Float64Array(GOAL_STRIDE * m);
  const target = new Float64Array(3 * m);
  const seen = new Set<number>();
  list.forEach((goal: unknown, i) => {
    const what = `goals.effectors[${i}]`;
    if (typeof goal !== 'object' || goal === null || Array.isArray(goal))
      throw new Error(`${what} must be an object like { bone, position, orientation }`);
    for (const key of Object.keys(goal))
      if (!GOAL_FIELDS.has(key))
        throw new Error(`unknown field ${what}.${key.slice(0, 60)} (known: ${[...GOAL_FIELDS].join(', ')})`);
    const g = goal as EffectorGoal;
    const bone = boneIndex(rig, g.bone, `${what}.bone`);
    const e = effectors.indexOf(bone);
    if (e < 0)
      throw new Error(
        `${what}.bone "${boneName(rig, bone)}" is not an end effector ` +
          `(the end effectors are ${effectors.map((b) => boneName(rig, b)).join(', ') || 'none'}; add it with setEffectors)`,
      );
    if (seen.has(bone)) throw new Error(`${what}.bone "${boneName(rig, bone)}" has a goal already`);
    seen.add(bone);
    const weight = weightOf(g.weight, 1, `${what}.weight`);
    if (g.position !== undefined) {
      target.set(toFloat64(g.position, `${what}.position`, 3), 3 * e);
      packed[GOAL_STRIDE * e] = weightOf(g.positionWeight, weight, `${what}.positionWeight`);
    } else if (g.positionWeight !== undefined) {
      throw new Error(`${what}.positionWeight is given without a position`);
    }
    if (g.orientation !== undefined) {
      const q = toFloat64(g.orientation, `${what}.orientation (a quaternion x, y, z, w)`, 4);
      if (Math.hypot(q[0], q[1], q[2], q[3]) < 1e-9)
        throw new Error(`${what}.orientation is a zero quaternion, not a rotation`);
      packed[GOAL_STRIDE * e + 1] = weightOf(g.orientationWeight, weight, `${what}.orientationWeight`);
      packed.set(q, GOAL_STRIDE * e + 2);
    } else if (g.orientationWeight !== undefined) {
      throw new Error(`${what}.orientationWeight is given without an orientation`);
    }
    if (g.yields !== undefined && typeof g.yields !== 'boolean')
      throw new Error(`${what}.yields must be true or false`);
    packed[GOAL_STRIDE * e + 6] = g.yields ? 1 : 0;
  });
  return {
    packed,
    target,
    lengthScale,
    poles: packPoles(rig, goals.poles),
    stiffness: packStiffness(rig, goals.stiffness),
  };
}

function packPoles(rig: IkRig, poles: unknown): Float64Array {
  if (poles === undefined) return new Float64Array(0);
  if (!Array.isArray(poles)) throw new Error('goals.poles must be an array of { bone, point, weight? }');
  const out = new Float64Array(POLE_STRIDE * poles.length);
  poles.forEach((pole: unknown, k) => {
    const what = `goals.poles[${k}]`;
    if (typeof pole !== 'object' || pole === null || Array.isArray(pole))
      throw new Error(`${what} must be an object like { bone, point }`);
    for (const key of Object.keys(pole))
      if (!POLE_FIELDS.has(key))
        throw new Error(`unknown field ${what}.${key.slice(0, 60)} (known: ${[...POLE_FIELDS].join(', ')})`);
    const p = pole as PoleGoal;
    const bone = boneIndex(rig, p.bone, `${what}.bone`);
    if (rig.spec.parents[bone] < 0)
      throw new Error(`${what}.bone "${boneName(rig, bone)}" has no parent: a pole bends a two-bone limb at its head`);
    out[POLE_STRIDE * k] = bone;
    out.set(toFloat64(p.point, `${what}.point`, 3), POLE_STRIDE * k + 1);
    out[POLE_STRIDE * k + 4] = weightOf(p.weight, 1, `${what}.weight`);
  });
  return out;
}

function packStiffness(rig: IkRig, stiffness: unknown): Float64Array {
  if (stiffness === undefined) return new Float64Array(0);
  if (typeof stiffness !== 'object' || stiffness === null || Array.isArray(stiffness))
    throw new Error("goals.stiffness must be an object of bone names and factors, like { 'forearm.L': 5 }");
  const out = new Float64Array(rig.numBones).fill(1);
  for (const [name, value] of Object.entries(stiffness)) {
    const names = rig.spec.names ?? [];
    const bone =
      names.includes(name) || !/^\d+$/.test(name)
        ? boneIndex(rig, name, 'a goals.stiffness key')
        : boneIndex(rig, Number(name), 'a goals.stiffness key');
    out[bone] = weightOf(value, 1, `goals.stiffness["${name.slice(0, 60)}"]`);
  }
  return out;
}

/**
 * The angle in DEGREES between each effector's bone frame at `angles` and its goal's orientation
 * (NaN for an effector without an orientation goal), in the rig's effector order.
 */
export function orientationErrorsDeg(rig: IkRig, angles: Numbers, goals: Goals): Float64Array {
  const { packed } = packGoals(rig, goals);
  const q = rig.tipRotations(angles);
  const out = new Float64Array(q.length / 4);
  for (let e = 0; e < out.length; e++) {
    const g = packed.subarray(GOAL_STRIDE * e + 2, GOAL_STRIDE * e + 6);
    if (packed[GOAL_STRIDE * e + 1] === 0) {
      out[e] = NaN;
      continue;
    }
    out[e] = rotationAngleDeg(q.subarray(4 * e, 4 * e + 4), g);
  }
  return out;
}

/** The angle, DEGREES, between rotation `a`, a unit quaternion [x, y, z, w], and rotation `b`, a quaternion of any nonzero length. */
export function rotationAngleDeg(a: ArrayLike<number>, b: ArrayLike<number>): number {
  const norm = Math.hypot(b[0], b[1], b[2], b[3]);
  const dot = Math.abs(a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3]) / norm;
  return (2 * Math.acos(Math.min(1, dot)) * 180) / Math.PI;
}

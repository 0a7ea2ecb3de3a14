// Peer: three.js's CCDIKSolver addon on our rigs. Settings and the limit mapping are written down
// in bench-node/README.md ("Peers").
//
// Scene graph per bone i (parent p): an Object3D `offset_i` holding rest_p^-1 * rest_i (rest_i for
// a root) under bone p's joint, then a Bone `joint_i` whose quaternion is Rx(a0) Rz(a1) Rx(a2), then
// for end-effector bones a Bone `tip_i` at (length, 0, 0). The joint's world matrix is then the
// canonical frame T_i * rest_i of PROTOCOL.md, so tip_i sits at the protocol's tip.
// One IK chain per end effector: effector tip_i, links = the joints from bone i up to the root
// (bones whose three angles are all fixed are left out), target = a Bone under the scene root.
// One solve = CCDIKSolver.update() passes (iteration 1 per chain per pass) until the pose is on
// target (the run's test: E < errorTolerance, or every tip within tipTolerance), no link moved in a pass (zero_step), the best E fell by less than STALL_RATIO over STALL_PASSES
// passes (stalled), or the time budget is spent (timeout).
// CCD clamps Euler XYZ angles per link, not XZX ones, and no Euler XYZ box equals an XZX box (see
// eulerBox). So after every pass the adapter reads each joint back as XZX angles inside the rig's
// limits (web/src/rig/xzx_angles.ts) and poses it there: every pass ends inside the limits, and E and the
// stopping tests are measured on that pose. This projection is part of the timed solve.
import {
  Bone,
  BufferGeometry,
  Matrix4,
  MeshBasicMaterial,
  Object3D,
  Quaternion,
  Skeleton,
  SkinnedMesh,
  Vector3,
} from 'three';
import { CCDIKSolver, type IK } from 'three/examples/jsm/animation/CCDIKSolver.js';

import type { RigSpec } from '#ik/rig_arrays.js';
import { errorOf, isOnTarget, largestChange, pinnedDeviation, tipDistance } from '../evaluate.js';
import type { SolveResult } from '../metrics.js';
import type { Runner, RunSettings, SolveInput } from '../runner.js';
import { project } from '../target_set.js';
import { xzxWithinLimits } from '#rig/xzx_angles.js';

export const STALL_PASSES = 100;
export const STALL_RATIO = 1e-3;
export const MAX_PASSES = 100000;

const DEG = Math.PI / 180;
const X = new Vector3(1, 0, 0);
const Z = new Vector3(0, 0, 1);

/** The quaternion of Rx(a0) Rz(a1) Rx(a2), angles in degrees. */
export function xzxQuaternion(a0: number, a1: number, a2: number, out = new Quaternion()): Quaternion {
  const q1 = new Quaternion().setFromAxisAngle(X, a0 * DEG);
  const q2 = new Quaternion().setFromAxisAngle(Z, a1 * DEG);
  const q3 = new Quaternion().setFromAxisAngle(X, a2 * DEG);
  return out.copy(q1).multiply(q2).multiply(q3);
}

/** [min, max] of sin (or cos) over [lo, hi] radians. */
function trigRange(f: (x: number) => number, lo: number, hi: number): [number, number] {
  if (hi - lo >= 2 * Math.PI) return [-1, 1];
  const values = [f(lo), f(hi)];
  // Critical points of sin and cos are multiples of pi/2.
  for (let k = Math.ceil(lo / (Math.PI / 2)); k * (Math.PI / 2) <= hi; k++) values.push(f(k * (Math.PI / 2)));
  return [Math.min(...values), Math.max(...values)];
}

function product([a, b]: [number, number], [c, d]: [number, number]): [number, number] {
  const p = [a * c, a * d, b * c, b * d].map((x) => (Number.isNaN(x) ? 0 : x));
  return [Math.min(...p), Math.max(...p)];
}

function wrap([lo, hi]: [number, number]): [number, number] {
  if (!(hi - lo < 2 * Math.PI)) return [-Math.PI, Math.PI];
  return [lo, hi];
}

/**
 * The Euler XYZ box (radians) CCD clamps a joint to, for XZX limits lo, hi (degrees).
 * Rx(a0) Rz(a1) Rx(a2) = Rx(a0 + a2) R_u(a1) with u = (0, sin a2, cos a2), so to first order in a1
 * the XYZ angles are (a0 + a2, a1 sin a2, a1 cos a2); the box bounds those over the limit box.
 * Exact for joints that move about one axis only (most joints of the report's rigs).
 */
export function eulerBox(lo: ArrayLike<number>, hi: ArrayLike<number>): { min: Vector3; max: Vector3 } {
  const r = (i: number): [number, number] => [Math.max(lo[i], -1e6) * DEG, Math.min(hi[i], 1e6) * DEG];
  const [a0, a1, a2] = [r(0), r(1), r(2)];
  const x = wrap([a0[0] + a2[0], a0[1] + a2[1]]);
  const y = wrap(product(a1, trigRange(Math.sin, a2[0], a2[1])));
  const z = wrap(product(a1, trigRange(Math.cos, a2[0], a2[1])));
  return { min: new Vector3(x[0], y[0], z[0]), max: new Vector3(x[1], y[1], z[1]) };
}

export class ThreeCcdRunner implements Runner {
  private readonly root = new Object3D();
  private readonly joints: Bone[] = [];
  private readonly tips: Bone[] = [];
  private readonly targets: Bone[] = [];
  private readonly solver: CCDIKSolver;
  private readonly tipBuffer: Float64Array;
  private readonly poseOut: Float64Array;
  /** The XZX angles of the current pose (degrees). */
  private readonly angles: Float64Array;

  constructor(
    private readonly spec: RigSpec,
    private readonly settings: RunSettings,
  ) {
    const n = spec.parents.length;
    const restOf = (i: number): Matrix4 => new Matrix4().fromArray(spec.rest.subarray(16 * i, 16 * i + 16)).transpose();
    const order = topologicalOrder(spec.parents);
    const bones: Bone[] = [];
    for (const i of order) {
      const p = spec.parents[i];
      const local = p === -1 ? restOf(i) : restOf(p).invert().multiply(restOf(i));
      const offset = new Object3D();
      local.decompose(offset.position, offset.quaternion, offset.scale);
      (p === -1 ? this.root : this.joints[p]).add(offset);
      const joint = new Bone();
      joint.name = spec.names[i] ?? `bone ${i}`;
      offset.add(joint);
      this.joints[i] = joint;
    }
    for (let i = 0; i < n; i++) bones.push(this.joints[i]);
    const iks: IK[] = [];
    spec.effectors.forEach((b, e) => {
      const tip = new Bone();
      tip.position.set(spec.lengths[b], 0, 0);
      this.joints[b].add(tip);
      this.tips[e] = tip;
      const target = new Bone();
      this.root.add(target);
      this.targets[e] = target;
      bones.push(tip, target);
      const links: IK['links'] = [];
      for (let j = b; j !== -1; j = spec.parents[j]) {
        const lo = spec.lower.subarray(3 * j, 3 * j + 3);
        const hi = spec.upper.subarray(3 * j, 3 * j + 3);
        if (lo.every((v, k) => v === hi[k])) continue; // a fixed bone never moves
        const box = eulerBox(lo, hi);
        links.push({ index: j, rotationMin: box.min, rotationMax: box.max });
      }
      iks.push({ target: bones.length - 1, effector: bones.length - 2, links, iteration: 1 });
    });
    const mesh = new SkinnedMesh(new BufferGeometry(), new MeshBasicMaterial());
    this.root.add(mesh);
    this.root.updateMatrixWorld(true);
    mesh.bind(new Skeleton(bones));
    // CCDIKSolver warns when a link is not its effector's direct parent; ours have an offset
    // Object3D in between (by design, see above), which the solver handles.
    const warn = console.warn;
    console.warn = () => {};
    try {
      this.solver = new CCDIKSolver(mesh, iks);
    } finally {
      console.warn = warn;
    }
    this.tipBuffer = new Float64Array(3 * spec.effectors.length);
    this.poseOut = new Float64Array(4 * n);
    this.angles = new Float64Array(3 * n);
    this.setPose(project(spec, new Float64Array(3 * n)));
  }

  private setPose(angles: Float64Array): void {
    this.angles.set(angles);
    const a = project(this.spec, this.angles);
    for (let i = 0; i < this.joints.length; i++)
      xzxQuaternion(a[3 * i], a[3 * i + 1], a[3 * i + 2], this.joints[i].quaternion);
  }

  /** Replaces each joint's rotation by its XZX reading inside the limits (see xzx.ts). */
  private projectPose(): void {
    const { lower, upper } = this.spec;
    for (let i = 0; i < this.joints.length; i++) {
      xzxWithinLimits(
        this.joints[i].quaternion,
        lower.subarray(3 * i, 3 * i + 3),
        upper.subarray(3 * i, 3 * i + 3),
        this.angles,
        3 * i,
      );
      xzxQuaternion(this.angles[3 * i], this.angles[3 * i + 1], this.angles[3 * i + 2], this.joints[i].quaternion);
    }
    this.root.updateMatrixWorld(true);
  }

  private readTips(): Float64Array {
    for (let e = 0; e < this.tips.length; e++) {
      const m = this.tips[e].matrixWorld.elements;
      this.tipBuffer[3 * e] = m[12];
      this.tipBuffer[3 * e + 1] = m[13];
      this.tipBuffer[3 * e + 2] = m[14];
    }
    return this.tipBuffer;
  }

  solve(input: SolveInput): SolveResult {
    const timeBudgetSeconds = input.budgetSeconds ?? this.settings.timeBudgetSeconds;
    const from = input.start ? project(this.spec, input.start.slice()) : this.angles.slice(); // for the jump, untimed
    const t0 = performance.now();
    const deadline = t0 + 1000 * timeBudgetSeconds;
    if (input.start) this.setPose(input.start);
    for (let e = 0; e < this.targets.length; e++)
      this.targets[e].position.set(input.target[3 * e], input.target[3 * e + 1], input.target[3 * e + 2]);
    this.root.updateMatrixWorld(true);

    let E = errorOf(this.readTips(), input.target);
    let during = NaN;
    let passes = 0;
    let best = E,
      bestAt = 0;
    let stopReason = 'converged_E';
    // tipBuffer holds the tips readTips() read last.
    while (!isOnTarget(this.settings, E, tipDistance(this.tipBuffer, input.target))) {
      if (performance.now() >= deadline) {
        stopReason = 'timeout';
        break;
      }
      if (passes >= MAX_PASSES) {
        stopReason = 'max_iterations';
        break;
      }
      this.solver.update();
      this.projectPose();
      passes++;
      const previous = E;
      const tips = this.readTips();
      E = errorOf(tips, input.target);
      if (input.dragged >= 0)
        during = Math.max(Number.isNaN(during) ? 0 : during, pinnedDeviation(tips, input.target, input.dragged));
      if (E === previous) {
        stopReason = 'zero_step';
        break;
      }
      if (E < best * (1 - STALL_RATIO)) {
        best = E;
        bestAt = passes;
      } else if (passes - bestAt >= STALL_PASSES) {
        stopReason = 'stalled';
        break;
      }
    }
    // Copy the pose out as a user would (one quaternion per joint).
    for (let i = 0; i < this.joints.length; i++) this.joints[i].quaternion.toArray(this.poseOut, 4 * i);
    const seconds = (performance.now() - t0) / 1000;
    const tips = this.readTips();
    const after = pinnedDeviation(tips, input.target, input.dragged);
    return {
      E,
      tipDistance: tipDistance(tips, input.target),
      iterations: passes,
      seconds,
      stopReason,
      wobbleDuring: passes === 0 ? after : during,
      wobbleAfter: after,
      jumpDeg: largestChange(from, this.angles, this.spec.lower, this.spec.upper),
      angles: this.angles.slice(),
    };
  }

  dispose(): void {
    this.root.clear();
  }
}

/** Bones ordered parents first. */
export function topologicalOrder(parents: ArrayLike<number>): number[] {
  const n = parents.length;
  const order: number[] = [];
  const placed = new Uint8Array(n);
  const visit = (i: number): void => {
    if (placed[i]) return;
    if (parents[i] !== -1) visit(parents[i]);
    placed[i] = 1;
    order.push(i);
  };
  for (let i = 0; i < n; i++) visit(i);
  return order;
}

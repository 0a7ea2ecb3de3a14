// Peer: closed-chain-ik (npm), a damped-least-squares solver with per-DOF joint limits, on our
// rigs. Settings are written down in bench-node/README.md ("Peers").
//
// Structure per bone i (parent p): under bone p's link (or the root link), three single-DOF joints
// J_x0 -> J_z -> J_x2 with links between them; J_x0 sits at rest_p^-1 * rest_i (rest_i for a
// root), so the last link is the canonical bone frame T_i * rest_i and the XZX angles and their
// limits map one to one (radians). Fixed angles (min = max) become joints without DOF, rotated by
// the fixed value. End-effector bones get a DOF-less joint at (length, 0, 0) and a tip link, and
// a position-only Goal (DOF X, Y, Z) closes onto that tip link; with --goals pose the Goal has all
// six DOF (X, Y, Z, EX, EY, EZ) and the effector's target orientation (the tip link's frame is the
// bone frame, whose rotation the targets are), judged from our forward kinematics of the returned
// angles (`rotations`).
// One solve = Solver.solve() calls of CHUNK_ITERATIONS iterations each until every chain reports
// CONVERGED, one reports STALLED or DIVERGED, or the time budget is spent (checked between
// calls). E is measured from the tip links' world positions (the library computes in float32).
// The package has no "main" or "exports" for Node, hence the path into it.
import * as closedChainIk from 'closed-chain-ik/src/core/index.js';
import { Goal, Joint, Link, Solver, SOLVE_STATUS_NAMES } from 'closed-chain-ik/src/core/index.js';
import { Matrix4, Quaternion, Vector3 } from 'three';

import type { RigSpec } from '#ik/rig_arrays.js';
import { errorOf, isOnTarget, largestChange, pinnedDeviation, tipDistance } from '../evaluate.js';
import type { SolveResult } from '../metrics.js';
import { largestRotationErrorDeg, ORIENTATION_TOLERANCE_DEG, type RotationsFn } from '../pose_goals.js';
import type { Runner, RunSettings, SolveInput } from '../runner.js';
import { REFERENCE_SIZE } from '../rigs.js';
import { project } from '../target_set.js';
import { topologicalOrder } from './three_ccd.js';

/** Iterations per Solver.solve() call; the time budget is checked between calls. */
export const CHUNK_ITERATIONS = 20;

const RAD = Math.PI / 180;
/** The library's DOF enum: a const enum in its typings, so read from the module at run time. */
const DOF = (closedChainIk as unknown as { DOF: Record<'X' | 'Y' | 'Z' | 'EX' | 'EY' | 'EZ', number> }).DOF;
const X_AXIS = new Vector3(1, 0, 0);
const Z_AXIS = new Vector3(0, 0, 1);

/** Bone i's rest frame (spec.rest, row-major) as a three.js matrix. */
function restOf(spec: RigSpec, i: number): Matrix4 {
  return new Matrix4().fromArray(spec.rest.subarray(16 * i, 16 * i + 16)).transpose();
}

/** Bone i's rest frame relative to its parent's (its own rest frame for a root): where J_x0 sits. */
function localRest(spec: RigSpec, i: number): { position: Vector3; rotation: Quaternion } {
  const p = spec.parents[i];
  const local = p === -1 ? restOf(spec, i) : restOf(spec, p).invert().multiply(restOf(spec, i));
  const position = new Vector3(),
    rotation = new Quaternion();
  local.decompose(position, rotation, new Vector3());
  return { position, rotation };
}

/** The library's per-chain solver, whose step we count (not part of its typings). */
interface ChainSolverLike {
  applyJointAngles(...args: unknown[]): boolean;
}

export class ClosedChainIkRunner implements Runner {
  private readonly solver: Solver;
  /** Per angle (3 per bone): the joint carrying it and its DOF, or null when fixed. */
  private readonly dofs: Array<{ joint: Joint; dof: number } | null> = [];
  private readonly tipLinks: Link[] = [];
  private readonly goals: Goal[] = [];
  private readonly tipBuffer: Float64Array;
  private readonly poseOut: Float64Array;
  private readonly position = new Float32Array(3);
  private iterations = 0;
  private observe: (() => void) | null = null;

  /**
   * `rotations` (needed with settings.goals 'pose'): the effectors' frame rotations at given
   * angles (IkRig.tipRotations), to judge the returned pose's orientations.
   */
  constructor(
    private readonly spec: RigSpec,
    private readonly settings: RunSettings,
    private readonly rotations?: RotationsFn,
  ) {
    if (settings.goals === 'pose' && !rotations)
      throw new Error("closed-chain-ik: pose goals need the rig's tip rotations");
    const n = spec.parents.length;
    const root = new Link();
    const boneLinks = this.addBones(root);
    this.addEffectors(boneLinks);
    this.solver = this.makeSolver(root);
    this.countIterations();
    this.tipBuffer = new Float64Array(3 * spec.effectors.length);
    this.poseOut = new Float64Array(3 * n);
    this.setPose(project(spec, new Float64Array(3 * n)));
  }

  /** Every bone's joints under `root`, parents first; returns each bone's last link (its canonical frame). */
  private addBones(root: Link): Link[] {
    const boneLinks: Link[] = [];
    for (const i of topologicalOrder(this.spec.parents)) {
      const p = this.spec.parents[i];
      boneLinks[i] = this.addBone(i, p === -1 ? root : boneLinks[p]);
    }
    return boneLinks;
  }

  /**
   * Bone i's three joints J_x0 -> J_z -> J_x2 under `parent` (its parent bone's last link, or the
   * root), each followed by a link, J_x0 at the bone's local rest frame; returns the last link.
   */
  private addBone(i: number, parent: Link): Link {
    const { position, rotation } = localRest(this.spec, i);
    let last = parent;
    for (let k = 0; k < 3; k++) {
      const joint = new Joint();
      const q = k === 0 ? rotation : new Quaternion();
      if (k === 0) joint.setPosition(position.x, position.y, position.z);
      this.setAngle(joint, 3 * i + k, k === 1 ? Z_AXIS : X_AXIS, k === 1 ? DOF.EZ : DOF.EX, q);
      joint.setQuaternion(q.x, q.y, q.z, q.w);
      const link = new Link();
      last.addChild(joint);
      joint.addChild(link);
      last = link;
    }
    return last;
  }

  /**
   * Angle `a` (3 per bone) on `joint`, turning about `axis`: the DOF `dof` within the angle's
   * limits (degrees, set in radians); a fixed angle (min = max) has no DOF and turns `q` instead.
   */
  private setAngle(joint: Joint, a: number, axis: Vector3, dof: number, q: Quaternion): void {
    const lo = this.spec.lower[a],
      hi = this.spec.upper[a];
    if (lo === hi) {
      q.multiply(new Quaternion().setFromAxisAngle(axis, lo * RAD));
      this.dofs[a] = null;
    } else {
      joint.setDoF(dof);
      if (Number.isFinite(lo)) joint.setMinLimits(lo * RAD);
      if (Number.isFinite(hi)) joint.setMaxLimits(hi * RAD);
      this.dofs[a] = { joint, dof };
    }
  }

  /**
   * Per effector: a DOF-less joint at (length, 0, 0) of its bone (rig units), a tip link, and the
   * Goal closing onto it (position only, or the whole pose with --goals pose).
   */
  private addEffectors(boneLinks: Link[]): void {
    this.spec.effectors.forEach((b, e) => {
      const joint = new Joint();
      joint.setPosition(this.spec.lengths[b], 0, 0);
      const tip = new Link();
      boneLinks[b].addChild(joint);
      joint.addChild(tip);
      this.tipLinks[e] = tip;
      const goal = new Goal();
      if (this.settings.goals === 'pose') goal.setGoalDoF(DOF.X, DOF.Y, DOF.Z, DOF.EX, DOF.EY, DOF.EZ);
      else goal.setGoalDoF(DOF.X, DOF.Y, DOF.Z);
      goal.makeClosure(tip);
      this.goals[e] = goal;
    });
  }

  /** The library's solver over `root` and the goals, its thresholds and lengths set for this rig and run. */
  private makeSolver(root: Link): Solver {
    const { settings } = this;
    const size = settings.rigSize / REFERENCE_SIZE;
    const solver = new Solver([root, ...this.goals]);
    solver.maxIterations = CHUNK_ITERATIONS;
    solver.useSVD = false; // the library's default; its README warns SVD can diverge
    solver.restPoseFactor = 0; // no rest pose is set: skip the null-space term
    // Every goal nearer than this: on target by the run's test (tipTolerance, or E < errorTolerance).
    solver.translationConvergeThreshold =
      settings.tipTolerance > 0
        ? settings.tipTolerance
        : Math.sqrt((2 * settings.errorTolerance) / this.spec.effectors.length);
    // Its rotation error is the length of a quaternion difference, 2 sin(angle / 4) for unit
    // quaternions: under this, every frame is within the run's orientation tolerance.
    const toleranceRad = (settings.orientationToleranceDeg ?? ORIENTATION_TOLERANCE_DEG) * RAD;
    if (settings.goals === 'pose') solver.rotationConvergeThreshold = 2 * Math.sin(toleranceRad / 4);
    // Its rotation rows (a quaternion difference, about half the angle) weigh rotationFactor
    // (error and Jacobian alike) against translation rows in rig units: scaled with the rig like
    // every length here, as our solvers weigh orientations by a length (the rig's reach).
    if (settings.goals === 'pose') solver.rotationFactor = size;
    // Lengths in the library's defaults assume a rig about 1 unit across; scale them with the rig.
    solver.translationErrorClamp = 0.1 * size;
    // As the library's authors run it: the damping of its own benchmark (benchmark/solve.js: 0.01,
    // ten times its default), and its own exits: a solve stops when the error grows by more than
    // divergeThreshold (0.01, a length) or no DOF moves more than stallThreshold (1e-4 rad). With
    // those exits off, a solve pinned against its limits (the library locks a joint that reaches
    // one) ran to the time budget, and its "solve times" were timeouts.
    solver.dampingFactor = 0.01 * size;
    solver.divergeThreshold = 0.01 * size;
    return solver;
  }

  /** Counts each chain's steps in `iterations` (and calls `observe` after each) by wrapping the library's step. */
  private countIterations(): void {
    for (const chain of (this.solver as unknown as { solvers: ChainSolverLike[] }).solvers) {
      const apply = chain.applyJointAngles.bind(chain);
      chain.applyJointAngles = (...args: unknown[]): boolean => {
        const locked = apply(...args);
        this.iterations++;
        this.observe?.();
        return locked;
      };
    }
  }

  private setPose(angles: Float64Array): void {
    const a = project(this.spec, angles.slice());
    this.dofs.forEach((d, k) => d?.joint.setDoFValue(d.dof, a[k] * RAD));
  }

  private readTips(): Float64Array {
    this.tipLinks.forEach((link, e) => {
      link.updateMatrixWorld();
      link.getWorldPosition(this.position as unknown as number[]);
      this.tipBuffer.set(this.position, 3 * e);
    });
    return this.tipBuffer;
  }

  /** Runs solve() calls until a stop; `untilIterations` replaces the time budget (replays). */
  private run(deadline: number, untilIterations: number): string {
    this.iterations = 0;
    for (;;) {
      const statuses = this.solver.solve().map((s) => SOLVE_STATUS_NAMES[s as unknown as number]);
      if (statuses.every((s) => s === 'CONVERGED')) return 'converged_E';
      if (statuses.includes('DIVERGED')) return 'diverged';
      if (statuses.includes('STALLED') && !statuses.includes('TIMEOUT')) return 'zero_step';
      if (this.iterations >= untilIterations) return 'max_iterations';
      if (performance.now() >= deadline) return 'timeout';
    }
  }

  solve(input: SolveInput): SolveResult {
    const start = input.start ? input.start.slice() : this.currentAngles();
    const t0 = performance.now();
    if (input.start) this.setPose(input.start);
    this.goals.forEach((g, e) => g.setPosition(input.target[3 * e], input.target[3 * e + 1], input.target[3 * e + 2]));
    const q = this.settings.goals === 'pose' ? input.orientations : null;
    if (q) this.goals.forEach((g, e) => g.setQuaternion(q[4 * e], q[4 * e + 1], q[4 * e + 2], q[4 * e + 3]));
    let stopReason: string;
    try {
      stopReason = this.run(t0 + 1000 * (input.budgetSeconds ?? this.settings.timeBudgetSeconds), Infinity);
    } catch {
      // The library throws when every free DOF is locked at a limit (an empty matrix product).
      stopReason = 'library_error';
    }
    this.copyOut();
    const seconds = (performance.now() - t0) / 1000;
    const iterations = this.iterations;
    const jumpDeg = largestChange(start, this.poseOut, this.spec.lower, this.spec.upper);

    const tips = this.readTips();
    const E = errorOf(tips, input.target);
    const distance = tipDistance(tips, input.target);
    const rotErrDeg = q ? largestRotationErrorDeg(this.rotations!(this.poseOut), q) : undefined;
    // The library's convergence test is per goal in float32; report our own test's verdict.
    if (stopReason === 'converged_E' && !isOnTarget(this.settings, E, distance, rotErrDeg))
      stopReason = 'converged_float32';
    const after = pinnedDeviation(tips, input.target, input.dragged);
    let during = after;
    if (input.dragged >= 0 && Number.isFinite(after) && iterations > 0)
      during = this.replayWobble(start, input, iterations);
    return {
      E,
      tipDistance: distance,
      iterations,
      seconds,
      stopReason,
      wobbleDuring: during,
      wobbleAfter: after,
      jumpDeg,
      angles: this.poseOut.slice(),
      ...(rotErrDeg === undefined ? {} : { rotErrDeg }),
    };
  }

  /** Replays the solve (same start, same iteration count) observing the pinned effectors. */
  private replayWobble(start: Float64Array, input: SolveInput, iterations: number): number {
    const end = this.currentAngles();
    let worst = 0;
    this.setPose(start);
    this.observe = () => {
      worst = Math.max(worst, pinnedDeviation(this.readTips(), input.target, input.dragged));
    };
    try {
      this.run(Infinity, iterations);
    } catch {
      // Same failure as the timed solve; the iterates seen so far count.
    } finally {
      this.observe = null;
      this.setPose(end);
    }
    return worst;
  }

  /** The pose as XZX degrees, what a user reads back after a solve. */
  private copyOut(): Float64Array {
    this.dofs.forEach((d, k) => {
      this.poseOut[k] = d ? Number(d.joint.getDoFValue(d.dof)) / RAD : this.spec.lower[k];
    });
    return this.poseOut;
  }

  private currentAngles(): Float64Array {
    return this.copyOut().slice();
  }

  dispose(): void {
    this.observe = null;
  }
}

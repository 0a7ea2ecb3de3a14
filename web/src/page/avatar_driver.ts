// The avatar of the rig the page shows: an AvatarSolver (web/src/avatar/) on the rig's
// recognised humanoid, always with its anatomical limits, one solve per frame from the last pose,
// timed. It keeps how the avatar stood when it was made (where the gizmos, a clip and a headset's
// calibration start from), says whether the feet stand where they are planted, and carries a
// tracked point's frame along with the body when a gizmo moves the point.
import { Quaternion, Vector3 } from 'three';

import { type AvatarInput, AvatarSolver } from '../avatar/avatar_solver.js';
import type { IkCoreModule } from '../ik/module.js';
import type { RigSpec } from '../ik/rig_arrays.js';
import type { RigSource } from '../view/rig_source.js';
import type { SolveOutcome } from '../live/method_solver.js';
import { bodyFrame } from '../rig/anatomy/anatomy_frame.js';
import type { HumanoidMap, HumanoidRole } from '../rig/humanoid/humanoid_roles.js';
import { TrackedPoints } from './tracked_points.js';

/** The humanoid bones an avatar needs (AvatarSolver): the tracked head and hands, the planted feet, the hips. */
const NEEDED: readonly HumanoidRole[] = ['head', 'leftHand', 'rightHand', 'leftFoot', 'rightFoot', 'hips'];
/** The joints the tracked points swing about when a gizmo moves them (carryFrame): the head from the hips, a hand from its shoulder. */
const PIVOTS: readonly HumanoidRole[] = ['hips', 'leftUpperArm', 'rightUpperArm'];

const pivot = new Vector3();
const tip = new Vector3();
const to = new Vector3();
const swing = new Quaternion();
const frame = new Quaternion();

/**
 * Why `source` cannot drive an avatar (not recognised as a humanoid, or the bones its humanoid
 * lacks), as a sentence; null when it can.
 */
export function avatarProblem(source: RigSource): string | null {
  const humanoid = source.humanoid;
  if (!humanoid) return `${source.name} is not recognised as a humanoid`;
  const missing = NEEDED.filter((role) => humanoid.bones[role] === undefined);
  return missing.length ? `${source.name}: its humanoid has no ${missing.join(', ')}` : null;
}

/** How the avatar stood when it was made, rig coordinates. */
export interface StandingAvatar {
  /** The head and hands: positions (rig units) and bone frames. */
  points: TrackedPoints;
  /** Height of the floor: the lowest bone tip (rig units). */
  floorY: number;
  /** The way the body faces, a horizontal unit vector. */
  forward: [number, number, number];
  /** The height at rest, rig units (AvatarSolver.height). */
  height: number;
}

export class AvatarDriver {
  readonly solver: AvatarSolver;
  readonly standing: StandingAvatar;
  /** The head's, hands', feet's and hips' tips as the avatar stood when made, 3 each (AvatarSolver.bones order), rig units. */
  readonly standingTips: Float64Array;
  /** Main-thread milliseconds of the last update(); 0 before the first. */
  ms = 0;
  /** Per tracked point, the bone whose base it swings about (PIVOTS), or -1 where the humanoid has none. */
  private readonly pivots: number[];

  /** The avatar of `source`, standing at rest. Throws an Error saying why for a rig that cannot have one (avatarProblem). */
  constructor(module: IkCoreModule, source: RigSource) {
    const problem = avatarProblem(source);
    if (problem) throw new Error(problem);
    const humanoid = source.humanoid as HumanoidMap;
    this.solver = new AvatarSolver(module, anatomicalSpec(source), humanoid);
    const tips = this.solver.tips(),
      rotations = this.solver.tipRotations();
    const points = new TrackedPoints();
    points.copy(tips, rotations);
    this.standingTips = tips;
    this.pivots = PIVOTS.map((role) => humanoid.bones[role] ?? -1);
    const boneTips = this.solver.rig.boneTips(this.solver.angles);
    let floorY = Infinity;
    for (let i = 1; i < boneTips.length; i += 3) floorY = Math.min(floorY, boneTips[i]);
    const forward = bodyFrame(source.spec, humanoid).forward;
    const across = Math.hypot(forward[0], forward[2]) || 1;
    this.standing = {
      points,
      floorY,
      forward: [forward[0] / across, 0, forward[2] / across],
      height: this.solver.height,
    };
  }

  /** Solves one frame towards `input` from the last pose (AvatarSolver.update), timed in `ms`. */
  update(input: AvatarInput): SolveOutcome {
    const t0 = performance.now();
    const outcome = this.solver.update(input);
    this.ms = performance.now() - t0;
    return outcome;
  }

  /**
   * Tracked point k's frame for a gizmo that moved the point (`points`' position k, rig units):
   * its bone's frame now, turned by the shortest turn about the bone's pivot joint (the hips for
   * the head, the shoulder for a hand) that takes the bone's tip onto the point, as the arm or the
   * body carries the hand or the head along. Written as `points`' rotation k; a point without a
   * pivot keeps its frame. (A frame held while its point moves away is a goal the solver keeps
   * before that point's new position: the hand stops short of its point.)
   */
  carryFrame(k: number, points: TrackedPoints): void {
    const b = this.pivots[k];
    if (b < 0) return;
    const poses = this.poses(),
      rest = this.solver.rig.spec.rest,
      tips = this.solver.tips();
    pivot.set(rest[16 * b + 3], rest[16 * b + 7], rest[16 * b + 11]); // the bone's base at rest
    const p = poses.subarray(16 * b, 16 * b + 16); // moved by its pose T_b (row-major)
    pivot.set(
      p[0] * pivot.x + p[1] * pivot.y + p[2] * pivot.z + p[3],
      p[4] * pivot.x + p[5] * pivot.y + p[6] * pivot.z + p[7],
      p[8] * pivot.x + p[9] * pivot.y + p[10] * pivot.z + p[11],
    );
    tip
      .fromArray(tips, 3 * k)
      .sub(pivot)
      .normalize();
    to.fromArray(points.positions, 3 * k)
      .sub(pivot)
      .normalize();
    swing.setFromUnitVectors(tip, to);
    frame.fromArray(this.solver.tipRotations(), 4 * k).premultiply(swing);
    points.setRotation(k, frame.x, frame.y, frame.z, frame.w);
  }

  /** Every bone's pose at the current pose, 16 row-major numbers per bone (IkRig.poses): what the view draws. */
  poses(): Float64Array {
    return this.solver.rig.poses(this.solver.angles);
  }

  /**
   * The feet now: how far the farther of those planted is from where it is planted (rig units; 0
   * when none is), and whether one is stepping (AvatarSolver.plantedFeet).
   */
  feet(): { drift: number; stepping: boolean } {
    const tips = this.solver.tips();
    let drift = 0,
      stepping = false;
    this.solver.plantedFeet().forEach((at, f) => {
      const i = 9 + 3 * f; // the feet follow the head and hands in AvatarSolver.bones
      if (at) drift = Math.max(drift, Math.hypot(tips[i] - at[0], tips[i + 1] - at[1], tips[i + 2] - at[2]));
      else stepping = true;
    });
    return { drift, stepping };
  }

  dispose(): void {
    this.solver.dispose();
  }
}

/** `source`'s spec with its humanoid's anatomical limits where the importer made them (the avatar bends as a body does). */
function anatomicalSpec(source: RigSource): RigSpec {
  const limits = source.humanoidLimits;
  return limits ? { ...source.spec, lower: limits.lower, upper: limits.upper } : source.spec;
}

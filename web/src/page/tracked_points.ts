// The three points track mode follows (the head, the left hand, the right hand), each a position
// (rig units) and the bone frame's rotation ([x, y, z, w], rig coordinates), in two flat arrays.
// `input` is the AvatarSolver's input viewing those arrays, so a frame's points are written in
// place (gizmos, a clip, a headset) and handed to the solver with no per-frame garbage.
import type { AvatarInput } from '../avatar/avatar_solver.js';

/** The tracked points in their order here: 0 head, 1 left hand, 2 right hand (AvatarInput's keys). */
export const TRACKED_KEYS = ['head', 'leftHand', 'rightHand'] as const;

export class TrackedPoints {
  /** 3 per point, rig units. */
  readonly positions = new Float64Array(3 * TRACKED_KEYS.length);
  /** 4 per point, unit quaternions [x, y, z, w], rig coordinates. */
  readonly rotations = new Float64Array(4 * TRACKED_KEYS.length);
  /** The solver's input: views of `positions` and `rotations`. */
  readonly input: AvatarInput;

  constructor() {
    const at = (k: number) => ({
      position: this.positions.subarray(3 * k, 3 * k + 3),
      orientation: this.rotations.subarray(4 * k, 4 * k + 4),
    });
    this.input = { head: at(0), leftHand: at(1), rightHand: at(2) };
  }

  /** Point k's position (x, y, z, rig units). */
  setPosition(k: number, x: number, y: number, z: number): void {
    this.positions[3 * k] = x;
    this.positions[3 * k + 1] = y;
    this.positions[3 * k + 2] = z;
  }

  /** Point k's rotation, a unit quaternion (x, y, z, w), rig coordinates. */
  setRotation(k: number, x: number, y: number, z: number, w: number): void {
    this.rotations[4 * k] = x;
    this.rotations[4 * k + 1] = y;
    this.rotations[4 * k + 2] = z;
    this.rotations[4 * k + 3] = w;
  }

  /** Copies `positions` (3 per point, at least 9 numbers; more are ignored) and `rotations` (4 per point, at least 12). */
  copy(positions: ArrayLike<number>, rotations: ArrayLike<number>): void {
    for (let i = 0; i < this.positions.length; i++) this.positions[i] = positions[i];
    for (let i = 0; i < this.rotations.length; i++) this.rotations[i] = rotations[i];
  }
}

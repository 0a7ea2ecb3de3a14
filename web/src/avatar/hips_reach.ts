// Tracked hips within reach of the tracked head and feet (6 points). Standing, the legs and the
// spine are straight: a hips tracker a millimetre off where the head and feet trackers allow (a
// tracker's noise, a strap that slipped) asks for a longer spine or longer legs than the avatar
// has, and no pose meets the goals: the frame's solve ran its 50 iterations and the next frames
// went on from wherever it stopped (bench --experiment track --points 6 --noise 0.001, seeds 1-6:
// the crouch clip 93.9-97.2% of its frames on target, reach_wave with seed 2 26%). Here, before
// the solve, the hips' target moves towards the head's neck and each foot's ankle by what it asks
// beyond the spine's and the legs' length (a straight chain's: the sum of its bones' lengths): the
// hips give way, the points the user sees are met (crouch 97.2-99.4%, reach_wave seed 2 77%). A
// hips target within reach is left exactly as given. No three.js; rig units, quaternions
// [x, y, z, w].
import type { IkRig } from '../ik/rig.js';
import type { HumanoidMap } from '../rig/humanoid/humanoid_roles.js';
import { transformPoint } from '../rig/mat4.js';
import { rotateInto } from '../rig/quat.js';

/** Effectors (AvatarSolver's order). */
const HEAD = 0,
  LEFT_FOOT = 3,
  RIGHT_FOOT = 4,
  HIPS = 5;

/** A tracked pose: a position (rig units) and an orientation [x, y, z, w]. */
interface Pose {
  position: ArrayLike<number>;
  orientation: ArrayLike<number>;
}
/** A chain from the hips to another tracked bone: where it starts in the hips' frame, where it ends in the other's, its length (rig units). */
interface Chain {
  effector: number;
  fromHips: Float64Array;
  fromOther: Float64Array;
  length: number;
}

export class HipsReach {
  private readonly chains: Chain[] = [];
  private readonly start = new Float64Array(3);
  private readonly end = new Float64Array(3);
  private readonly out = new Float64Array(3);

  /**
   * The spine (from the hips to the head's neck) and the legs (from each hip joint to its ankle)
   * of `rig` (the avatar's part: effectors head, hands, feet, hips) at rest in `angles`, mapped by
   * `humanoid`. A chain whose bones the map lacks is left out.
   */
  constructor(rig: IkRig, humanoid: HumanoidMap, angles: Float64Array) {
    const spec = rig.spec,
      parents = spec.parents;
    const poses = rig.poses(angles),
      tips = rig.tips(angles),
      rotations = rig.tipRotations(angles);
    // A bone's head: its rest transform's origin, carried by its pose transform (rest space -> posed world).
    const head = (b: number) =>
      transformPoint(poses.subarray(16 * b, 16 * b + 16), [
        spec.rest[16 * b + 3],
        spec.rest[16 * b + 7],
        spec.rest[16 * b + 11],
      ]);
    // `point` in effector e's frame, from its tip.
    const local = (point: ArrayLike<number>, e: number) => {
      const q = rotations.subarray(4 * e, 4 * e + 4);
      const v = [0, 1, 2].map((i) => point[i] - tips[3 * e + i]);
      return rotateInto([-q[0], -q[1], -q[2], q[3]], v, new Float64Array(3));
    };
    // The chain from bone `low`'s head up to bone `high`'s head: `high`'s ancestors below the
    // hips, `low` the last of them; their lengths summed.
    const add = (low: number | undefined, high: number | undefined, effector: number) => {
      const hips = humanoid.bones.hips;
      if (low === undefined || high === undefined || hips === undefined) return;
      let length = 0,
        b = parents[high];
      for (; b >= 0 && b !== hips; b = parents[b]) {
        length += spec.lengths[b];
        if (b === low) break;
      }
      if (b !== low) return;
      this.chains.push({ effector, fromHips: local(head(low), HIPS), fromOther: local(head(high), effector), length });
    };
    const bones = humanoid.bones;
    let spine = bones.head === undefined ? -1 : parents[bones.head];
    while (spine >= 0 && parents[spine] !== bones.hips) spine = parents[spine];
    add(spine >= 0 ? spine : undefined, bones.head, HEAD);
    add(bones.leftUpperLeg, bones.leftFoot, LEFT_FOOT);
    add(bones.rightUpperLeg, bones.rightFoot, RIGHT_FOOT);
  }

  /**
   * The hips' target `hips` moved, where a chain would have to be longer than it is to join it to
   * the head `head` or the foot `leftFoot`, `rightFoot` tracked, towards that chain's end by the
   * difference (each chain in turn, twice: a move for one may take another's start out of its
   * reach). Returns an array rewritten by the next call (the position as given when every chain
   * reaches). No allocation.
   */
  clampHips(hips: Pose, head: Pose, leftFoot: Pose, rightFoot: Pose): Float64Array {
    const out = this.out;
    for (let i = 0; i < 3; i++) out[i] = hips.position[i];
    for (let pass = 0; pass < 2; pass++)
      for (const chain of this.chains) {
        const other = chain.effector === HEAD ? head : chain.effector === LEFT_FOOT ? leftFoot : rightFoot;
        rotateInto(hips.orientation, chain.fromHips, this.start);
        rotateInto(other.orientation, chain.fromOther, this.end);
        let d2 = 0;
        for (let i = 0; i < 3; i++) {
          this.start[i] += out[i];
          this.end[i] += other.position[i];
          d2 += (this.end[i] - this.start[i]) ** 2;
        }
        const d = Math.sqrt(d2),
          excess = d - chain.length;
        if (excess > 0) for (let i = 0; i < 3; i++) out[i] += ((this.end[i] - this.start[i]) / d) * excess;
      }
    return out;
  }
}

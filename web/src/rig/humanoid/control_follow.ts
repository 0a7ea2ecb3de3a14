// Control bones that carry a limb's geometry follow the limb's end in the pose written to the mesh
//. A rig like three.js's RobotExpressive hangs its feet (FootL, FootR: Blender IK
// targets, control_bones.ts) off the root, beside the legs, and its foot meshes hang off those
// control bones, not off the legs. The importer makes the leg's own end the end effector in their
// place; the solver moves that end and leaves the control bone where the root puts it, so a lifted
// leg would leave its foot on the floor. Here each such control bone instead keeps its rest offset
// from the end of its limb:
//   T_c := T_e        (so posedWorld_c = T_e * restWorld_c)
// and a bone below it keeps its pose relative to the control:
//   T_d := T_e * T_c^-1 * T_d
// where T_i (16 numbers, row-major) is bone i's pose, rest world -> posed world (IkRig.poses), c
// the control bone and e the end of its limb (limbChainEnd: the leg's last bone, or its child).
// Only controls named as a hand or foot ('limbEnd' ones) follow; IK targets and poles do not.
// Poses are rigid (the joints only turn, a floating root only moves), so T^-1 is a transpose and a
// translation. The solve, the drawn bones and the tips are untouched: this is for the mesh.
import { controlBones, limbChainEnd } from './control_bones.js';

/** A bone that follows another in the written pose. */
export interface Follower {
  /** The bone that follows (a control bone, or a bone below one). */
  bone: number;
  /** The control bone at the top of its subtree (`bone` itself for the control). */
  control: number;
  /** The end of the control's limb, whose pose the control takes. */
  end: number;
}

/**
 * The bones that follow a limb's end: each control bone named as a hand or foot whose limb chain
 * exists (on its side, deeper than the root), and the bones below it, parents first. `names`
 * and `parents` of the rig's bones, parents first (depth-first). Empty for most rigs. Linear time
 * per control bone.
 */
export function limbEndFollowers(names: readonly string[], parents: ArrayLike<number>): Follower[] {
  const controls = controlBones(names, parents);
  const isControl = new Set(controls.map((c) => c.bone));
  const ends = new Map<number, number>();
  for (const c of controls) {
    if (c.kind !== 'limbEnd' || !c.limb || c.side === 'none') continue;
    const end = limbChainEnd(names, parents, c.limb, c.side, isControl);
    if (end !== undefined) ends.set(c.bone, end);
  }
  if (ends.size === 0) return [];
  // Each bone's control ancestor (itself included), parents first.
  const top = new Int32Array(names.length).fill(-1);
  const out: Follower[] = [];
  for (let b = 0; b < names.length; b++) {
    top[b] = ends.has(b) ? b : parents[b] >= 0 ? top[parents[b]] : -1;
    if (top[b] >= 0) out.push({ bone: b, control: top[b], end: ends.get(top[b])! });
  }
  return out;
}

/**
 * A function giving the poses to write to the mesh: `poses` (16 row-major numbers per bone) with
 * every follower's pose replaced as above, in a buffer it owns (valid until its next call); the
 * poses themselves when `followers` is empty. Allocates nothing per call.
 */
export function followLimbEnds(followers: readonly Follower[]): (poses: ArrayLike<number>) => ArrayLike<number> {
  if (followers.length === 0) return (poses) => poses;
  let out = new Float64Array(0);
  const relative = new Float64Array(16); // T_e * T_c^-1 of the current control
  const inverse = new Float64Array(16);
  return (poses) => {
    if (out.length !== poses.length) out = new Float64Array(poses.length);
    out.set(poses);
    let control = -1;
    for (const f of followers) {
      if (f.control !== control) {
        control = f.control;
        invertRigid(poses, 16 * control, inverse);
        multiplyInto(poses, 16 * f.end, inverse, 0, relative);
      }
      multiplyInto(relative, 0, poses, 16 * f.bone, out, 16 * f.bone);
    }
    return out;
  };
}

/** out[o..o+16] = a[i..i+16] * b[j..j+16] (row-major 4x4). `out` must not overlap a or b. */
function multiplyInto(
  a: ArrayLike<number>,
  i: number,
  b: ArrayLike<number>,
  j: number,
  out: Float64Array,
  o = 0,
): void {
  for (let r = 0; r < 4; r++)
    for (let c = 0; c < 4; c++) {
      let s = 0;
      for (let k = 0; k < 4; k++) s += a[i + 4 * r + k] * b[j + 4 * k + c];
      out[o + 4 * r + c] = s;
    }
}

/** out = m[i..i+16]^-1 for a rigid row-major m (rotation R, translation t): R^T and -R^T t. */
function invertRigid(m: ArrayLike<number>, i: number, out: Float64Array): void {
  for (let r = 0; r < 3; r++) {
    for (let c = 0; c < 3; c++) out[4 * r + c] = m[i + 4 * c + r];
    out[4 * r + 3] = -(m[i + r] * m[i + 3] + m[i + 4 + r] * m[i + 7] + m[i + 8 + r] * m[i + 11]);
  }
  out[12] = 0;
  out[13] = 0;
  out[14] = 0;
  out[15] = 1;
}

// An independent forward kinematics of a URDF chain for the tests, written from the URDF
// specification and sharing no code with the importer (web/src/rig/urdf_*.ts): its own reading of
// the XML (fast-xml-parser with its default layout), its own matrices (plain number arrays), the
// origin as Trans(xyz) * Rz(yaw) * Ry(pitch) * Rx(roll) from three elementary rotations, and each
// joint's motion as Rodrigues' rotation by q about its axis:
//   T_child = T_parent * Origin(joint) * Rot(axis, q)   (fixed joints: q = 0, no motion)
// from the BASE link (the identity) down to the TIP link.
import { XMLParser } from 'fast-xml-parser';

type M = number[]; // row-major 4x4

const mul = (a: M, b: M): M => {
  const out = new Array<number>(16).fill(0);
  for (let r = 0; r < 4; r++)
    for (let c = 0; c < 4; c++) for (let k = 0; k < 4; k++) out[4 * r + c] += a[4 * r + k] * b[4 * k + c];
  return out;
};
const eye = (): M => [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1];
const rot = (axis: number, t: number): M => {
  const [c, s] = [Math.cos(t), Math.sin(t)];
  if (axis === 0) return [1, 0, 0, 0, 0, c, -s, 0, 0, s, c, 0, 0, 0, 0, 1];
  if (axis === 1) return [c, 0, s, 0, 0, 1, 0, 0, -s, 0, c, 0, 0, 0, 0, 1];
  return [c, -s, 0, 0, s, c, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1];
};
const trans = (v: number[]): M => [1, 0, 0, v[0], 0, 1, 0, v[1], 0, 0, 1, v[2], 0, 0, 0, 1];
/** Rodrigues: R = I + sin(q) K + (1 - cos(q)) K^2 for the unit axis u. */
const axisAngle = (axis: number[], q: number): M => {
  const n = Math.hypot(axis[0], axis[1], axis[2]);
  const [x, y, z] = axis.map((v) => v / n);
  const K = [0, -z, y, z, 0, -x, -y, x, 0];
  const K2 = [0, 1, 2].flatMap((r) =>
    [0, 1, 2].map((c) => K[3 * r] * K[c] + K[3 * r + 1] * K[3 + c] + K[3 * r + 2] * K[6 + c]),
  );
  const [s, v] = [Math.sin(q), 1 - Math.cos(q)];
  const R = [0, 1, 2].flatMap((r) => [0, 1, 2].map((c) => (r === c ? 1 : 0) + s * K[3 * r + c] + v * K2[3 * r + c]));
  return [R[0], R[1], R[2], 0, R[3], R[4], R[5], 0, R[6], R[7], R[8], 0, 0, 0, 0, 1];
};

const numbers = (text: string | undefined, missing: number[]): number[] =>
  text === undefined ? missing : text.trim().split(/\s+/).map(Number);

interface RefJoint {
  name: string;
  type: string;
  origin: M;
  axis: number[];
  lower: number;
  upper: number;
}

/** A URDF chain BASE:TIP read for the reference: its joints from BASE down, and the moving ones' limits (radians). */
export class ReferenceChain {
  readonly joints: RefJoint[] = [];

  constructor(text: string, chain: string) {
    const doc = new XMLParser({
      ignoreAttributes: false,
      attributeNamePrefix: '',
      isArray: (tag, _path, _leaf, isAttribute) => !isAttribute && (tag === 'joint' || tag === 'link'),
    }).parse(text);
    type Attr = Record<string, string> | undefined;
    const byChild = new Map<string, Record<string, unknown>>();
    for (const j of doc.robot.joint as Record<string, unknown>[]) byChild.set((j.child as { link: string }).link, j);
    const [base, tip] = chain.split(':');
    for (let link = tip; link !== base;) {
      const j = byChild.get(link);
      if (!j) throw new Error(`reference: ${tip} is not below ${base}`);
      const origin = j.origin as Attr;
      const limit = j.limit as Attr;
      const type = j.type as string;
      const rpy = numbers(origin?.rpy, [0, 0, 0]);
      this.joints.unshift({
        name: j.name as string,
        type,
        origin: mul(trans(numbers(origin?.xyz, [0, 0, 0])), mul(rot(2, rpy[2]), mul(rot(1, rpy[1]), rot(0, rpy[0])))),
        axis: numbers((j.axis as Attr)?.xyz, [1, 0, 0]),
        lower: type === 'continuous' ? -Math.PI : Number(limit?.lower ?? 0),
        upper: type === 'continuous' ? Math.PI : Number(limit?.upper ?? 0),
      });
      link = (j.parent as { link: string }).link;
    }
  }

  /** The revolute and continuous joints, BASE first. */
  get moving(): RefJoint[] {
    return this.joints.filter((j) => j.type === 'revolute' || j.type === 'continuous');
  }

  /** The TIP link's frame (row-major 4x4, in BASE's frame) with the moving joints at `q` (radians, in `moving` order). */
  tipFrame(q: readonly number[]): number[] {
    let T = eye(),
      k = 0;
    for (const j of this.joints) {
      T = mul(T, j.origin);
      if (j.type === 'revolute' || j.type === 'continuous') T = mul(T, axisAngle(j.axis, q[k++]));
    }
    return T;
  }

  /** The sum of the joints' offsets: the robot's size for tolerances. */
  get size(): number {
    return this.joints.reduce((s, j) => s + Math.hypot(j.origin[3], j.origin[7], j.origin[11]), 0);
  }
}

/** The rotation matrix (9 numbers, row-major) of the unit quaternion q = [x, y, z, w]. */
export function quaternionMatrix(q: ArrayLike<number>): number[] {
  const [x, y, z, w] = [q[0], q[1], q[2], q[3]];
  return [
    1 - 2 * (y * y + z * z),
    2 * (x * y - z * w),
    2 * (x * z + y * w),
    2 * (x * y + z * w),
    1 - 2 * (x * x + z * z),
    2 * (y * z - x * w),
    2 * (x * z - y * w),
    2 * (y * z + x * w),
    1 - 2 * (x * x + y * y),
  ];
}

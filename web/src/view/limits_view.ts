// Joint limits of the selected bone: for each XZX angle a translucent sector spanning
// [min, max] in the plane that angle turns, and a needle at the current value.
// Frames: F0 = T_parent * rest_i turns by Rx(a0) into F1, then Rz(a1) into F2, then Rx(a2).
import {
  BufferGeometry,
  DoubleSide,
  Float32BufferAttribute,
  Group,
  Line,
  LineBasicMaterial,
  Matrix4,
  Mesh,
  MeshBasicMaterial,
} from 'three';

import type { RigSpec } from '../ik/rig_arrays.js';
import type { RigView } from './rig_view.js';

const COLORS = [0xff6b6b, 0x5ee07a, 0x5aa8ff];
const deg = Math.PI / 180;

const mFrame = new Matrix4();
const mRot = new Matrix4();

/** Whether a limit pair (degrees) leaves the angle free (missing, huge, or spanning a full turn). */
export function unbounded(lo: number, hi: number): boolean {
  return !Number.isFinite(lo) || !Number.isFinite(hi) || hi - lo >= 360 || Math.abs(lo) > 1e6 || Math.abs(hi) > 1e6;
}

/** Point on the arc of angle t (radians) in the plane that angle k turns. */
function arcPoint(k: number, r: number, x: number, t: number, out: number[]): void {
  if (k === 1) out.push(r * Math.cos(t), r * Math.sin(t), 0);
  else out.push(x, r * Math.cos(t), r * Math.sin(t));
}

export class LimitsView {
  readonly root = new Group();
  private readonly frames: Group[] = [new Group(), new Group(), new Group()];
  private readonly needles: Line[] = [];
  private bone: number | null = null;

  constructor(
    private spec: RigSpec,
    private readonly rigSize: number,
  ) {
    this.root.renderOrder = 20;
    for (const f of this.frames) {
      f.matrixAutoUpdate = false;
      this.root.add(f);
    }
    this.root.visible = false;
  }

  /** Shows the limits of bone `i` (null hides them). */
  select(i: number | null): void {
    if (i === this.bone) return;
    this.clearShapes();
    this.bone = i;
    this.root.visible = i !== null;
    if (i === null) return;
    const len = Math.max(this.spec.lengths[i], this.rigSize * 0.1);
    for (let k = 0; k < 3; k++) {
      const lo = this.spec.lower[3 * i + k],
        hi = this.spec.upper[3 * i + k];
      const free = unbounded(lo, hi);
      const t0 = free ? -Math.PI : lo * deg,
        t1 = free ? Math.PI : hi * deg;
      const r = k === 1 ? 0.6 * len : 0.3 * len;
      const x = k === 0 ? 0.12 * len : 0.3 * len;
      const segments = Math.max(2, Math.ceil(Math.abs(t1 - t0) / (4 * deg)));
      const fan: number[] = [],
        rim: number[] = [];
      for (let s = 0; s < segments; s++) {
        const a = t0 + ((t1 - t0) * s) / segments,
          b = t0 + ((t1 - t0) * (s + 1)) / segments;
        fan.push(...(k === 1 ? [0, 0, 0] : [x, 0, 0]));
        arcPoint(k, r, x, a, fan);
        arcPoint(k, r, x, b, fan);
      }
      for (let s = 0; s <= segments; s++) arcPoint(k, r, x, t0 + ((t1 - t0) * s) / segments, rim);
      const color = COLORS[k];
      const fanGeo = new BufferGeometry();
      fanGeo.setAttribute('position', new Float32BufferAttribute(fan, 3));
      const fanMesh = new Mesh(
        fanGeo,
        new MeshBasicMaterial({
          color,
          transparent: true,
          opacity: free ? 0.08 : 0.25,
          side: DoubleSide,
          depthTest: false,
          depthWrite: false,
        }),
      );
      const rimGeo = new BufferGeometry();
      rimGeo.setAttribute('position', new Float32BufferAttribute(rim, 3));
      const rimLine = new Line(rimGeo, new LineBasicMaterial({ color, depthTest: false, transparent: true }));
      const needleGeo = new BufferGeometry();
      const tip: number[] = [];
      arcPoint(k, r * 1.15, x, 0, tip);
      needleGeo.setAttribute('position', new Float32BufferAttribute([k === 1 ? 0 : x, 0, 0, ...tip], 3));
      const needle = new Line(
        needleGeo,
        new LineBasicMaterial({ color: 0xffffff, depthTest: false, transparent: true }),
      );
      needle.matrixAutoUpdate = false;
      for (const o of [fanMesh, rimLine, needle]) o.renderOrder = 20;
      this.frames[k].add(fanMesh, rimLine, needle);
      this.needles[k] = needle;
    }
  }

  /** Shows the limits of `spec` from now on (the rig's limits were switched); redraws the selected bone's. */
  useSpec(spec: RigSpec): void {
    this.spec = spec;
    const bone = this.bone;
    this.select(null);
    this.select(bone);
  }

  /** Places the sectors on the selected bone at the current pose. */
  update(view: RigView, angles: Float64Array): void {
    const i = this.bone;
    if (i === null) return;
    const a0 = angles[3 * i] * deg,
      a1 = angles[3 * i + 1] * deg,
      a2 = angles[3 * i + 2] * deg;
    // F0 = (T_i rest_i) * (Rx(a0) Rz(a1) Rx(a2))^-1
    view.boneFrame(i, mFrame);
    mFrame.multiply(mRot.makeRotationX(-a2)).multiply(mRot.makeRotationZ(-a1)).multiply(mRot.makeRotationX(-a0));
    this.frames[0].matrix.copy(mFrame);
    mFrame.multiply(mRot.makeRotationX(a0));
    this.frames[1].matrix.copy(mFrame);
    mFrame.multiply(mRot.makeRotationZ(a1));
    this.frames[2].matrix.copy(mFrame);
    this.needles[0].matrix.makeRotationX(a0);
    this.needles[1].matrix.makeRotationZ(a1);
    this.needles[2].matrix.makeRotationX(a2);
    for (const f of this.frames) f.matrixWorldNeedsUpdate = true;
  }

  dispose(): void {
    this.clearShapes();
    this.root.removeFromParent();
  }

  private clearShapes(): void {
    for (const f of this.frames) {
      for (const c of [...f.children]) {
        if (c instanceof Mesh || c instanceof Line) {
          c.geometry.dispose();
          (c.material as MeshBasicMaterial | LineBasicMaterial).dispose();
        }
        f.remove(c);
      }
    }
    this.needles.length = 0;
  }
}

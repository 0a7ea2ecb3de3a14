// A headset's stream through XrTracking (web/src/page/xr_tracking.ts) into the avatar, as the page
// runs it in VR (track_mode.ts: xrSample() of each XR frame, XrTracking.input(), AvatarDriver.update()),
// with the XR frames scripted: a recorded stream of the viewer's and both grips' poses. The user
// is smaller than the character, stands elsewhere in the XR space facing another way, holds the
// controllers at fixed offsets from the hands' bone frames, and moves through an upper-body motion
// that starts standing as the character stands (the calibration pose).
// - The points the stream maps to are the motion's own (to 1e-9 of the height and 1e-4 degrees),
//   and the avatar's head and hands follow them within δ (0.1% of the height) and 0.5° with the
//   feet planted; nothing is solved before a frame with the head and both grips calibrates.
// - A grip that loses tracking holds its hand's last point; the input sources' order does not
//   matter and a source without a grip or a hand is left out.
// - A sample with a number that is not finite, or a zero quaternion, is refused by name.
import { readFileSync } from 'node:fs';
import { resolve } from 'node:path';

import { Euler, Quaternion, Vector3 } from 'three';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';

import { rotationAngleDeg } from '../../web/src/ik/goals.js';
import type { IkCoreModule } from '../../web/src/ik/module.js';
import { loadIkNode } from '../../web/src/ik/node.js';
import { IkRig } from '../../web/src/ik/rig.js';
import { readRig, type RigSource } from '../../web/src/view/rig_source.js';
import { IkSession } from '../../web/src/live/session.js';
import { AvatarDriver } from '../../web/src/page/avatar_driver.js';
import { TrackedPoints } from '../../web/src/page/tracked_points.js';
import {
  type XrFrameLike,
  type XrInputSourceLike,
  type XrPoseLike,
  type XrSample,
  XrTracking,
  xrSample,
} from '../../web/src/page/xr_tracking.js';

let ik: IkCoreModule;
let character: RigSource;
beforeAll(async () => {
  ik = await loadIkNode();
  character = await readRig(
    readFileSync(resolve(import.meta.dirname, '../../web/public/models/character.glb')),
    'character.glb',
  );
});
afterAll(() => expect(IkSession.alive.sessions).toBe(0));

const UPPER_BODY = [
  'spine',
  'chest',
  'upperChest',
  'neck',
  'head',
  'leftShoulder',
  'leftUpperArm',
  'leftLowerArm',
  'leftHand',
  'rightShoulder',
  'rightUpperArm',
  'rightLowerArm',
  'rightHand',
] as const;

/** Frame f (60 per second) of an upper-body motion: the rest pose for 5 frames, then each angle of the moving bones on its own sine within its limits, growing over half a second. */
function motionFrame(rig: IkRig, bones: number[], f: number): Float64Array {
  const out = new Float64Array(rig.numAngles),
    t = f / 60,
    grow = Math.min(1, Math.max(0, (f - 5) / 30));
  bones.forEach((b, i) => {
    for (let k = 0; k < 3; k++) {
      const j = 3 * b + k,
        lo = rig.lower[j],
        hi = rig.upper[j];
      const mid = Math.max(lo, Math.min(hi, 0)),
        span = Math.min(hi - mid, mid - lo, 60);
      out[j] = mid + grow * 0.6 * span * Math.sin(2 * Math.PI * (0.15 + 0.05 * ((i + k) % 5)) * t + i + 2 * k);
    }
  });
  return rig.project(out);
}

/** The user in the XR space: rig point p -> XR point T + u Y (p - A), bone frame q -> device frame Y q E(device). */
interface User {
  /** Meters per rig unit. */
  u: number;
  /** Rig -> XR, a turn about +Y. */
  Y: Quaternion;
  /** Where the user stands in the XR space (on its floor, y = 0), meters. */
  T: Vector3;
  /** The rig point that maps onto T: under the standing head, on the avatar's floor. */
  A: Vector3;
  /** Per device (head, left grip, right grip): bone frame -> device frame. */
  E: Quaternion[];
}

/** A pose as XRFrame.getPose returns it. */
function xrPose(p: Vector3, q: Quaternion): XrPoseLike {
  return { transform: { position: { x: p.x, y: p.y, z: p.z }, orientation: { x: q.x, y: q.y, z: q.z, w: q.w } } };
}

/** The devices' poses (head, left grip, right grip) of a pose whose tracked tips and frames are `tips`, `rotations`. */
function devicePoses(user: User, tips: Float64Array, rotations: Float64Array): XrPoseLike[] {
  return [0, 1, 2].map((k) => {
    const p = new Vector3()
      .fromArray(tips, 3 * k)
      .sub(user.A)
      .applyQuaternion(user.Y)
      .multiplyScalar(user.u)
      .add(user.T);
    const q = new Quaternion()
      .fromArray(rotations, 4 * k)
      .premultiply(user.Y)
      .multiply(user.E[k]);
    return xrPose(p, q);
  });
}

/** One recorded frame played back as XRFrame: the viewer's pose, and each grip space's pose (null: not tracked). */
class ScriptedFrame implements XrFrameLike {
  constructor(
    private readonly viewer: XrPoseLike | null,
    private readonly grips: Map<object, XrPoseLike | null>,
  ) {}

  getViewerPose(_space: object): XrPoseLike | null {
    return this.viewer;
  }

  getPose(space: object, _base: object): XrPoseLike | null {
    return this.grips.get(space) ?? null;
  }
}

const REFERENCE_SPACE = {};
const leftGrip = {},
  rightGrip = {};
/** The session's input sources: the right one first, a gaze source (no grip), an unhanded one, a left one without a grip (hand tracking, say). */
const SOURCES: XrInputSourceLike[] = [
  { handedness: 'right', gripSpace: rightGrip },
  { handedness: 'none' },
  { handedness: 'left', gripSpace: leftGrip },
  { handedness: 'none', gripSpace: {} },
  { handedness: 'left' },
];

describe('XrTracking: a recorded headset stream drives the avatar', () => {
  it('maps the stream onto the motion itself and the avatar follows; a lost grip holds its hand; no solve before calibration', () => {
    const driver = new AvatarDriver(ik, character);
    const truth = new IkRig(ik, driver.solver.rig.spec);
    try {
      const humanoid = character.humanoid!;
      const bones = UPPER_BODY.map((role) => humanoid.bones[role]).filter((b): b is number => b !== undefined);
      const s = driver.standing,
        h = s.height,
        delta = 1e-3 * h;
      const head = s.points.positions;
      // The user: 1.62 m to the eyes (the character's head is 1.8 units over its floor), standing
      // at (0.7, 0, -0.4) in the XR space, turned 110 degrees from the character's facing.
      const user: User = {
        u: 1.62 / (head[1] - s.floorY),
        Y: new Quaternion().setFromAxisAngle(new Vector3(0, 1, 0), (110 * Math.PI) / 180),
        T: new Vector3(0.7, 0, -0.4),
        A: new Vector3(head[0], s.floorY, head[2]),
        E: [
          // The viewer looks along its -Z: at rest, along the way the character faces (+Z).
          new Quaternion()
            .fromArray(s.points.rotations, 0)
            .invert()
            .multiply(new Quaternion().setFromAxisAngle(new Vector3(0, 1, 0), Math.PI)),
          new Quaternion().setFromEuler(new Euler(0.3, -1.1, 0.5)),
          new Quaternion().setFromEuler(new Euler(-0.7, 0.4, 2.0)),
        ],
      };
      // The recorded stream: 240 frames; the first two miss a grip, the right grip is lost in 100..119.
      const frames = 240;
      const recorded: { frame: ScriptedFrame; tips: Float64Array; rotations: Float64Array }[] = [];
      for (let f = 0; f < frames; f++) {
        const a = motionFrame(truth, bones, f);
        const tips = truth.tips(a),
          rotations = truth.tipRotations(a);
        const [viewer, left, right] = devicePoses(user, tips, rotations);
        const rightTracked = f >= 2 && (f < 100 || f >= 120);
        recorded.push({
          frame: new ScriptedFrame(
            viewer,
            new Map([
              [leftGrip, left],
              [rightGrip, rightTracked ? right : null],
            ]),
          ),
          tips,
          rotations,
        });
      }

      const tracking = new XrTracking(s);
      const points = new TrackedPoints();
      let solves = 0,
        worstMap = 0,
        worstTurn = 0,
        worstTip = 0,
        worstFrame = 0,
        worstFoot = 0;
      let held: Float64Array | null = null;
      for (let f = 0; f < frames; f++) {
        const { frame, tips, rotations } = recorded[f];
        const sample = xrSample(frame, REFERENCE_SPACE, SOURCES);
        if (!tracking.input(sample, points)) {
          expect(f, 'calibrated by the first frame with the head and both grips').toBeLessThan(2);
          continue;
        }
        driver.update(points.input);
        solves++;
        const lost = f >= 100 && f < 120;
        if (f === 99) held = points.positions.slice(6, 9);
        for (const k of lost ? [0, 1] : [0, 1, 2]) {
          worstMap = Math.max(worstMap, distance(points.positions, tips, k) / h);
          worstTurn = Math.max(
            worstTurn,
            rotationAngleDeg(points.rotations.subarray(4 * k, 4 * k + 4), rotations.subarray(4 * k, 4 * k + 4)),
          );
        }
        if (lost) expect(Array.from(points.positions.subarray(6, 9))).toEqual(Array.from(held!)); // the right hand holds its last point
        const mine = driver.solver.tips(),
          turned = driver.solver.tipRotations();
        for (const k of [0, 1, 2]) {
          worstTip = Math.max(worstTip, distance(mine, points.positions, k) / delta);
          worstFrame = Math.max(
            worstFrame,
            rotationAngleDeg(turned.subarray(4 * k, 4 * k + 4), points.rotations.subarray(4 * k, 4 * k + 4)),
          );
        }
        for (const k of [3, 4]) worstFoot = Math.max(worstFoot, distance(mine, driver.standingTips, k) / delta); // where it stood
      }
      expect(solves).toBe(frames - 2);
      expect(worstMap).toBeLessThan(1e-9);
      expect(worstTurn).toBeLessThan(1e-4); // acos rounds to about 1e-6 degrees near 0
      expect(worstTip).toBeLessThan(1);
      expect(worstFrame).toBeLessThan(0.5);
      expect(worstFoot).toBeLessThan(1);
    } finally {
      truth.dispose();
      driver.dispose();
    }
  });

  it('refuses a sample with a number that is not finite, or a zero quaternion, naming it', () => {
    const driver = new AvatarDriver(ik, character);
    try {
      const tracking = new XrTracking(driver.standing);
      const points = new TrackedPoints();
      const ok = { position: [0, 1.6, 0], orientation: [0, 0, 0, 1] };
      const sample = (left: XrSample['left']): XrSample => ({ head: ok, left, right: ok });
      expect(() => tracking.input(sample({ position: [0, NaN, 0], orientation: [0, 0, 0, 1] }), points)).toThrow(
        'XR sample: left grip position[1] is NaN, not a finite number',
      );
      expect(() => tracking.input(sample({ position: [0, 1, 0], orientation: [0, 0, 0, 0] }), points)).toThrow(
        'XR sample: left grip orientation is a zero quaternion',
      );
      expect(() => tracking.input(sample({ position: [0, 1], orientation: [0, 0, 0, 1] }), points)).toThrow(
        'XR sample: left grip position has 2 values, expected 3',
      );
      expect(tracking.isCalibrated).toBe(false);
      expect(tracking.input(sample(ok), points)).toBe(true); // a good sample calibrates
    } finally {
      driver.dispose();
    }
  });
});

/** Distance between point k of `a` and of `b` (3 numbers per point). */
function distance(a: ArrayLike<number>, b: ArrayLike<number>, k: number): number {
  return Math.hypot(a[3 * k] - b[3 * k], a[3 * k + 1] - b[3 * k + 1], a[3 * k + 2] - b[3 * k + 2]);
}

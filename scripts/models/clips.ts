// Animation clips for the generated models: a clip gives, at each time, each moving joint's turn
// and the root's shift, and addClips() writes them as glTF animations sampled at the clip's frame
// rate (LINEAR): every frame, or only the frames interpolation cannot rebuild within the clip's
// tolerance (key_reduction.ts). A turn is a rotation in ARMATURE coordinates about the joint's own
// head, applied after its parent's motion (the joint's world motion is its parent's times its
// turn), so a clip can say "bend the shin back 40 degrees" without knowing the joints' local axes.
import type { Accessor, AnimationSampler, Buffer, Document, Node } from '@gltf-transform/core';

import { type Quat, inverse, mul } from '#rig/quat.js';
import { keptFrames } from './key_reduction.js';
import { type Vec3, cross, dot, length, normalize } from './vec.js';

export { type Quat, inverse, mul, rotate } from '#rig/quat.js';

export interface ClipPose {
  /** Per joint name, its turn (armature coordinates); joints not listed keep their rest rotation. */
  turns: Record<string, Quat>;
  /** The root joint's shift from rest, armature units. */
  shift?: Vec3;
}

export interface ClipDef {
  name: string;
  seconds: number;
  fps: number;
  pose(t: number): ClipPose;
  /**
   * Keep only the keyframes that linear interpolation cannot rebuild within these: degrees for
   * rotations, armature units for the root's shift. Without it every frame is a keyframe.
   */
  tolerance?: { degrees: number; units: number };
}

export const IDENTITY: Quat = [0, 0, 0, 1];

/** The rotation by `degrees` about `axis` (any length but 0). */
export function turnAbout(axis: Vec3, degrees: number): Quat {
  const [x, y, z] = normalize(axis),
    h = (degrees * Math.PI) / 360,
    s = Math.sin(h);
  return [x * s, y * s, z * s, Math.cos(h)];
}

/** The smallest rotation taking direction `from` to direction `to`. */
export function between(from: Vec3, to: Vec3): Quat {
  const a = normalize(from),
    b = normalize(to);
  const axis = cross(a, b),
    s = length(axis),
    c = dot(a, b);
  if (s < 1e-12) return IDENTITY;
  return turnAbout(axis, (Math.atan2(s, c) * 180) / Math.PI);
}

/** A joint node with its rest local rotation and its rest frame's rotation in armature coordinates. */
export interface ClipJoint {
  node: Node;
  restLocal: Quat;
  restFrame: Quat;
}

/**
 * Writes `clips` into `doc` as animations of `joints` (by joint name; `root`: the joint shifted).
 * Frames 0..seconds*fps; a joint's channel holds its rest local rotation times its turn, brought
 * into its own frame.
 */
export function addClips(
  doc: Document,
  buffer: Buffer,
  clips: readonly ClipDef[],
  joints: ReadonlyMap<string, ClipJoint>,
  root: string,
): void {
  for (const clip of clips) {
    const frames = Math.round(clip.seconds * clip.fps) + 1;
    const times = Float32Array.from({ length: frames }, (_, k) => k / clip.fps);
    const poses = Array.from(times, (t) => clip.pose(t));
    const animation = doc.createAnimation(clip.name);
    // One input accessor per set of kept frames (all of them without a tolerance).
    const inputs = new Map<string, Accessor>();
    const input = (kept: number[]): Accessor => {
      const key = kept.join(' ');
      let accessor = inputs.get(key);
      if (!accessor)
        inputs.set(
          key,
          (accessor = doc
            .createAccessor()
            .setType('SCALAR')
            .setArray(Float32Array.from(kept, (k) => times[k]))
            .setBuffer(buffer)),
        );
      return accessor;
    };
    const channel = (
      node: Node,
      path: 'rotation' | 'translation',
      values: Float32Array,
      type: 'VEC3' | 'VEC4',
    ): void => {
      const stride = type === 'VEC4' ? 4 : 3;
      const tolerance = clip.tolerance && (path === 'rotation' ? clip.tolerance.degrees : clip.tolerance.units);
      const kept = tolerance === undefined ? Array.from(times, (_, k) => k) : keptFrames(values, stride, tolerance);
      const keys =
        tolerance === undefined
          ? values
          : Float32Array.from(kept.flatMap((k) => Array.from(values.subarray(stride * k, stride * (k + 1)))));
      const sampler: AnimationSampler = doc
        .createAnimationSampler()
        .setInput(input(kept))
        .setOutput(doc.createAccessor().setType(type).setArray(keys).setBuffer(buffer))
        .setInterpolation('LINEAR');
      animation
        .addSampler(sampler)
        .addChannel(doc.createAnimationChannel().setTargetNode(node).setTargetPath(path).setSampler(sampler));
    };
    const moving = [...new Set(poses.flatMap((p) => Object.keys(p.turns)))];
    for (const name of moving) {
      const joint = joints.get(name);
      if (!joint) throw new Error(`clip ${clip.name}: no joint ${name}`);
      const values = new Float32Array(4 * frames);
      poses.forEach((p, k) => {
        const turn = p.turns[name] ?? IDENTITY;
        // World motion G = W0 D W0^-1 for a local delta D: D = W0^-1 G W0.
        const local = mul(joint.restLocal, mul(mul(inverse(joint.restFrame), turn), joint.restFrame));
        values.set(local[3] < 0 ? local.map((v) => -v) : local, 4 * k);
      });
      channel(joint.node, 'rotation', values, 'VEC4');
    }
    if (poses.some((p) => p.shift)) {
      const node = joints.get(root)!.node,
        rest = node.getTranslation();
      const values = new Float32Array(3 * frames);
      poses.forEach((p, k) =>
        values.set(
          rest.map((x, i) => x + (p.shift?.[i] ?? 0)),
          3 * k,
        ),
      );
      channel(node, 'translation', values, 'VEC3');
    }
  }
}

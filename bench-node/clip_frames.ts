// A glTF file's animation clips, sampled frame by frame for the track experiment: each bone's
// motion from its rest pose, G_i(t) = W_i(t) W_i(rest)^-1 (row-major 4x4, world coordinates), so
// that a point of the rest pose, p, is at G_i(t) p at time t. Read with glTF-Transform; samplers
// are LINEAR (slerp for rotations), STEP, or CUBICSPLINE (its keyframe values, without the
// tangents); a clip's frame rate is the one its keyframes are spaced at.
import { type Animation, type Node, NodeIO } from '@gltf-transform/core';

import { fromTRS, invertAffine, multiply } from '#rig/mat4.js';
import { BenchError } from './errors.js';

/** One clip: its name, frame rate (per second) and frame count (from time 0 to its end). */
export interface ClipInfo {
  name: string;
  fps: number;
  frames: number;
}

/** Frame rates a clip's keyframe spacing is rounded to; one spaced otherwise is sampled at 30. */
const FRAME_RATES = [24, 25, 30, 50, 60, 120];
const FALLBACK_FPS = 30;

interface Track {
  node: number;
  path: 'translation' | 'rotation' | 'scale';
  times: Float32Array;
  values: Float32Array;
  /** Numbers per keyframe (3 or 4; CUBICSPLINE stores 3 times as many: in-tangent, value, out-tangent). */
  stride: number;
  interpolation: 'LINEAR' | 'STEP' | 'CUBICSPLINE';
}

/** The clips of a glTF file and their frames' bone motions. */
export class ClipFrames {
  readonly clips: ClipInfo[];
  private readonly nodes: Node[];
  private readonly parents: Int32Array;
  private readonly restInverse: Float64Array[];
  /** Per clip, its channels with their keyframes (read once). */
  private readonly tracks: Track[][];

  private constructor(
    animations: Animation[],
    nodes: Node[],
    private readonly boneNodes: Int32Array,
  ) {
    this.nodes = nodes;
    this.tracks = animations.map((a) => tracksOf(a, nodes));
    const index = new Map(nodes.map((n, i) => [n, i]));
    this.parents = Int32Array.from(nodes, (n) => {
      const p = n.getParentNode();
      return p ? (index.get(p) ?? -1) : -1;
    });
    this.clips = animations.map((a, i) => clipInfo(a, i));
    const rest = this.world([], 0);
    this.restInverse = Array.from(boneNodes, (node) => {
      const inv = invertAffine(rest[node]);
      if (!inv) throw new BenchError(`track: the rest transform of node ${node} cannot be inverted`);
      return inv;
    });
  }

  /** Reads `path` (.glb or .gltf); `boneNodes`: the glTF node of each bone (GltfRigInfo.boneNodes). */
  static async read(path: string, boneNodes: Int32Array): Promise<ClipFrames> {
    const doc = await new NodeIO().read(path);
    const root = doc.getRoot();
    return new ClipFrames(root.listAnimations(), root.listNodes(), boneNodes);
  }

  /** Each bone's motion from rest at frame `frame` of clip `clip` (16 row-major numbers per bone). */
  motion(clip: number, frame: number): Float64Array {
    const t = frame / this.clips[clip].fps;
    const world = this.world(this.tracks[clip], t);
    const out = new Float64Array(16 * this.boneNodes.length);
    this.boneNodes.forEach((node, i) => out.set(multiply(world[node], this.restInverse[i]), 16 * i));
    return out;
  }

  /** Every node's world matrix at time `t` of a clip's `tracks` (none: the rest pose). */
  private world(tracks: readonly Track[], t: number): Float64Array[] {
    const trs = this.nodes.map((n) => ({
      t: n.getTranslation() as number[],
      r: n.getRotation() as number[],
      s: n.getScale() as number[],
    }));
    for (const track of tracks) trs[track.node][pathKey(track.path)] = sample(track, t);
    const world: Float64Array[] = new Array(this.nodes.length);
    const at = (i: number): Float64Array => {
      if (world[i]) return world[i];
      const local = fromTRS(trs[i].t, trs[i].r, trs[i].s);
      return (world[i] = this.parents[i] < 0 ? local : multiply(at(this.parents[i]), local));
    };
    for (let i = 0; i < this.nodes.length; i++) at(i);
    return world;
  }
}

function pathKey(path: Track['path']): 't' | 'r' | 's' {
  return path === 'translation' ? 't' : path === 'rotation' ? 'r' : 's';
}

function tracksOf(animation: Animation, nodes: Node[]): Track[] {
  const out: Track[] = [];
  for (const channel of animation.listChannels()) {
    const node = channel.getTargetNode(),
      path = channel.getTargetPath(),
      sampler = channel.getSampler();
    if (!node || !sampler || (path !== 'translation' && path !== 'rotation' && path !== 'scale')) continue;
    const input = sampler.getInput()?.getArray(),
      output = sampler.getOutput()?.getArray();
    if (!input || !output || input.length === 0) continue;
    const interpolation = sampler.getInterpolation();
    out.push({
      node: nodes.indexOf(node),
      path,
      times: Float32Array.from(input),
      values: Float32Array.from(output),
      stride: path === 'rotation' ? 4 : 3,
      interpolation,
    });
  }
  return out;
}

/** The value of `track` at time `t` (held before the first and after the last keyframe). */
function sample(track: Track, t: number): number[] {
  const { times, values, stride, interpolation } = track;
  const cubic = interpolation === 'CUBICSPLINE';
  const value = (k: number): number[] => {
    const o = (cubic ? 3 * k + 1 : k) * stride;
    return Array.from(values.subarray(o, o + stride));
  };
  if (t <= times[0]) return value(0);
  const last = times.length - 1;
  if (t >= times[last]) return value(last);
  let k = 0;
  while (times[k + 1] <= t) k++;
  if (interpolation === 'STEP') return value(k);
  const u = (t - times[k]) / (times[k + 1] - times[k]);
  const a = value(k),
    b = value(k + 1);
  return stride === 4 ? slerp(a, b, u) : a.map((x, i) => x + u * (b[i] - x));
}

function slerp(a: number[], b: number[], u: number): number[] {
  let dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
  const sign = dot < 0 ? -1 : 1;
  dot *= sign;
  if (dot > 0.9995) {
    const q = a.map((x, i) => x + u * (sign * b[i] - x));
    const n = Math.hypot(...q);
    return q.map((x) => x / n);
  }
  const theta = Math.acos(dot),
    s = Math.sin(theta);
  const wa = Math.sin((1 - u) * theta) / s,
    wb = (sign * Math.sin(u * theta)) / s;
  return a.map((x, i) => wa * x + wb * b[i]);
}

/** A clip's frame rate (its keyframes' smallest spacing, rounded to a common rate) and frame count. */
function clipInfo(animation: Animation, index: number): ClipInfo {
  let end = 0,
    spacing = Infinity;
  for (const channel of animation.listChannels()) {
    const input = channel.getSampler()?.getInput()?.getArray();
    if (!input || input.length === 0) continue;
    end = Math.max(end, input[input.length - 1]);
    for (let k = 1; k < input.length; k++)
      if (input[k] > input[k - 1]) spacing = Math.min(spacing, input[k] - input[k - 1]);
  }
  const rate = 1 / spacing;
  const fps = FRAME_RATES.find((r) => Math.abs(r - rate) < 0.02 * r) ?? FALLBACK_FPS;
  return { name: animation.getName() || `clip ${index}`, fps, frames: Math.floor(end * fps + 1e-6) + 1 };
}

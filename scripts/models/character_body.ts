// The character's skeleton as its clips pose it (character_clips.ts and the clips in files of their
// own): joints by their short names ("LeftArm" for mixamorig:LeftArm), and turns made from the
// bones' rest directions. A turn is a rotation in armature coordinates (clips.ts); angles in
// degrees, lengths in armature centimetres.
import { type Quat, between, turnAbout } from './clips.js';
import type { JointDef } from './model.js';
import { type Vec3, add, cross, normalize, scale, sub } from './vec.js';

/** The joints' name prefix. */
export const P = 'mixamorig:';
/** Where the character faces at rest. */
export const fwd: Vec3 = [0, 0, 1];

/**
 * The keyframes turn_in_place and stress keep (clips.ts): interpolation rebuilds every frame within
 * 0.01 degrees and 0.01 cm (a planted foot then stays within 0.1 mm of the floor).
 */
export const KEY_TOLERANCE = { degrees: 0.01, units: 0.01 };

/** 0 before `a`, 1 after `b`, smooth between. */
export function ease(t: number, a: number, b: number): number {
  const u = Math.min(1, Math.max(0, (t - a) / (b - a)));
  return u * u * (3 - 2 * u);
}

export interface Body {
  /** The joint named `name` (without the prefix). */
  joint(name: string): JointDef;
  /** Bone `name`'s rest direction, head to tail (unit). */
  dir(name: string): Vec3;
  /** Turns bone `name` towards `towards` (across the bone) by `degrees`. */
  bend(name: string, towards: Vec3, degrees: number): Quat;
  /** Turns bone `name` about itself by `degrees`. */
  twist(name: string, degrees: number): Quat;
  /** The turn that points bone `name` along `to` (the smallest one), eased in by `w`. */
  aim(name: string, to: Vec3, w: number): Quat;
  /**
   * The relaxed stance at weight w (0: T-pose): arms down and a little forward, elbows bent 20
   * degrees; written into `turns` where they leave the arms free.
   */
  stance(w: number, turns?: Record<string, Quat>): Record<string, Quat>;
}

export function characterBody(joints: readonly JointDef[]): Body {
  const joint = (name: string): JointDef => {
    const j = joints.find((x) => x.name === P + name);
    if (!j) throw new Error(`character clips: no joint ${name}`);
    return j;
  };
  const dir = (name: string): Vec3 => normalize(sub(joint(name).tail, joint(name).head));
  const bend = (name: string, towards: Vec3, degrees: number): Quat => turnAbout(cross(dir(name), towards), degrees);
  const twist = (name: string, degrees: number): Quat => turnAbout(dir(name), degrees);
  const aim = (name: string, to: Vec3, w: number): Quat => {
    const d = dir(name);
    return between(d, normalize(add(scale(d, 1 - w), scale(normalize(to), w))));
  };
  const stance = (w: number, turns: Record<string, Quat> = {}): Record<string, Quat> => {
    for (const s of ['Left', 'Right']) {
      const side = s === 'Left' ? 1 : -1;
      turns[P + `${s}Arm`] ??= aim(`${s}Arm`, [0.25 * side, -1, 0.15], w);
      turns[P + `${s}ForeArm`] ??= bend(`${s}ForeArm`, fwd, 20 * w);
    }
    return turns;
  };
  return { joint, dir, bend, twist, aim, stance };
}

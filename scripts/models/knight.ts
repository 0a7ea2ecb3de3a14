// Knight (mirrors the report's knight: 19 bones rooted at the chest, 5 end effectors: hands, feet,
// head). Meters, Y up, facing +Z, Blender-style names (hand.L). Carries a sword and a shield.
import { ball as ballLimits, fixed, flex, hinge } from './limits.js';
import type { JointDef, ModelDef, Shape } from './model.js';
import { ball, block, frustum } from './shapes.js';
import { type Vec3, lerp, mirrorX } from './vec.js';

const fwd: Vec3 = [0, 0, 1],
  back: Vec3 = [0, 0, -1],
  up: Vec3 = [0, 1, 0];
const chest: Vec3 = [0, 1.3, 0],
  neck: Vec3 = [0, 1.5, 0],
  head: Vec3 = [0, 1.6, 0],
  crown: Vec3 = [0, 1.82, 0];
const waist: Vec3 = [0, 1.25, 0],
  hips: Vec3 = [0, 1.02, 0],
  pelvis: Vec3 = [0, 0.92, 0];

type Side = 'L' | 'R';
const at = (s: Side, p: Vec3): Vec3 => (s === 'L' ? p : mirrorX(p));

function arm(s: Side): JointDef[] {
  const root = at(s, [0.06, 1.45, 0]),
    shoulder = at(s, [0.2, 1.45, 0]),
    elbow = at(s, [0.27, 1.17, 0]);
  const wrist = at(s, [0.31, 0.92, 0]),
    fingers = at(s, [0.33, 0.78, 0.01]);
  return [
    {
      name: `shoulder.${s}`,
      parent: 'chest',
      head: root,
      tail: shoulder,
      hinge: flex(root, shoulder, up),
      limits: ballLimits(10, -15, 15, 10),
    },
    {
      name: `upper_arm.${s}`,
      parent: `shoulder.${s}`,
      head: shoulder,
      tail: elbow,
      hinge: flex(shoulder, elbow, fwd),
      limits: ballLimits(90, -45, 120, 45),
    },
    {
      name: `forearm.${s}`,
      parent: `upper_arm.${s}`,
      head: elbow,
      tail: wrist,
      hinge: flex(elbow, wrist, fwd),
      limits: [
        [0, 0, -60],
        [0, 145, 60],
      ],
    },
    {
      name: `hand.${s}`,
      parent: `forearm.${s}`,
      head: wrist,
      tail: fingers,
      hinge: flex(wrist, fingers, fwd),
      limits: ballLimits(20, -60, 60, 20),
      effector: true,
    },
  ];
}

function leg(s: Side): JointDef[] {
  const hip = at(s, [0.1, 0.95, 0]),
    knee = at(s, [0.11, 0.52, 0]),
    ankle = at(s, [0.12, 0.1, 0]),
    toe = at(s, [0.12, 0.02, 0.16]);
  return [
    {
      name: `thigh.${s}`,
      parent: 'hips',
      head: hip,
      tail: knee,
      hinge: flex(hip, knee, fwd),
      limits: ballLimits(30, -30, 100, 30),
    },
    {
      name: `shin.${s}`,
      parent: `thigh.${s}`,
      head: knee,
      tail: ankle,
      hinge: flex(knee, ankle, back),
      limits: hinge(0, 140),
    },
    {
      name: `foot.${s}`,
      parent: `shin.${s}`,
      head: ankle,
      tail: toe,
      hinge: flex(ankle, toe, [0, -1, 0]),
      limits: ballLimits(15, -30, 45, 15),
      effector: true,
    },
  ];
}

function armShapes(s: Side): Shape[] {
  const j = arm(s);
  const [shoulder, upper, fore, hand] = j;
  return [
    ball('steel', upper.head, 0.09, shoulder.name, [1, 0.8, 1]),
    frustum(
      'mail',
      upper.head,
      upper.tail,
      0.055,
      0.05,
      8,
      [
        [upper.name, 0.5],
        [shoulder.name, 0.5],
      ],
      upper.name,
    ),
    frustum(
      'steel',
      fore.head,
      fore.tail,
      0.05,
      0.042,
      8,
      [
        [fore.name, 0.5],
        [upper.name, 0.5],
      ],
      fore.name,
    ),
    block('dark', hand.head, hand.tail, 0.08, 0.05, hand.name, fwd),
  ];
}

function legShapes(s: Side): Shape[] {
  const [thigh, shin, foot] = leg(s);
  return [
    frustum(
      'mail',
      thigh.head,
      thigh.tail,
      0.075,
      0.06,
      8,
      [
        [thigh.name, 0.5],
        ['hips', 0.5],
      ],
      thigh.name,
    ),
    frustum(
      'steel',
      shin.head,
      shin.tail,
      0.06,
      0.05,
      8,
      [
        [shin.name, 0.5],
        [thigh.name, 0.5],
      ],
      shin.name,
    ),
    block('steel', at(s, [0.12, 0.08, -0.04]), at(s, [0.12, 0.04, 0.18]), 0.1, 0.07, foot.name, [1, 0, 0]),
  ];
}

const grip = lerp(mirrorX([0.31, 0.92, 0]), mirrorX([0.33, 0.78, 0.01]), 0.55);

export const knight: ModelDef = {
  name: 'knight',
  armature: {},
  joints: [
    { name: 'chest', head: chest, tail: neck, hinge: flex(chest, neck, fwd), limits: fixed },
    {
      name: 'neck',
      parent: 'chest',
      head: neck,
      tail: head,
      hinge: flex(neck, head, fwd),
      limits: ballLimits(40, -20, 40, 40),
    },
    {
      name: 'head',
      parent: 'neck',
      head,
      tail: crown,
      hinge: flex(head, crown, fwd),
      limits: ballLimits(40, -30, 30, 30),
      effector: true,
    },
    ...arm('L'),
    ...arm('R'),
    {
      name: 'spine',
      parent: 'chest',
      head: waist,
      tail: hips,
      hinge: flex(waist, hips, back),
      limits: ballLimits(20, -20, 30, 20),
    },
    {
      name: 'hips',
      parent: 'spine',
      head: hips,
      tail: pelvis,
      hinge: flex(hips, pelvis, back),
      limits: ballLimits(10, -10, 10, 10),
    },
    ...leg('L'),
    ...leg('R'),
  ],
  materials: [
    { name: 'steel', color: [0.72, 0.74, 0.78], metallic: 0.45, roughness: 0.35 },
    { name: 'mail', color: [0.5, 0.51, 0.55], metallic: 0.4, roughness: 0.6 },
    { name: 'dark', color: [0.22, 0.2, 0.19], metallic: 0.3, roughness: 0.7 },
    { name: 'red', color: [0.62, 0.08, 0.1], metallic: 0.1, roughness: 0.6 },
    { name: 'gold', color: [0.85, 0.66, 0.2], metallic: 0.6, roughness: 0.35 },
  ],
  shapes: [
    block('steel', [0, 1.22, 0], [0, 1.5, 0], 0.38, 0.24, 'chest', [1, 0, 0]),
    block('mail', [0, 1.02, 0], [0, 1.24, 0], 0.32, 0.21, 'spine', [1, 0, 0]),
    block('dark', [0, 0.9, 0], [0, 1.04, 0], 0.34, 0.24, 'hips', [1, 0, 0]),
    frustum('dark', [0, 1.48, 0], [0, 1.6, 0], 0.05, 0.05, 8, 'neck'),
    block('steel', [0, 1.58, 0], [0, 1.84, 0], 0.22, 0.25, 'head', [1, 0, 0]),
    block('dark', [0, 1.7, 0.118], [0, 1.73, 0.118], 0.18, 0.02, 'head', [1, 0, 0]),
    frustum('red', [0, 1.84, 0], [0, 1.96, -0.06], 0.03, 0.012, 6, 'head'),
    ...armShapes('L'),
    ...armShapes('R'),
    ...legShapes('L'),
    ...legShapes('R'),
    // Shield on the left forearm, sword in the right hand (pointing forward).
    block('red', [0.37, 0.86, 0], [0.37, 1.26, 0], 0.34, 0.03, 'forearm.L', [0, 0, 1]),
    block('gold', [0.386, 1.0, 0], [0.386, 1.12, 0], 0.06, 0.006, 'forearm.L', [0, 0, 1]),
    block(
      'gold',
      [grip[0], grip[1], grip[2] - 0.09],
      [grip[0], grip[1], grip[2] + 0.04],
      0.03,
      0.03,
      'hand.R',
      [1, 0, 0],
    ),
    block(
      'gold',
      [grip[0] - 0.1, grip[1], grip[2] + 0.05],
      [grip[0] + 0.1, grip[1], grip[2] + 0.05],
      0.03,
      0.025,
      'hand.R',
      [0, 1, 0],
    ),
    block(
      'steel',
      [grip[0], grip[1], grip[2] + 0.06],
      [grip[0], grip[1], grip[2] + 0.85],
      0.05,
      0.01,
      'hand.R',
      [0, 1, 0],
    ),
  ],
};

// A 65-joint humanoid for scale, named and shaped like a Mixamo rig ("mixamorig:LeftHandIndex1"):
// centimeters under an Armature scaled by 0.01 (as Mixamo FBX files arrive in glTF), T-pose,
// Y up, facing +Z, full fingers and a three-bone spine. End effectors: hands, feet, head.
import { characterClips } from './character_clips.js';
import { ball as ballLimits, fixed, flex, hinge } from './limits.js';
import type { JointDef, Limits, ModelDef, Shape } from './model.js';
import { ball, block, frustum } from './shapes.js';
import { type Vec3, add, mirrorX } from './vec.js';

const P = 'mixamorig:';
const fwd: Vec3 = [0, 0, 1],
  back: Vec3 = [0, 0, -1],
  down: Vec3 = [0, -1, 0];

type Side = 'Left' | 'Right';
const at = (s: Side, p: Vec3): Vec3 => (s === 'Left' ? p : mirrorX(p));

interface Chain {
  names: string[];
  /** Joint positions plus the last joint's tail. */
  points: Vec3[];
  towards: Vec3;
  limits: Limits[];
  effector?: string;
}

function chainJoints(parent: string, c: Chain, side?: Side): JointDef[] {
  const pts = c.points.map((p) => (side ? at(side, p) : p));
  return c.names.map((name, k) => ({
    name: P + name,
    parent: k === 0 ? P + parent : P + c.names[k - 1],
    head: pts[k],
    tail: pts[k + 1],
    hinge: flex(pts[k], pts[k + 1], c.towards),
    limits: c.limits[k],
    effector: name === c.effector,
  }));
}

const spine: Chain = {
  names: ['Spine', 'Spine1', 'Spine2', 'Neck', 'Head', 'HeadTop_End'],
  points: [
    [0, 110, 0],
    [0, 122, 0],
    [0, 134, 0],
    [0, 150, 0],
    [0, 160, 0],
    [0, 180, 0],
    [0, 185, 0],
  ],
  towards: fwd,
  limits: [
    ballLimits(15, -15, 25, 15),
    ballLimits(15, -15, 25, 15),
    ballLimits(15, -15, 25, 15),
    ballLimits(30, -30, 30, 30),
    ballLimits(40, -30, 40, 30),
    fixed,
  ],
  effector: 'Head',
};

function arm(s: Side): JointDef[] {
  const chain: Chain = {
    names: ['Shoulder', 'Arm', 'ForeArm', 'Hand'].map((n) => s + n),
    points: [
      [6, 145, 0],
      [18, 145, 0],
      [45, 145, 0],
      [70, 145, 0],
      [80, 145, 1],
    ],
    towards: fwd,
    limits: [
      ballLimits(10, -15, 30, 10),
      ballLimits(90, -90, 90, 60),
      [
        [0, 0, -80],
        [0, 150, 80],
      ],
      ballLimits(20, -70, 70, 20),
    ],
    effector: `${s}Hand`,
  };
  const fingers: [string, Vec3[]][] = [
    [
      'Thumb',
      [
        [73, 144, 3],
        [77, 143, 7],
        [80, 142, 9.5],
        [83, 141, 11.5],
        [85, 140.5, 13],
      ],
    ],
    [
      'Index',
      [
        [80, 145, 3],
        [84, 145, 3.2],
        [86.5, 145, 3.3],
        [88.5, 145, 3.3],
        [90, 145, 3.3],
      ],
    ],
    [
      'Middle',
      [
        [80, 145, 1],
        [84.5, 145, 1],
        [87.3, 145, 1],
        [89.5, 145, 1],
        [91, 145, 1],
      ],
    ],
    [
      'Ring',
      [
        [79.5, 145, -1.2],
        [83.7, 145, -1.3],
        [86.3, 145, -1.4],
        [88.3, 145, -1.4],
        [89.8, 145, -1.4],
      ],
    ],
    [
      'Pinky',
      [
        [78.5, 145, -3.2],
        [81.8, 145, -3.5],
        [83.8, 145, -3.6],
        [85.3, 145, -3.6],
        [86.5, 145, -3.6],
      ],
    ],
  ];
  return [
    ...chainJoints('Spine2', chain, s),
    ...fingers.flatMap(([f, points]) =>
      chainJoints(
        `${s}Hand`,
        {
          names: [1, 2, 3, 4].map((k) => `${s}Hand${f}${k}`),
          points,
          towards: f === 'Thumb' ? [0, -0.5, -0.85] : down,
          limits:
            f === 'Thumb'
              ? [ballLimits(30, -20, 50, 30), hinge(0, 70), hinge(0, 80), fixed]
              : [
                  [
                    [-15, -10, 0],
                    [15, 90, 0],
                  ],
                  hinge(0, 100),
                  hinge(0, 80),
                  fixed,
                ],
        },
        s,
      ),
    ),
  ];
}

function leg(s: Side): JointDef[] {
  const names = ['UpLeg', 'Leg', 'Foot', 'ToeBase', 'Toe_End'].map((n) => s + n);
  const pts = (
    [
      [9, 95, 0],
      [9.5, 52, 0],
      [10, 8, 0],
      [10, 1, 12],
      [10, 1, 19],
      [10, 1, 22],
    ] as Vec3[]
  ).map((p) => at(s, p));
  const towards: Vec3[] = [fwd, back, down, down, down];
  const limits: Limits[] = [
    ballLimits(40, -30, 110, 40),
    hinge(0, 150),
    ballLimits(20, -30, 50, 20),
    hinge(-30, 40),
    fixed,
  ];
  return names.map((name, k) => ({
    name: P + name,
    parent: P + (k === 0 ? 'Hips' : names[k - 1]),
    head: pts[k],
    tail: pts[k + 1],
    hinge: flex(pts[k], pts[k + 1], towards[k]),
    limits: limits[k],
    effector: name === `${s}Foot`,
  }));
}

const joints: JointDef[] = [
  { name: `${P}Hips`, head: [0, 100, 0], tail: [0, 110, 0], hinge: [1, 0, 0], limits: fixed },
  ...chainJoints('Hips', spine),
  ...arm('Left'),
  ...arm('Right'),
  ...leg('Left'),
  ...leg('Right'),
];

const joint = (name: string): JointDef => {
  const j = joints.find((x) => x.name === P + name);
  if (!j) throw new Error(`character: no joint ${name}`);
  return j;
};

/** A limb segment along a joint, blended with the parent at its start. */
function limb(name: string, r0: number, r1: number, sides = 8, material = 'body'): Shape {
  const j = joint(name);
  return frustum(
    material,
    j.head,
    j.tail,
    r0,
    r1,
    sides,
    j.parent
      ? [
          [j.name, 0.5],
          [j.parent, 0.5],
        ]
      : j.name,
    j.name,
  );
}

function sideShapes(s: Side): Shape[] {
  const hand = joint(`${s}Hand`),
    foot = joint(`${s}Foot`),
    toe = joint(`${s}ToeBase`);
  return [
    limb(`${s}Arm`, 5, 4.2),
    limb(`${s}ForeArm`, 4, 3.2),
    block('dark', add(hand.head, at(s, [1, 0, -0.5])), add(hand.head, at(s, [10, 0, 0])), 8.5, 3, hand.name, [0, 0, 1]),
    ...['Thumb', 'Index', 'Middle', 'Ring', 'Pinky'].flatMap((f) =>
      [1, 2, 3].map((k) => limb(`${s}Hand${f}${k}`, f === 'Thumb' ? 1.2 : 0.95, 0.8, 4, 'dark')),
    ),
    limb(`${s}UpLeg`, 8, 6),
    limb(`${s}Leg`, 5.5, 4.2),
    block('dark', add(foot.head, [0, -1, -4]), add(toe.head, [0, -1, 0]), 9, 7, foot.name, [1, 0, 0]),
    block('dark', toe.head, add(toe.tail, [0, 0, 2]), 8.5, 3.5, toe.name, [1, 0, 0]),
    ball('body', joint(`${s}Arm`).head, 6, joint(`${s}Shoulder`).name),
  ];
}

export const character: ModelDef = {
  name: 'character',
  plain: true, // as a downloaded Mixamo character arrives: recognised as a humanoid, limits from anatomy
  armature: { scale: [0.01, 0.01, 0.01] },
  joints,
  clips: characterClips(joints),
  materials: [
    { name: 'body', color: [0.78, 0.74, 0.68], metallic: 0, roughness: 0.6 },
    { name: 'dark', color: [0.2, 0.22, 0.27], metallic: 0.1, roughness: 0.6 },
  ],
  shapes: [
    block('body', [0, 90, 0], [0, 110, 0], 30, 18, `${P}Hips`, [1, 0, 0]),
    frustum(
      'body',
      [0, 110, 0],
      [0, 122, 0],
      12,
      13,
      10,
      [
        [`${P}Spine`, 0.5],
        [`${P}Hips`, 0.5],
      ],
      `${P}Spine`,
    ),
    frustum(
      'body',
      [0, 122, 0],
      [0, 134, 0],
      13,
      15,
      10,
      [
        [`${P}Spine1`, 0.5],
        [`${P}Spine`, 0.5],
      ],
      `${P}Spine1`,
    ),
    frustum(
      'body',
      [0, 134, 0],
      [0, 150, 0],
      15,
      12,
      10,
      [
        [`${P}Spine2`, 0.5],
        [`${P}Spine1`, 0.5],
      ],
      `${P}Spine2`,
    ),
    limb('Neck', 5, 4.5),
    ball('body', [0, 170, 1], 11, `${P}Head`, [0.85, 1, 1]),
    ball('dark', [0, 168, 10], 2, `${P}Head`),
    ...sideShapes('Left'),
    ...sideShapes('Right'),
  ],
};

// Hand (mirrors the report's chimpanzee-hand: 21 bones, the 5 fingertips as end effectors).
// Meters, fingers along +Y, palm facing +Z; fingers flex towards the palm (+Z).
import { ball as ballLimits, fixed, flex, hinge } from './limits.js';
import type { JointDef, ModelDef, Shape } from './model.js';
import { block, frustum } from './shapes.js';
import type { Vec3 } from './vec.js';

const palmward: Vec3 = [0, 0, 1];

interface Finger {
  name: string;
  /** Joint positions from the base outwards; the last is the fingertip (a tail, not a joint). */
  points: Vec3[];
  radius: number;
}

const fingers: Finger[] = [
  {
    name: 'thumb',
    points: [
      [0.025, 0.015, 0.012],
      [0.05, 0.05, 0.03],
      [0.065, 0.08, 0.04],
      [0.075, 0.105, 0.045],
    ],
    radius: 0.011,
  },
  {
    name: 'index',
    points: [
      [0.02, 0.025, 0],
      [0.025, 0.1, 0],
      [0.028, 0.145, 0],
      [0.03, 0.172, 0],
      [0.031, 0.192, 0],
    ],
    radius: 0.0095,
  },
  {
    name: 'middle',
    points: [
      [0, 0.027, 0],
      [0.003, 0.105, 0],
      [0.004, 0.155, 0],
      [0.005, 0.185, 0],
      [0.006, 0.207, 0],
    ],
    radius: 0.0098,
  },
  {
    name: 'ring',
    points: [
      [-0.018, 0.025, 0],
      [-0.017, 0.1, 0],
      [-0.018, 0.146, 0],
      [-0.019, 0.174, 0],
      [-0.019, 0.194, 0],
    ],
    radius: 0.009,
  },
  {
    name: 'pinky',
    points: [
      [-0.034, 0.02, 0],
      [-0.037, 0.09, 0],
      [-0.04, 0.125, 0],
      [-0.042, 0.146, 0],
      [-0.043, 0.163, 0],
    ],
    radius: 0.008,
  },
];

const wrist: Vec3 = [0, 0, 0];

function fingerJoints(f: Finger): JointDef[] {
  const thumb = f.name === 'thumb';
  const limits = thumb
    ? [ballLimits(30, -20, 50, 30), hinge(0, 70), hinge(0, 80)]
    : [
        ballLimits(5, -5, 10, 5),
        [
          [-15, -10, 0],
          [15, 90, 0],
        ] as JointDef['limits'],
        hinge(0, 100),
        hinge(0, 80),
      ];
  // The thumb flexes across the palm, the fingers straight towards it.
  const towards: Vec3 = thumb ? [-0.6, 0, 0.8] : palmward;
  return f.points.slice(0, -1).map((head, k) => ({
    name: `${f.name}_0${k + 1}`,
    parent: k === 0 ? 'wrist' : `${f.name}_0${k}`,
    head,
    tail: f.points[k + 1],
    hinge: flex(head, f.points[k + 1], towards),
    limits: limits[k],
    effector: k === f.points.length - 2,
  }));
}

function fingerShapes(f: Finger): Shape[] {
  const joints = fingerJoints(f);
  // A finger's metacarpal lies inside the palm block; the thumb's shows.
  return joints.flatMap((j, k) => {
    if (k === 0 && f.name !== 'thumb') return [];
    const r = f.radius * (1 - 0.12 * k);
    return [
      frustum(
        'skin',
        j.head,
        j.tail,
        r,
        r * 0.88,
        6,
        k === 0
          ? j.name
          : [
              [j.name, 0.5],
              [joints[k - 1].name, 0.5],
            ],
        j.name,
      ),
    ];
  });
}

export const hand: ModelDef = {
  name: 'hand',
  armature: {},
  joints: [
    { name: 'forearm', head: [0, -0.25, 0], tail: wrist, hinge: [1, 0, 0], limits: fixed },
    {
      name: 'wrist',
      parent: 'forearm',
      head: wrist,
      tail: fingers[2].points[0],
      hinge: flex(wrist, fingers[2].points[0], palmward),
      limits: ballLimits(20, -70, 70, 20),
    },
    ...fingers.flatMap(fingerJoints),
  ],
  materials: [
    { name: 'skin', color: [0.86, 0.66, 0.53], metallic: 0, roughness: 0.7 },
    { name: 'sleeve', color: [0.2, 0.32, 0.55], metallic: 0, roughness: 0.8 },
  ],
  shapes: [
    frustum('sleeve', [0, -0.25, 0], [0, -0.08, 0], 0.04, 0.038, 10, 'forearm'),
    frustum('skin', [0, -0.08, 0], [0, 0.005, 0], 0.03, 0.027, 10, 'forearm', [
      ['wrist', 0.5],
      ['forearm', 0.5],
    ]),
    block('skin', [-0.004, 0.005, 0], [-0.004, 0.1, 0], 0.085, 0.03, 'wrist', [1, 0, 0]),
    ...fingers.flatMap(fingerShapes),
  ],
};

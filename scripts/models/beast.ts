// Four-legged beast (22 bones like the report's beast, 5 end effectors: four paws and the head).
// Meters, Y up, facing +Z; rooted at the pelvis, with a tail.
import { ball as ballLimits, fixed, flex, hinge } from './limits.js';
import type { JointDef, ModelDef, Shape } from './model.js';
import { block, frustum } from './shapes.js';
import { type Vec3, mirrorX } from './vec.js';

const fwd: Vec3 = [0, 0, 1],
  back: Vec3 = [0, 0, -1],
  up: Vec3 = [0, 1, 0];
const pelvis: Vec3 = [0, 0.85, -0.45],
  spine: Vec3 = [0, 0.88, -0.15],
  chest: Vec3 = [0, 0.9, 0.2];
const neck: Vec3 = [0, 1.0, 0.38],
  head: Vec3 = [0, 1.2, 0.55],
  snout: Vec3 = [0, 1.1, 0.85];
const tailBase: Vec3 = [0, 0.88, -0.5],
  tailTip: Vec3 = [0, 0.72, -0.9];

type Side = 'L' | 'R';
const at = (s: Side, p: Vec3): Vec3 => (s === 'L' ? p : mirrorX(p));

function frontLeg(s: Side): JointDef[] {
  const p = [
    [0.12, 0.95, 0.3],
    [0.16, 0.72, 0.32],
    [0.16, 0.45, 0.28],
    [0.16, 0.12, 0.3],
    [0.16, 0.02, 0.38],
  ].map((v) => at(s, v as Vec3));
  return [
    {
      name: `scapula.${s}`,
      parent: 'chest',
      head: p[0],
      tail: p[1],
      hinge: flex(p[0], p[1], fwd),
      limits: ballLimits(10, -20, 20, 10),
    },
    {
      name: `upperarm.${s}`,
      parent: `scapula.${s}`,
      head: p[1],
      tail: p[2],
      hinge: flex(p[1], p[2], fwd),
      limits: ballLimits(20, -60, 60, 20),
    },
    {
      name: `forearm.${s}`,
      parent: `upperarm.${s}`,
      head: p[2],
      tail: p[3],
      hinge: flex(p[2], p[3], back),
      limits: hinge(0, 120),
    },
    {
      name: `paw_front.${s}`,
      parent: `forearm.${s}`,
      head: p[3],
      tail: p[4],
      hinge: flex(p[3], p[4], back),
      limits: ballLimits(10, -30, 60, 10),
      effector: true,
    },
  ];
}

function hindLeg(s: Side): JointDef[] {
  const p = [
    [0.13, 0.82, -0.45],
    [0.15, 0.5, -0.32],
    [0.15, 0.25, -0.48],
    [0.15, 0.1, -0.44],
    [0.15, 0.02, -0.36],
  ].map((v) => at(s, v as Vec3));
  return [
    {
      name: `thigh.${s}`,
      parent: 'pelvis',
      head: p[0],
      tail: p[1],
      hinge: flex(p[0], p[1], fwd),
      limits: ballLimits(20, -50, 70, 20),
    },
    {
      name: `shin.${s}`,
      parent: `thigh.${s}`,
      head: p[1],
      tail: p[2],
      hinge: flex(p[1], p[2], fwd),
      limits: hinge(-60, 60),
    },
    {
      name: `hock.${s}`,
      parent: `shin.${s}`,
      head: p[2],
      tail: p[3],
      hinge: flex(p[2], p[3], back),
      limits: hinge(-40, 60),
    },
    {
      name: `paw_hind.${s}`,
      parent: `hock.${s}`,
      head: p[3],
      tail: p[4],
      hinge: flex(p[3], p[4], back),
      limits: ballLimits(10, -30, 60, 10),
      effector: true,
    },
  ];
}

function legShapes(joints: JointDef[], radii: number[]): Shape[] {
  return joints.map((j, k) => {
    if (k === joints.length - 1) return block('dark', j.head, j.tail, 0.08, 0.05, j.name, [1, 0, 0]);
    const blendWith = k === 0 ? undefined : joints[k - 1].name;
    return frustum(
      'fur',
      j.head,
      j.tail,
      radii[k],
      radii[k + 1],
      8,
      blendWith
        ? [
            [j.name, 0.5],
            [blendWith, 0.5],
          ]
        : j.name,
      j.name,
    );
  });
}

export const beast: ModelDef = {
  name: 'beast',
  armature: {},
  joints: [
    { name: 'pelvis', head: pelvis, tail: spine, hinge: flex(pelvis, spine, up), limits: fixed },
    {
      name: 'spine',
      parent: 'pelvis',
      head: spine,
      tail: chest,
      hinge: flex(spine, chest, up),
      limits: ballLimits(10, -20, 20, 10),
    },
    {
      name: 'chest',
      parent: 'spine',
      head: chest,
      tail: neck,
      hinge: flex(chest, neck, up),
      limits: ballLimits(10, -15, 15, 10),
    },
    {
      name: 'neck',
      parent: 'chest',
      head: neck,
      tail: head,
      hinge: flex(neck, head, up),
      limits: ballLimits(30, -40, 40, 30),
    },
    {
      name: 'head',
      parent: 'neck',
      head,
      tail: snout,
      hinge: flex(head, snout, up),
      limits: ballLimits(30, -30, 30, 30),
      effector: true,
    },
    ...frontLeg('L'),
    ...frontLeg('R'),
    ...hindLeg('L'),
    ...hindLeg('R'),
    {
      name: 'tail',
      parent: 'pelvis',
      head: tailBase,
      tail: tailTip,
      hinge: flex(tailBase, tailTip, up),
      limits: ballLimits(30, -45, 45, 30),
    },
  ],
  materials: [
    { name: 'fur', color: [0.55, 0.38, 0.22], metallic: 0, roughness: 0.9 },
    { name: 'dark', color: [0.22, 0.16, 0.11], metallic: 0, roughness: 0.8 },
  ],
  shapes: [
    frustum('fur', [0, 0.84, -0.58], spine, 0.15, 0.17, 10, 'pelvis', [
      ['spine', 0.5],
      ['pelvis', 0.5],
    ]),
    frustum(
      'fur',
      spine,
      chest,
      0.17,
      0.19,
      10,
      [
        ['spine', 0.5],
        ['pelvis', 0.5],
      ],
      [
        ['spine', 0.5],
        ['chest', 0.5],
      ],
    ),
    frustum(
      'fur',
      chest,
      [0, 0.97, 0.42],
      0.19,
      0.15,
      10,
      [
        ['spine', 0.5],
        ['chest', 0.5],
      ],
      'chest',
    ),
    frustum(
      'fur',
      neck,
      head,
      0.1,
      0.08,
      8,
      [
        ['neck', 0.5],
        ['chest', 0.5],
      ],
      'neck',
    ),
    block('fur', [0, 1.22, 0.48], [0, 1.19, 0.7], 0.18, 0.16, 'head', [1, 0, 0]),
    block('dark', [0, 1.15, 0.68], [0, 1.1, 0.86], 0.1, 0.09, 'head', [1, 0, 0]),
    frustum('dark', [0.06, 1.29, 0.52], [0.08, 1.38, 0.5], 0.03, 0.005, 5, 'head'),
    frustum('dark', [-0.06, 1.29, 0.52], [-0.08, 1.38, 0.5], 0.03, 0.005, 5, 'head'),
    frustum(
      'fur',
      tailBase,
      tailTip,
      0.045,
      0.012,
      6,
      [
        ['tail', 0.5],
        ['pelvis', 0.5],
      ],
      'tail',
    ),
    ...legShapes(frontLeg('L'), [0.07, 0.06, 0.045, 0.04]),
    ...legShapes(frontLeg('R'), [0.07, 0.06, 0.045, 0.04]),
    ...legShapes(hindLeg('L'), [0.08, 0.06, 0.045, 0.04]),
    ...legShapes(hindLeg('R'), [0.08, 0.06, 0.045, 0.04]),
  ],
};

// Desk lamp (mirrors the report's ikea-lamp: 5 bones, 4 free angles, the shade as end effector).
// Meters, Y up; the arm moves in the XY plane, hinges about Z; the swivel turns about the vertical.
import { fixed, hinge } from './limits.js';
import type { ModelDef } from './model.js';
import { ball, block, frustum } from './shapes.js';
import type { Vec3 } from './vec.js';

const base: Vec3 = [0, 0, 0],
  swivel: Vec3 = [0, 0.04, 0],
  elbow: Vec3 = [0, 0.12, 0];
const knee: Vec3 = [0.12, 0.48, 0],
  neck: Vec3 = [0.5, 0.56, 0],
  mouth: Vec3 = [0.58, 0.42, 0];
const z: Vec3 = [0, 0, 1];

export const lamp: ModelDef = {
  name: 'lamp',
  armature: {},
  joints: [
    { name: 'base', head: base, tail: swivel, hinge: z, limits: fixed },
    {
      name: 'swivel',
      parent: 'base',
      head: swivel,
      tail: elbow,
      hinge: z,
      limits: [
        [-90, 0, 0],
        [90, 0, 0],
      ],
    },
    { name: 'lower_arm', parent: 'swivel', head: elbow, tail: knee, hinge: z, limits: hinge(-50, 60) },
    { name: 'upper_arm', parent: 'lower_arm', head: knee, tail: neck, hinge: z, limits: hinge(-110, 80) },
    { name: 'head', parent: 'upper_arm', head: neck, tail: mouth, hinge: z, limits: hinge(-100, 80), effector: true },
  ],
  materials: [
    { name: 'paint', color: [0.8, 0.16, 0.12], metallic: 0.1, roughness: 0.5 },
    { name: 'metal', color: [0.78, 0.78, 0.8], metallic: 0.4, roughness: 0.35 },
    { name: 'bulb', color: [1, 0.95, 0.7], metallic: 0, roughness: 0.2 },
  ],
  shapes: [
    frustum('paint', [0, 0, 0], [0, 0.03, 0], 0.14, 0.12, 16, 'base'),
    frustum('metal', [0, 0.03, 0], [0, 0.12, 0], 0.025, 0.022, 8, 'swivel'),
    ball('metal', elbow, 0.03, 'lower_arm'),
    block('metal', elbow, knee, 0.03, 0.02, 'lower_arm', z),
    ball('metal', knee, 0.025, 'upper_arm'),
    block('metal', knee, neck, 0.025, 0.018, 'upper_arm', z),
    ball('metal', neck, 0.022, 'head'),
    frustum('paint', [0.52, 0.52, 0], mouth, 0.035, 0.1, 12, 'head'),
    ball('bulb', [0.555, 0.46, 0], 0.035, 'head'),
  ],
};

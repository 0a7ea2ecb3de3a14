// Robot arm (mirrors the report's robot-arm: 7 bones, the tool tip as end effector).
// Meters, Y up, standing straight up at rest; the waist turns about the vertical, the three
// hinges turn about Z, the tool rolls without limit.
import { fixed, hinge } from './limits.js';
import type { ModelDef } from './model.js';
import { block, frustum } from './shapes.js';
import type { Vec3 } from './vec.js';

const y = (h: number): Vec3 => [0, h, 0];
const z: Vec3 = [0, 0, 1];
const across = (h: number, r: number, w: number): [Vec3, Vec3, number, number] => [[0, h, -w], [0, h, w], r, r];

export const robotArm: ModelDef = {
  name: 'robot-arm',
  armature: {},
  joints: [
    { name: 'base', head: y(0), tail: y(0.06), hinge: z, limits: fixed },
    { name: 'riser', parent: 'base', head: y(0.06), tail: y(0.12), hinge: z, limits: fixed },
    {
      name: 'waist',
      parent: 'riser',
      head: y(0.12),
      tail: y(0.2),
      hinge: z,
      limits: [
        [-180, 0, 0],
        [180, 0, 0],
      ],
    },
    { name: 'shoulder', parent: 'waist', head: y(0.2), tail: y(0.55), hinge: z, limits: hinge(-100, 100) },
    { name: 'elbow', parent: 'shoulder', head: y(0.55), tail: y(0.85), hinge: z, limits: hinge(-135, 135) },
    { name: 'wrist', parent: 'elbow', head: y(0.85), tail: y(0.95), hinge: z, limits: hinge(-110, 110) },
    {
      name: 'tool',
      parent: 'wrist',
      head: y(0.95),
      tail: y(1.03),
      hinge: z,
      limits: [
        [0, 0, null],
        [0, 0, null],
      ],
      effector: true,
    },
  ],
  materials: [
    { name: 'dark', color: [0.2, 0.21, 0.23], metallic: 0.3, roughness: 0.5 },
    { name: 'orange', color: [0.95, 0.45, 0.08], metallic: 0.2, roughness: 0.4 },
    { name: 'steel', color: [0.7, 0.72, 0.75], metallic: 0.4, roughness: 0.35 },
  ],
  shapes: [
    frustum('dark', y(0), y(0.06), 0.16, 0.14, 16, 'base'),
    frustum('dark', y(0.06), y(0.12), 0.1, 0.1, 12, 'riser'),
    frustum('orange', y(0.12), y(0.18), 0.11, 0.1, 12, 'waist'),
    block('orange', y(0.17), y(0.26), 0.16, 0.14, 'waist', z),
    frustum('steel', ...across(0.2, 0.065, 0.085), 12, 'shoulder'),
    block('orange', y(0.2), y(0.55), 0.09, 0.1, 'shoulder', z),
    frustum('steel', ...across(0.55, 0.055, 0.07), 12, 'elbow'),
    block('orange', y(0.55), y(0.85), 0.075, 0.085, 'elbow', z),
    frustum('steel', ...across(0.85, 0.045, 0.055), 12, 'wrist'),
    frustum('steel', y(0.85), y(0.95), 0.04, 0.035, 10, 'wrist'),
    frustum('dark', y(0.95), y(0.97), 0.045, 0.045, 10, 'tool'),
    block('dark', [0.025, 0.97, 0], [0.025, 1.05, 0], 0.015, 0.03, 'tool', [1, 0, 0]),
    block('dark', [-0.025, 0.97, 0], [-0.025, 1.05, 0], 0.015, 0.03, 'tool', [1, 0, 0]),
  ],
};

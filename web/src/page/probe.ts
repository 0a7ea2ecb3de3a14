// A small window onto the page for browser tests and tools: screen positions of targets and
// bones, the camera, what is loaded, the targets' orientation goals, the limbs' pole handles and
// the poles the solve is sent, and one action: turning the selected target's gizmo as a rotate
// drag does (turnGizmo). Set as window.ikPage by main.ts.
import { Box3, Quaternion, Vector3 } from 'three';

import { isGoals, orientationErrorsDeg } from '../ik/goals.js';
import { limbPoints } from '../live/pole_placement.js';

import { IkSession } from '../live/session.js';
import type { ScreenPoint } from '../view/stage.js';
import type { PageApp } from './app.js';
import type { PageSettings } from './page_settings.js';
import type { SlowestSolve } from './solve_report.js';

export interface PageProbe {
  /** Loads finished so far, successful or not. */
  loads(): number;
  rigName(): string | null;
  effectors(): number[];
  /** Main-thread ms per live solve over the stats window (the last 121): median, p95, max, window size, solves so far. */
  solveMs(): { median: number; p95: number; max: number; n: number; total: number };
  /** The slowest per-frame solve since the rig loaded. */
  slowestSolve(): SlowestSolve | null;
  /** The tip tolerance in use (the panel's): the on-target distance, rig units. */
  tipTolerance(): number;
  /** Bone names, in bone order. */
  boneNames(): string[];
  /** Bone lengths, in bone order (rig units). */
  boneLengths(): number[];
  /** Where a world point is on screen (client pixels). */
  worldToScreen(p: [number, number, number]): ScreenPoint;
  /** Where target k is on screen (client pixels), or null. */
  targetScreen(k: number): ScreenPoint | null;
  /** Bone i's tip as drawn (world coordinates), or null. */
  boneTip(i: number): [number, number, number] | null;
  /** Bone i's base (its joint) as drawn (world coordinates), or null. */
  boneBase(i: number): [number, number, number] | null;
  /** Where the middle of bone i is on screen, or null. */
  boneScreen(i: number): ScreenPoint | null;
  /** Index of the target holding the gizmo. */
  selectedTarget(): number | null;
  /** The gizmo's handle under the mouse now ('X', 'XY', 'XYZ'…; the gizmo's hover), or null. */
  gizmoAxis(): string | null;
  cameraPosition(): [number, number, number];
  /** Height of the floor (the ground grid), world units. */
  floorY(): number;
  /** Distance from effector k's tip to its target. */
  effectorError(k: number): number;
  /** Target k's world position, or null. */
  targetPosition(k: number): [number, number, number] | null;
  /** End effector k's tip, world position, or null. */
  tipPosition(k: number): [number, number, number] | null;
  /** Screen pixels per rig unit at the selected target (target 0 if none), as the stats use. */
  pixelsPerUnit(): number;
  /** The rig's bounding box at the current pose (world): min and max corners. */
  bounds(): { min: [number, number, number]; max: [number, number, number] } | null;
  /** The root joint's world position (where swing mode swings about), or null. */
  rootJoint(): [number, number, number] | null;
  /** The world box of the scene's object named `name` (a mesh of the model: its vertices as posed now), or null. */
  objectBounds(name: string): { min: [number, number, number]; max: [number, number, number] } | null;
  /** Frames the 3D view has drawn since it was made (a still view draws one a second). */
  drawnFrames(): number;
  /** Asks the 3D view to draw its next frames now (as input does); returns drawnFrames() before. */
  redraw(): number;
  /** The gizmo's mode: translate, rotate or swing. */
  gizmoMode(): string;
  /** Target k's orientation goal [x, y, z, w] (rig coordinates), or null when it has none. */
  orientationGoal(k: number): [number, number, number, number] | null;
  /** End effector k's bone-frame rotation [x, y, z, w] at the current pose (rig coordinates), or null. */
  tipRotation(k: number): [number, number, number, number] | null;
  /** Angle between effector k's bone frame and its orientation goal, DEGREES; NaN without a goal. */
  orientationError(k: number): number;
  /** Whether target k shows its orientation axes. */
  axesShown(k: number): boolean;
  /** The gizmo's object's world quaternion [x, y, z, w] (the selected target, or the swing pivot), or null. */
  gizmoQuaternion(): [number, number, number, number] | null;
  /**
   * Drags the gizmo as a user's rotate drag does: the 'dragging-changed' events around `steps`
   * turns (one per animation frame) of its object about the world `axis` that add up to `degrees`,
   * each followed by the gizmo's 'objectChange' event. Resolves after the drag ended.
   */
  turnGizmo(axis: [number, number, number], degrees: number, steps?: number): Promise<void>;
  /**
   * The limbs' pole handles as drawn (none with pole handles off): per pole its limb's lower bone,
   * the pole, the limb's root (shoulder, hip), joint (elbow, knee) and tip (wrist, ankle) at the
   * current pose (rig units), and where the handle is on screen (client pixels).
   */
  poleHandles(): PoleProbe[];
  /** Index of the pole handle holding the gizmo, or null. */
  selectedPole(): number | null;
  /** The poles the next solve is sent (goals.poles: lower bone and point, rig units); [] when it is sent none. */
  solvePoles(): { bone: number; point: [number, number, number] }[];
  /** The current pose: 3 XZX angles per bone, degrees. */
  angles(): number[];
  /** All targets, 3 per effector, rig units. */
  targets(): number[];
  /** The joint limits in use (the session's: humanoid or the file's), per angle, degrees. */
  limits(): { lower: number[]; upper: number[] };
  /** The page's settings record (what the panel edits): a test may set values the panel's sliders do not reach. */
  settings(): PageSettings;
  /** Steps undo can take now. */
  undoSteps(): number;
  /** Objects alive now: IK sessions and solvers (WebAssembly), geometries and textures (GPU). */
  alive(): { sessions: number; solvers: number; geometries: number; textures: number };
}

/** One pole handle, as poleHandles() reports it (rig units; screen: client pixels). */
export interface PoleProbe {
  bone: number;
  point: [number, number, number];
  root: [number, number, number];
  joint: [number, number, number];
  tip: [number, number, number];
  screen: ScreenPoint;
}

declare global {
  interface Window {
    ikPage?: PageProbe;
  }
}

export function makeProbe(app: PageApp): PageProbe {
  const a = new Vector3(),
    b = new Vector3(),
    turn = new Quaternion();
  const quad = (q: ArrayLike<number>, k: number): [number, number, number, number] => [
    q[4 * k],
    q[4 * k + 1],
    q[4 * k + 2],
    q[4 * k + 3],
  ];
  const { controller } = app;
  const { stage } = controller;
  const session = () => controller.live?.session;
  return {
    loads: () => app.loads,
    rigName: () => controller.live?.name ?? null,
    effectors: () => Array.from(session()?.effectors() ?? []),
    tipTolerance: () => app.settings.tipTolerance,
    slowestSolve: () => app.report.slowest,
    solveMs: () => {
      const t = app.solveTimes;
      return { median: t.median(), p95: t.quantile(0.95), max: t.max(), n: t.size, total: t.total };
    },
    boneNames: () => [...(session()?.spec.names ?? [])],
    boneLengths: () => Array.from(session()?.spec.lengths ?? []),
    worldToScreen: (p) => stage.toScreen(a.set(p[0], p[1], p[2])),
    targetScreen(k) {
      const t = session()?.targets;
      return t && k >= 0 && 3 * k < t.length ? stage.toScreen(a.fromArray(t, 3 * k)) : null;
    },
    boneTip(i) {
      const live = controller.live;
      if (!live || i < 0 || i >= live.session.rig.numBones) return null;
      return live.view.boneTip(i, a).toArray() as [number, number, number];
    },
    boneBase(i) {
      const live = controller.live;
      if (!live || i < 0 || i >= live.session.rig.numBones) return null;
      return live.view.boneBase(i, a).toArray() as [number, number, number];
    },
    boneScreen(i) {
      const live = controller.live;
      if (!live || i < 0 || i >= live.session.rig.numBones) return null;
      live.view.boneBase(i, a);
      live.view.glyphEnd(i, b);
      return stage.toScreen(a.lerp(b, 0.5));
    },
    selectedTarget: () => controller.handles.selected,
    gizmoAxis: () => controller.handles.gizmo.axis,
    drawnFrames: () => stage.drawnFrames,
    redraw() {
      stage.invalidate();
      return stage.drawnFrames;
    },
    selectedPole: () => controller.handles.selectedPole,
    poleHandles() {
      const s = session();
      if (!s || controller.handles.poles.count !== s.goals.poleBones.length) return [];
      const poses = s.poses();
      return Array.from(s.goals.poleBones, (bone, j) => {
        const point = Array.from(s.goals.polePoints.subarray(3 * j, 3 * j + 3)) as [number, number, number];
        return { bone, point, ...limbPoints(s.spec, poses, bone), screen: stage.toScreen(a.fromArray(point)) };
      });
    },
    solvePoles() {
      const problem = session()?.problem();
      if (!problem || !isGoals(problem)) return [];
      return (problem.poles ?? []).map((p) => ({
        bone: Number(p.bone),
        point: Array.from(p.point) as [number, number, number],
      }));
    },
    angles: () => Array.from(session()?.angles ?? []),
    targets: () => Array.from(session()?.targets ?? []),
    limits: () => ({ lower: Array.from(session()?.spec.lower ?? []), upper: Array.from(session()?.spec.upper ?? []) }),
    undoSteps: () => app.history.undoSteps,
    settings: () => app.settings,
    cameraPosition: () => stage.camera.position.toArray() as [number, number, number],
    floorY: () => stage.floorY,
    alive() {
      const memory = stage.renderer.info.memory;
      return { ...IkSession.alive, geometries: memory.geometries, textures: memory.textures };
    },
    targetPosition(k) {
      const t = session()?.targets;
      return t && k >= 0 && 3 * k < t.length ? [t[3 * k], t[3 * k + 1], t[3 * k + 2]] : null;
    },
    tipPosition(k) {
      const t = session()?.tips();
      return t && k >= 0 && 3 * k < t.length ? [t[3 * k], t[3 * k + 1], t[3 * k + 2]] : null;
    },
    pixelsPerUnit() {
      const t = session()?.targets;
      if (!t) return NaN;
      const k = Math.min(controller.handles.selected ?? 0, t.length / 3 - 1);
      return stage.pixelsPerUnit(a.fromArray(t, 3 * k));
    },
    bounds() {
      const box = controller.live?.view.bounds();
      return box ? { min: box.min.toArray(), max: box.max.toArray() } : null;
    },
    objectBounds(name) {
      const object = stage.scene.getObjectByName(name);
      if (!object) return null;
      object.updateWorldMatrix(true, true);
      const box = new Box3().setFromObject(object, true);
      return box.isEmpty() ? null : { min: box.min.toArray(), max: box.max.toArray() };
    },
    gizmoMode: () => controller.handles.gizmoMode,
    rootJoint: () =>
      controller.live ? (controller.live.view.boneBase(0, a).toArray() as [number, number, number]) : null,
    orientationGoal(k) {
      const s = session();
      return s && s.goals.orientation[k] === 1 ? quad(s.goals.rotations, k) : null;
    },
    tipRotation(k) {
      const s = session();
      return s && k >= 0 && k < s.goals.count ? quad(s.tipRotations(), k) : null;
    },
    orientationError(k) {
      const s = session();
      return s && s.goals.orientation[k] === 1
        ? orientationErrorsDeg(s.rig, s.angles, s.goals.goals(s.effectors(), s.targets))[k]
        : NaN;
    },
    axesShown: (k) => controller.handles.axesShown(k),
    gizmoQuaternion() {
      const o = controller.handles.gizmo.object;
      return o ? (o.getWorldQuaternion(new Quaternion()).toArray() as [number, number, number, number]) : null;
    },
    async turnGizmo(axis, degrees, steps = 12) {
      const gizmo = controller.handles.gizmo;
      const object = gizmo.object;
      if (!object) throw new Error('the gizmo holds no target');
      const frame = (): Promise<void> => new Promise((done) => requestAnimationFrame(() => done()));
      turn.setFromAxisAngle(a.set(...axis).normalize(), (degrees * Math.PI) / 180 / steps);
      gizmo.dragging = true;
      for (let i = 0; i < steps; i++) {
        object.quaternion.premultiply(turn); // the object's parent is the scene's untransformed root
        gizmo.dispatchEvent({ type: 'objectChange' });
        await frame();
      }
      gizmo.dragging = false;
    },
    effectorError(k) {
      const s = session();
      if (!s) return NaN;
      const tips = s.tips();
      const t = s.targets;
      return Math.hypot(tips[3 * k] - t[3 * k], tips[3 * k + 1] - t[3 * k + 1], tips[3 * k + 2] - t[3 * k + 2]);
    },
  };
}

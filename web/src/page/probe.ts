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

/** The probe: its parts below, each about one side of the page, put together. */
export function makeProbe(app: PageApp): PageProbe {
  return {
    ...sessionParts(app),
    ...statsParts(app),
    ...viewParts(app),
    ...targetParts(app),
    ...boneParts(app),
    ...effectorParts(app),
    ...gizmoParts(app),
    ...poleParts(app),
  };
}

/** The live rig's IK session, or undefined when none is loaded. */
function sessionOf(app: PageApp): IkSession | undefined {
  return app.controller.live?.session;
}

/** Point k of a flat list of 3-vectors as an array, or null when k is out of range (or there is no list). */
function point3(list: ArrayLike<number> | undefined, k: number): [number, number, number] | null {
  return list && k >= 0 && 3 * k < list.length ? [list[3 * k], list[3 * k + 1], list[3 * k + 2]] : null;
}

/** Quaternion k of a flat list of quaternions (4 each) as [x, y, z, w]. */
function quad(q: ArrayLike<number>, k: number): [number, number, number, number] {
  return [q[4 * k], q[4 * k + 1], q[4 * k + 2], q[4 * k + 3]];
}

/** What is loaded and the solver's state: the rig, its bones, the pose, the targets, limits, settings, undo. */
function sessionParts(
  app: PageApp,
): Pick<
  PageProbe,
  | 'loads'
  | 'rigName'
  | 'effectors'
  | 'boneNames'
  | 'boneLengths'
  | 'angles'
  | 'targets'
  | 'limits'
  | 'settings'
  | 'undoSteps'
  | 'alive'
> {
  const { controller } = app;
  const session = () => sessionOf(app);
  return {
    loads: () => app.loads,
    rigName: () => controller.live?.name ?? null,
    effectors: () => Array.from(session()?.effectors() ?? []),
    boneNames: () => [...(session()?.spec.names ?? [])],
    boneLengths: () => Array.from(session()?.spec.lengths ?? []),
    angles: () => Array.from(session()?.angles ?? []),
    targets: () => Array.from(session()?.targets ?? []),
    limits: () => ({ lower: Array.from(session()?.spec.lower ?? []), upper: Array.from(session()?.spec.upper ?? []) }),
    undoSteps: () => app.history.undoSteps,
    settings: () => app.settings,
    alive() {
      const memory = controller.stage.renderer.info.memory;
      return { ...IkSession.alive, geometries: memory.geometries, textures: memory.textures };
    },
  };
}

/** Stats and timing: solve times, the slowest solve, and the tip tolerance they are judged by. */
function statsParts(app: PageApp): Pick<PageProbe, 'solveMs' | 'slowestSolve' | 'tipTolerance'> {
  return {
    tipTolerance: () => app.settings.tipTolerance,
    slowestSolve: () => app.report.slowest,
    solveMs: () => {
      const t = app.solveTimes;
      return { median: t.median(), p95: t.quantile(0.95), max: t.max(), n: t.size, total: t.total };
    },
  };
}

/** The 3D view: world to screen, the camera, the floor, frames drawn, and the world boxes of the rig and of objects. */
function viewParts(
  app: PageApp,
): Pick<
  PageProbe,
  'worldToScreen' | 'cameraPosition' | 'floorY' | 'drawnFrames' | 'redraw' | 'bounds' | 'objectBounds'
> {
  const { controller } = app;
  const { stage } = controller;
  const a = new Vector3();
  return {
    worldToScreen: (p) => stage.toScreen(a.set(p[0], p[1], p[2])),
    cameraPosition: () => stage.camera.position.toArray() as [number, number, number],
    floorY: () => stage.floorY,
    drawnFrames: () => stage.drawnFrames,
    redraw() {
      stage.invalidate();
      return stage.drawnFrames;
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
  };
}

/** The targets and the effectors' tips: where they are in the world and on screen, and the scale there. */
function targetParts(
  app: PageApp,
): Pick<PageProbe, 'targetScreen' | 'targetPosition' | 'tipPosition' | 'pixelsPerUnit'> {
  const { controller } = app;
  const { stage } = controller;
  const a = new Vector3();
  return {
    targetScreen(k) {
      const p = point3(sessionOf(app)?.targets, k);
      return p ? stage.toScreen(a.fromArray(p)) : null;
    },
    targetPosition: (k) => point3(sessionOf(app)?.targets, k),
    tipPosition: (k) => point3(sessionOf(app)?.tips(), k),
    pixelsPerUnit() {
      const t = sessionOf(app)?.targets;
      if (!t) return NaN;
      const k = Math.min(controller.handles.selected ?? 0, t.length / 3 - 1);
      return stage.pixelsPerUnit(a.fromArray(t, 3 * k));
    },
  };
}

/** The bones as drawn: their tips, bases (joints), middles on screen, and the root joint. */
function boneParts(app: PageApp): Pick<PageProbe, 'boneTip' | 'boneBase' | 'boneScreen' | 'rootJoint'> {
  const { controller } = app;
  const a = new Vector3(),
    b = new Vector3();
  // The view drawing bone i, or null when no rig is loaded or it has no bone i.
  const viewOf = (i: number) => {
    const live = controller.live;
    return live && i >= 0 && i < live.session.rig.numBones ? live.view : null;
  };
  return {
    boneTip(i) {
      const view = viewOf(i);
      return view ? (view.boneTip(i, a).toArray() as [number, number, number]) : null;
    },
    boneBase(i) {
      const view = viewOf(i);
      return view ? (view.boneBase(i, a).toArray() as [number, number, number]) : null;
    },
    boneScreen(i) {
      const view = viewOf(i);
      if (!view) return null;
      view.boneBase(i, a);
      view.glyphEnd(i, b);
      return controller.stage.toScreen(a.lerp(b, 0.5));
    },
    rootJoint: () =>
      controller.live ? (controller.live.view.boneBase(0, a).toArray() as [number, number, number]) : null,
  };
}

/** The effectors against their goals: how far each tip is off, its orientation goal, its rotation, and the angle off. */
function effectorParts(
  app: PageApp,
): Pick<PageProbe, 'effectorError' | 'orientationGoal' | 'tipRotation' | 'orientationError'> {
  return {
    effectorError(k) {
      const s = sessionOf(app);
      if (!s) return NaN;
      const tips = s.tips();
      const t = s.targets;
      return Math.hypot(tips[3 * k] - t[3 * k], tips[3 * k + 1] - t[3 * k + 1], tips[3 * k + 2] - t[3 * k + 2]);
    },
    orientationGoal(k) {
      const s = sessionOf(app);
      return s && s.goals.orientation[k] === 1 ? quad(s.goals.rotations, k) : null;
    },
    tipRotation(k) {
      const s = sessionOf(app);
      return s && k >= 0 && k < s.goals.count ? quad(s.tipRotations(), k) : null;
    },
    orientationError(k) {
      const s = sessionOf(app);
      return s && s.goals.orientation[k] === 1
        ? orientationErrorsDeg(s.rig, s.angles, s.goals.goals(s.effectors(), s.targets))[k]
        : NaN;
    },
  };
}

/** The selection and the gizmo: what it holds, its mode, handle and turn, the axes shown, and a rotate drag. */
function gizmoParts(
  app: PageApp,
): Pick<PageProbe, 'selectedTarget' | 'gizmoAxis' | 'gizmoMode' | 'axesShown' | 'gizmoQuaternion' | 'turnGizmo'> {
  const { handles } = app.controller;
  const a = new Vector3(),
    turn = new Quaternion();
  return {
    selectedTarget: () => handles.selected,
    gizmoAxis: () => handles.gizmo.axis,
    gizmoMode: () => handles.gizmoMode,
    axesShown: (k) => handles.axesShown(k),
    gizmoQuaternion() {
      const o = handles.gizmo.object;
      return o ? (o.getWorldQuaternion(new Quaternion()).toArray() as [number, number, number, number]) : null;
    },
    async turnGizmo(axis, degrees, steps = 12) {
      const gizmo = handles.gizmo;
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
  };
}

/** The limbs' poles: the pole handles as drawn, the one selected, and the poles the solve is sent. */
function poleParts(app: PageApp): Pick<PageProbe, 'poleHandles' | 'selectedPole' | 'solvePoles'> {
  const { controller } = app;
  const a = new Vector3();
  return {
    selectedPole: () => controller.handles.selectedPole,
    poleHandles() {
      const s = sessionOf(app);
      if (!s || controller.handles.poles.count !== s.goals.poleBones.length) return [];
      const poses = s.poses();
      return Array.from(s.goals.poleBones, (bone, j) => {
        const point = Array.from(s.goals.polePoints.subarray(3 * j, 3 * j + 3)) as [number, number, number];
        return {
          bone,
          point,
          ...limbPoints(s.spec, poses, bone),
          screen: controller.stage.toScreen(a.fromArray(point)),
        };
      });
    },
    solvePoles() {
      const problem = sessionOf(app)?.problem();
      if (!problem || !isGoals(problem)) return [];
      return (problem.poles ?? []).map((p) => ({
        bone: Number(p.bone),
        point: Array.from(p.point) as [number, number, number],
      }));
    },
  };
}

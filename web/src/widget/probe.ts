// A read-only snapshot of a widget for browser tests and tools (the element's `probe` property):
// the selected target, targets and tips, where the targets are on screen, the tip tolerance and
// the camera. Plain data, so it crosses from the page to a test runner as JSON.
import { Vector3 } from 'three';

import { orientationErrorsDeg } from '../ik/goals.js';

import type { LiveController } from '../view/live_controller.js';
import type { ScreenPoint } from '../view/stage.js';

export interface WidgetProbe {
  /** Index (in effector order) of the target holding the gizmo, or null. */
  selected: number | null;
  /** The end effectors' bone names, in effector order. */
  effectorNames: string[];
  /** Per effector: whether its target sets its tip's position. */
  positionGoals: boolean[];
  /** Per effector: its orientation goal [x, y, z, w] (rig coordinates), or null. */
  orientationGoals: ([number, number, number, number] | null)[];
  /** Per effector: the angle between its bone frame and its orientation goal, DEGREES (null without a goal). */
  orientationErrors: (number | null)[];
  /** The gizmo's mode: translate or rotate. */
  gizmoMode: string;
  /** Targets, 3 numbers per end effector, rig units. */
  targets: number[];
  /** End-effector tips at the current pose, 3 numbers per end effector, rig units. */
  tips: number[];
  /** Where each target is on screen, client pixels. */
  targetsOnScreen: ScreenPoint[];
  /** An effector within this distance of its target is on target, rig units. */
  tipTolerance: number;
  /** The camera's position, rig units. */
  camera: [number, number, number];
}

/** The snapshot of the rig `controller` shows (null when none); the tip tolerance is the one it solves with. */
export function widgetProbe(controller: LiveController): WidgetProbe | null {
  const live = controller.live;
  if (!live) return null;
  const { stage, handles } = controller;
  const targets = live.session.targets;
  const p = new Vector3();
  const targetsOnScreen: ScreenPoint[] = [];
  for (let k = 0; k < targets.length / 3; k++) targetsOnScreen.push(stage.toScreen(p.fromArray(targets, 3 * k)));
  const { goals, spec, rig, angles } = live.session;
  const bones = Array.from(live.session.effectors());
  const errors = goals.anyOrientation ? orientationErrorsDeg(rig, angles, goals.goals(bones, targets)) : null;
  return {
    effectorNames: bones.map((b) => spec.names[b] || `bone ${b}`),
    positionGoals: bones.map((_, k) => goals.position[k] === 1),
    orientationGoals: bones.map((_, k) =>
      goals.orientation[k] === 1
        ? (Array.from(goals.rotations.subarray(4 * k, 4 * k + 4)) as [number, number, number, number])
        : null,
    ),
    orientationErrors: bones.map((_, k) => (errors && goals.orientation[k] === 1 ? errors[k] : null)),
    gizmoMode: handles.gizmoMode,
    selected: handles.selected,
    targets: Array.from(targets),
    tips: Array.from(live.session.tips()),
    targetsOnScreen,
    tipTolerance: controller.settings.tipTolerance,
    camera: stage.camera.position.toArray() as [number, number, number],
  };
}

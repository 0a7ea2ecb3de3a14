// A read-only snapshot of a widget for browser tests and tools (the element's `probe` property):
// the selected target, targets and tips, where the targets are on screen, the tip tolerance and
// the camera. Plain data, so it crosses from the page to a test runner as JSON.
import { Vector3 } from 'three';

import type { LiveController } from '../live/live_controller.js';
import type { ScreenPoint } from '../view/stage.js';

export interface WidgetProbe {
  /** Index (in effector order) of the target holding the gizmo, or null. */
  selected: number | null;
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
  return {
    selected: handles.selected,
    targets: Array.from(targets),
    tips: Array.from(live.session.tips()),
    targetsOnScreen,
    tipTolerance: controller.settings.tipTolerance,
    camera: stage.camera.position.toArray() as [number, number, number],
  };
}

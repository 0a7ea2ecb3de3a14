// A read-only snapshot of a widget for browser tests and tools (the element's `probe` property):
// the selected target, targets and tips, where the targets are on screen, the tip tolerance and
// the camera. Plain data, so it crosses from the page to a test runner as JSON.
import { Vector3 } from 'three';

import type { Handles } from '../page/handles.js';
import type { LiveRig } from '../page/live_rig.js';
import type { ScreenPoint } from '../page/probe.js';
import type { Stage } from '../page/scene.js';

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

/** The snapshot of one installed rig; `tipTolerance` is the one the widget solves with (rig units). */
export function widgetProbe(live: LiveRig, handles: Handles, stage: Stage, tipTolerance: number): WidgetProbe {
  const targets = live.session.targets;
  const p = new Vector3();
  const targetsOnScreen: ScreenPoint[] = [];
  for (let k = 0; k < targets.length / 3; k++) targetsOnScreen.push(stage.toScreen(p.fromArray(targets, 3 * k)));
  return {
    selected: handles.selected,
    targets: Array.from(targets),
    tips: Array.from(live.session.tips()),
    targetsOnScreen,
    tipTolerance,
    camera: stage.camera.position.toArray() as [number, number, number],
  };
}

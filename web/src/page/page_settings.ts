// What the page's panel edits: the per-frame solve's settings (FrameSettings, read by the
// LiveController every frame), compare's and step mode's, and the display options, with their
// starting values.
import { FRAME_DEFAULTS } from '../live/live_solve.js';
import type { FrameSettings } from '../view/live_controller.js';
import type { GizmoMode } from '../view/handles.js';

export type ClickAction = 'toggle effector' | 'select only';

/** Where compare starts every method from. */
export type CompareStart = 'current pose' | 'rest pose';

export interface PageSettings extends FrameSettings {
  /** The project rig's key (?rig=), or the file choice's. */
  rig: string;
  /** Anatomical limits for a rig recognised as a humanoid (else the file's own limits). */
  humanoidLimits: boolean;
  /** Compare's random restarts after a stall (the per-frame solve never restarts). */
  restarts: number;
  compareTimeBudgetMs: number;
  compareMaxIterations: number;
  /** Where every method of a compare starts: the rest pose by default (right after a drag that ended on target, from the current pose every method has nothing to do). */
  compareFrom: CompareStart;
  showMesh: boolean;
  showBones: boolean;
  gizmo: GizmoMode;
  /** A pole handle per limb (a bend hint for the elbow or knee, sent with every solve). */
  poleHandles: boolean;
  clickBone: ClickAction;
  stepMode: boolean;
  /** Step mode takes one iteration every stepIntervalMs milliseconds. */
  autoStep: boolean;
  stepIntervalMs: number;
}

/** The settings a page opens with, for rig key `rig` and solver method `method`. */
export function initialSettings(rig: string, method: string): PageSettings {
  return {
    rig,
    humanoidLimits: true,
    method,
    gradientTolerance: 1e-7,
    tipTolerance: 1e-3,
    ...FRAME_DEFAULTS,
    restarts: 0,
    paperMode: false,
    strictPriority: true,
    pinOrientations: true,
    stillBody: true,
    compareTimeBudgetMs: 1000,
    compareMaxIterations: 100000,
    compareFrom: 'rest pose',
    showMesh: true,
    showBones: true,
    gizmo: 'translate',
    poleHandles: false,
    clickBone: 'toggle effector',
    stepMode: false,
    autoStep: false,
    stepIntervalMs: 600,
  };
}

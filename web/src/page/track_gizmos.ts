// Track mode's three gizmos: the page's target handles (web/src/view/handles.ts) on the head and
// both hands, each showing its position and its frame's axes. Moving one writes its tracked point
// (TrackedPoints, rig units); turning one (rotate or swing mode) writes its frame. A translated
// point's frame is left to the owner (track mode carries it along with the body). While a clip or
// a headset drives the points, the gizmo lets go and the handles only follow.
import type { Vector3 } from 'three';

import { type GizmoMode, Handles } from '../view/handles.js';
import type { Stage } from '../view/stage.js';
import { TRACKED_KEYS, type TrackedPoints } from './tracked_points.js';

/** Every tracked point has an orientation goal: its handle always shows its axes. */
const ALL_TURNED = new Uint8Array(TRACKED_KEYS.length).fill(1);

export class TrackGizmos {
  readonly handles: Handles;
  /** The handle the gizmo held before it let go (follow()), taken back by hold(). */
  private held: number | null = null;

  /**
   * Handles on `stage` that write into `points`; `moved(k, translated)` is called after each move
   * or turn of point k, `translated` true when the gizmo only moved it (translate mode), false when
   * it set its frame too. Made once: they hold no targets until show().
   */
  constructor(stage: Stage, points: TrackedPoints, moved: (k: number, translated: boolean) => void) {
    this.handles = new Handles(stage);
    // The orbit controls listen again after this gizmo, as they do after the drag mode's: a drag
    // that starts on the gizmo must not orbit the camera too.
    stage.connectOrbit();
    this.handles.onTargetMoved = (k, x, y, z) => {
      points.setPosition(k, x, y, z);
      moved(k, this.handles.gizmoMode === 'translate');
    };
    this.handles.onTargetTurned = (k, q) => {
      points.setRotation(k, q.x, q.y, q.z, q.w);
      moved(k, false);
    };
    this.handles.currentRotation = (k, out) => void out.fromArray(points.rotations, 4 * k);
  }

  /** Shows a handle on each of `points`, sized for a rig of `size` (RigView.size); swing mode turns about `pivot` (rig units). The gizmo takes the head. */
  show(points: TrackedPoints, size: number, pivot: Vector3): void {
    this.handles.setRigSize(size);
    this.handles.setPivot(pivot);
    this.handles.setTargets(points.positions);
    this.held = null;
  }

  /** Removes the handles (and lets the gizmo go). */
  hide(): void {
    this.handles.setTargets(new Float64Array(0));
    this.held = null;
  }

  /** The gizmo lets go: something else (a clip, a headset) moves the points now. */
  follow(): void {
    if (this.handles.selected !== null) this.held = this.handles.selected;
    this.handles.select(null);
  }

  /** The gizmo takes the handle it held before follow() again (the head if none). */
  hold(): void {
    this.handles.select(this.held ?? 0);
    this.held = null;
  }

  /** Whether the gizmo is being dragged or the pointer is over it (a click then is no pick). */
  get busy(): boolean {
    return this.handles.dragging || this.handles.hovering;
  }

  setMode(mode: GizmoMode): void {
    this.handles.setMode(mode);
  }

  /** Moves the handles to `points` and their tip markers to `tips` (3 per point at least, rig units: the avatar's head and hands). */
  sync(points: TrackedPoints, tips: Float64Array): void {
    this.handles.sync(points.positions, tips, ALL_TURNED, points.rotations);
  }

  dispose(): void {
    this.handles.dispose();
  }
}

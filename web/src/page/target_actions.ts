// What the panel and the keys do to the targets and their gizmo: the gizmo's mode (W, E, Q), the
// target the gizmo holds (Tab, Shift+Tab, Esc; in track mode, the tracked point), the selected
// target's orientation goal (O, an undoable edit) and the pole handles (P). The panel shows each
// change.
import type { LiveController } from '../view/live_controller.js';
import type { Handles } from '../view/handles.js';
import type { EditHistory } from './page_history.js';
import type { PageSettings } from './page_settings.js';
import type { Panel } from './panel.js';
import { deselectTarget, stepTarget } from './selection.js';
import type { TrackMode } from './track_mode.js';

export class TargetActions {
  /** `panel` shows each change; `history` records the orientation goals' edits. */
  constructor(
    private readonly settings: PageSettings,
    private readonly controller: LiveController,
    private readonly track: TrackMode,
    private readonly panel: Panel,
    private readonly history: EditHistory,
  ) {}

  /** The gizmo's mode, in the drag mode and in track mode. */
  setGizmo(mode: PageSettings['gizmo']): void {
    this.settings.gizmo = mode;
    this.controller.handles.setMode(mode);
    this.track.setGizmo(mode);
    this.panel.refresh();
  }

  /** Tab (step 1) and Shift+Tab (-1): the gizmo takes the next or the previous target. */
  stepTarget(step: 1 | -1): void {
    const handles = this.selectable();
    if (handles) stepTarget(handles, step);
  }

  /** Esc: the gizmo lets go (the help, if open, was closed instead). */
  deselect(): void {
    const handles = this.selectable();
    if (handles) deselectTarget(handles);
  }

  /** Pole handles on or off, the other way round from now. */
  togglePoleHandles(): void {
    this.settings.poleHandles = !this.settings.poleHandles;
    this.controller.setPoleHandles(this.settings.poleHandles);
    this.panel.refresh();
  }

  /** The selected target's orientation goal on, off, or (no argument) the other way round. */
  setOrientationGoal(on?: boolean): void {
    const k = this.controller.handles.selected;
    if (k === null) {
      this.showGoals();
      return;
    }
    this.history.edit(() => this.controller.setOrientationGoal(k, on ?? !this.controller.orientationGoal(k)));
  }

  /** The panel's "orientation goal" box follows the selected target. */
  showGoals(): void {
    const k = this.controller.handles.selected;
    this.panel.showOrientationGoal(k !== null && this.controller.orientationGoal(k), k !== null);
  }

  /**
   * The handles Tab and Esc select among: the drag mode's targets, or in track mode the tracked
   * points while their gizmos move them (none while a clip or a headset does).
   */
  private selectable(): Handles | null {
    if (!this.track.active) return this.controller.handles;
    return this.track.source === 'gizmos' ? this.track.gizmos.handles : null;
  }
}

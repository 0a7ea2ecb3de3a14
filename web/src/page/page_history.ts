// The page's undo and redo (Ctrl+Z, Ctrl+Shift+Z): every edit a user makes to the rig on screen
// (a target or pole dragged or turned, an end effector added or removed, an orientation goal on or
// off, a reset, a pose file loaded) and every rig load. A step keeps the rig it was made on (its
// parsed file, so undoing a rig load shows the earlier rig again, built anew) and the pose, targets
// and goals (pose_state.ts).
import type { LiveController } from '../view/live_controller.js';
import type { RigSource } from '../view/rig_source.js';
import { capturePose, samePose, type PoseState } from '../live/pose_state.js';
import { UndoHistory } from './undo_stacks.js';

/** Steps kept (at least 100, as a user of an editor expects). */
export const UNDO_STEPS = 200;

/** One undoable state of the page: which rig and what was done to it. */
export interface PageState {
  source: RigSource;
  /** Its project rig key, or null for a user's file. */
  key: string | null;
  pose: PoseState;
}

export class EditHistory {
  private readonly history = new UndoHistory<PageState>(UNDO_STEPS);
  private dragStart: PageState | null = null;
  private busy = false;

  /** `showRig` builds and shows a rig from its source (undoing or redoing a rig load). */
  constructor(
    private readonly controller: LiveController,
    private readonly rigKey: () => string | null,
    private readonly showRig: (source: RigSource, key: string | null) => Promise<void>,
    /** Called after every change of what can be undone or redone. */
    private readonly changed: () => void = () => {},
  ) {}

  get canUndo(): boolean {
    return this.history.canUndo;
  }

  get canRedo(): boolean {
    return this.history.canRedo;
  }

  get undoSteps(): number {
    return this.history.undoSteps;
  }

  /** The page's state now, or null with no rig shown. */
  current(): PageState | null {
    const live = this.controller.live;
    return live ? { source: live.source, key: this.rigKey(), pose: capturePose(live.session) } : null;
  }

  /** Runs `edit` (an edit of the rig shown) and records the state before it if it changed anything. */
  edit<T>(edit: () => T): T {
    const before = this.current();
    const result = edit();
    const after = this.current();
    if (before && after && (after.source !== before.source || !samePose(before.pose, after.pose))) this.record(before);
    return result;
  }

  /** A rig is about to replace the one shown: that one's state becomes undoable. */
  rigReplacing(): void {
    const before = this.current();
    if (before) this.record(before);
  }

  /** A drag of a target or a pole started (true) or ended (false): one step for the whole drag. */
  dragging(on: boolean): void {
    if (on) {
      this.dragStart = this.current();
      return;
    }
    const before = this.dragStart;
    this.dragStart = null;
    const after = this.current();
    if (before && after && before.source === after.source && !samePose(before.pose, after.pose)) this.record(before);
  }

  /** Undoes the last step; false when there was none (or one is being shown). */
  undo(): Promise<boolean> {
    return this.move(true);
  }

  /** Redoes the last undone step; false when there was none. */
  redo(): Promise<boolean> {
    return this.move(false);
  }

  private record(before: PageState): void {
    this.history.record(before);
    this.changed();
  }

  private async move(back: boolean): Promise<boolean> {
    const now = this.current();
    if (!now || this.busy || this.controller.handles.dragging || this.controller.paused) return false;
    const state = back ? this.history.undo(now) : this.history.redo(now);
    if (!state) return false;
    this.busy = true;
    try {
      if (state.source !== now.source) await this.showRig(state.source, state.key);
      if (this.controller.live?.source !== state.source) throw new Error('the rig could not be shown again');
      this.controller.restore(state.pose);
    } catch (e) {
      this.history.putBack(state, back);
      throw e;
    } finally {
      this.busy = false;
      this.changed();
    }
    return true;
  }
}

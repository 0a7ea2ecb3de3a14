// Track mode: the whole body follows three tracked points, the head and both hands,
// through the avatar solver (AvatarDriver), one solve every frame from the last pose (as a tracker
// streams: a foot's step goes on while the points rest), drawn on the rig's view as the page draws
// poses. The points come from three gizmos (TrackGizmos), or from a
// clip of the glTF playing on a ghost beside the avatar (ClipPlayer), or from a headset and its
// controllers in immersive VR (VrSession, XrTracking). A point the translate gizmo moves has its
// frame carried along as the body would carry it (AvatarDriver.carryFrame); the rotate gizmo sets it.
//
// While it is on, the drag mode is put away: the LiveController is paused (no solve and no redraw,
// as during a compare, so undo, step mode and compare wait too) and its targets, gizmo, step-mode
// ghost and limit sectors are hidden. leave() puts them back and redraws the rig as it was. The
// page leaves track mode before anything changes the drag mode's rig or problem.
import { Vector3 } from 'three';

import type { IkCoreModule } from '../ik/module.js';
import { errorText } from '../live/error_text.js';
import type { LiveController } from '../view/live_controller.js';
import type { LiveRig } from '../view/live_rig.js';
import type { SolveOutcome } from '../live/method_solver.js';
import type { GizmoMode } from '../view/handles.js';
import type { ViewClick } from '../view/picking.js';
import { AvatarDriver, avatarProblem } from './avatar_driver.js';
import { ClipPlayer, clipNames } from './clip_player.js';
import { TrackGizmos } from './track_gizmos.js';
import { TrackedPoints } from './tracked_points.js';
import { VrSession } from './xr_session.js';
import { XrTracking } from './xr_tracking.js';

/** A layer no camera draws and no ray picks: where the drag mode's handles wait while track mode is on. */
const AWAY_LAYER = 31;
/** The ghost stands this many of the avatar's heights to its left. */
const GHOST_SPACING = 1;
/** In VR the viewer starts this many of the avatar's heights in front of it, facing it. */
const VR_DISTANCE = 1.5;

/** What moves the tracked points. */
export type TrackSource = 'gizmos' | 'clip' | 'vr';

export class TrackMode {
  /** Called after track mode went on or off, a clip started or stopped, or VR began or ended (the panel shows it). */
  onChanged: () => void = () => {};
  /** Called after each solve. */
  onSolved: () => void = () => {};
  /** The head and hands the avatar follows, rig coordinates. */
  readonly points = new TrackedPoints();
  readonly gizmos: TrackGizmos;
  /** Solves since track mode went on. */
  solves = 0;
  /** The last solve's outcome; null before the first. */
  outcome: SolveOutcome | null = null;
  private driver: AvatarDriver | null = null;
  private live: LiveRig | null = null;
  private clips: ClipPlayer | null = null;
  /** Counts clip loads begun: one that ends after a newer one began, or after leave(), is dropped. */
  private clipLoads = 0;
  private vr: VrSession | null = null;
  private vrStarting = false;
  private xr: XrTracking | null = null;
  /** Per tracked point: a gizmo translated it since the last solve, so its frame is carried along (AvatarDriver.carryFrame). */
  private readonly translated = [false, false, false];
  /** What the drag mode showed when track mode put it away. */
  private dragMode = { target: null as number | null, pole: null as number | null, stepGhost: false, limits: false };

  /** Track mode for the rigs `controller` shows; `failed` shows a message saying what went wrong. */
  constructor(
    private readonly module: IkCoreModule,
    private readonly controller: LiveController,
    private readonly failed: (message: string) => void,
  ) {
    this.gizmos = new TrackGizmos(controller.stage, this.points, (k, translated) => (this.translated[k] = translated));
    controller.stage.onFrame((seconds) => this.frame(seconds));
  }

  get active(): boolean {
    return this.driver !== null;
  }

  /** The avatar while track mode is on, else null. */
  get avatar(): AvatarDriver | null {
    return this.driver;
  }

  /** The clips' player once a clip has been played in this track mode, else null. */
  get clipPlayer(): ClipPlayer | null {
    return this.clips;
  }

  /** What moves the points now. */
  get source(): TrackSource {
    return this.clips?.playing != null ? 'clip' : this.vr ? 'vr' : 'gizmos';
  }

  /** Why the rig shown cannot be tracked, as a sentence; null when it can. */
  problem(): string | null {
    const live = this.controller.live;
    return live ? avatarProblem(live.source) : 'no rig is loaded';
  }

  /** The names of the shown rig's animation clips, in file order. */
  clipNames(): string[] {
    const live = this.controller.live;
    return live ? clipNames(live.source) : [];
  }

  /** Turns track mode on for the rig shown, the avatar standing at rest; false (with a message) when it cannot. */
  enter(): boolean {
    if (this.driver) return true;
    const live = this.controller.live;
    if (!live) return false;
    if (this.controller.paused) {
      this.failed('track mode waits for the compare to finish');
      return false;
    }
    try {
      this.driver = new AvatarDriver(this.module, live.source);
    } catch (e) {
      this.failed(`track mode: ${errorText(e)}`);
      return false;
    }
    this.live = live;
    this.solves = 0;
    this.standUp(this.driver);
    this.putAwayDragMode(live);
    const rest = live.source.spec.rest; // bone 0's rest frame, row-major: its origin is the root joint
    this.gizmos.show(this.points, live.view.size, new Vector3(rest[3], rest[7], rest[11]));
    this.onChanged();
    return true;
  }

  /** Turns track mode off (a clip stops, VR ends): the drag mode comes back with the rig as it was. */
  leave(): void {
    const live = this.live;
    if (!this.driver || !live) return;
    this.clipLoads++;
    this.vr?.end();
    this.vr = null;
    this.xr = null;
    this.clips?.dispose();
    this.clips = null;
    this.gizmos.hide();
    this.driver.dispose();
    this.driver = null;
    this.live = null;
    this.outcome = null;
    this.bringBackDragMode(live);
    this.onChanged();
  }

  toggle(): void {
    if (this.active) this.leave();
    else this.enter();
  }

  /** In track mode: the avatar stands at rest again with the points on it, a clip stops, VR calibrates anew; returns true. Else false. */
  reset(): boolean {
    const live = this.live;
    if (!this.driver || !live) return false;
    let driver: AvatarDriver;
    try {
      driver = new AvatarDriver(this.module, live.source);
    } catch (e) {
      this.failed(`track mode: ${errorText(e)}`);
      return true;
    }
    this.driver.dispose();
    this.driver = driver;
    this.standUp(driver);
    if (this.xr) this.xr = new XrTracking(driver.standing);
    this.stopClip();
    return true;
  }

  /** A click on the view: in track mode it may put the gizmo on a tracked point, and is taken (true); else false. */
  click(c: ViewClick): boolean {
    if (!this.active) return false;
    if (this.source === 'gizmos' && !this.gizmos.busy) {
      const k = this.gizmos.handles.pick(c.raycaster);
      if (k !== null) this.gizmos.handles.select(k);
    }
    return true;
  }

  setGizmo(mode: GizmoMode): void {
    this.gizmos.setMode(mode);
  }

  /**
   * Plays clip `index` (file order) of the rig's glTF, turning track mode on first: the ghost
   * shows the clip beside the avatar, which follows its head and hands; the camera takes both in.
   * Loads the clips on first use; a failure is shown as a message.
   */
  async playClip(index: number): Promise<void> {
    if (!this.enter()) return;
    const live = this.live!,
      driver = this.driver!;
    if (!this.clips) {
      const load = ++this.clipLoads;
      let player: ClipPlayer;
      try {
        player = await ClipPlayer.load(
          live.source,
          driver.solver.bones,
          driver.standing.points,
          this.ghostOffset(driver),
        );
      } catch (e) {
        if (load === this.clipLoads) this.failed(`play clip: ${errorText(e)}`);
        return;
      }
      if (load !== this.clipLoads) {
        player.dispose();
        return;
      }
      this.clips = player;
      this.controller.stage.scene.add(player.root);
    }
    try {
      this.clips.play(index);
    } catch (e) {
      this.failed(`play clip: ${errorText(e)}`);
      return;
    }
    this.gizmos.follow();
    if (!this.vr) this.frameWithGhost(live);
    this.onChanged();
  }

  /** Stops the clip playing, if any: the avatar keeps its pose and the gizmos take over (unless in VR). */
  stopClip(): void {
    if (this.clips?.playing == null) return;
    this.clips.stop();
    if (!this.vr) this.gizmos.hold();
    this.onChanged();
  }

  get inVr(): boolean {
    return this.vr !== null;
  }

  /**
   * Enters immersive VR, turning track mode on first: the headset moves the head and the
   * controllers' grips the hands (calibrated on the first frame that tracks all three, the user
   * standing as the avatar stands; a squeeze calibrates anew). A failure is shown as a message.
   */
  async enterVr(): Promise<void> {
    if (this.vr || this.vrStarting || !this.enter()) return;
    const s = this.driver!.standing,
      h = s.height;
    const forward = new Vector3(...s.forward);
    const at = new Vector3(s.points.positions[0], s.floorY, s.points.positions[2]).addScaledVector(
      forward,
      VR_DISTANCE * h,
    );
    this.vrStarting = true;
    let vr: VrSession;
    try {
      vr = await VrSession.start(this.controller.stage.renderer, at, forward.negate(), {
        ended: () => this.vrEnded(vr),
        squeezed: () => this.xr?.recalibrate(),
      });
    } catch (e) {
      this.failed(`could not enter VR: ${errorText(e)}`);
      return;
    } finally {
      this.vrStarting = false;
    }
    if (!this.driver) {
      vr.end(); // track mode was left meanwhile
      return;
    }
    this.vr = vr;
    this.xr = new XrTracking(this.driver.standing);
    this.gizmos.follow();
    this.onChanged();
  }

  /** Leaves VR (track mode stays on, the gizmos take over). */
  exitVr(): void {
    this.vr?.end();
  }

  dispose(): void {
    this.leave();
    this.gizmos.dispose();
  }

  /** The avatar `driver` stands at rest, the points on its head and hands; solved and drawn next frame. */
  private standUp(driver: AvatarDriver): void {
    const standing = driver.standing.points;
    this.points.copy(standing.positions, standing.rotations);
    this.outcome = null;
  }

  private vrEnded(vr: VrSession): void {
    if (this.vr !== vr) return;
    this.vr = null;
    this.xr = null;
    if (this.active && this.source === 'gizmos') this.gizmos.hold();
    this.onChanged();
  }

  /** Where the ghost stands: GHOST_SPACING heights to the avatar's left (rig units). */
  private ghostOffset(driver: AvatarDriver): Vector3 {
    const [fx, , fz] = driver.standing.forward;
    return new Vector3(fz, 0, -fx).multiplyScalar(GHOST_SPACING * driver.standing.height); // up x forward
  }

  /** Points the camera at the avatar and the ghost together. */
  private frameWithGhost(live: LiveRig): void {
    const box = live.view.bounds();
    if (this.clips) box.union(box.clone().translate(this.clips.root.position));
    this.controller.stage.frame(box);
  }

  /** The drag mode's targets, gizmo, step ghost and limit sectors are hidden, its solving paused. */
  private putAwayDragMode(live: LiveRig): void {
    const handles = this.controller.handles;
    this.dragMode = {
      target: handles.selected,
      pole: handles.selectedPole,
      stepGhost: live.ghost.root.visible,
      limits: live.limits.root.visible,
    };
    handles.select(null);
    handles.root.traverse((o) => o.layers.set(AWAY_LAYER));
    live.ghost.root.visible = false;
    live.limits.root.visible = false;
    this.controller.paused = true;
  }

  /** The drag mode as putAwayDragMode() found it; the rig is redrawn from its session next frame. */
  private bringBackDragMode(live: LiveRig): void {
    const handles = this.controller.handles,
      was = this.dragMode;
    handles.root.traverse((o) => o.layers.set(0)); // the handles' objects all live on the default layer
    if (was.pole !== null) handles.selectPole(was.pole);
    else handles.select(was.target);
    live.ghost.root.visible = was.stepGhost;
    live.limits.root.visible = was.limits;
    this.controller.paused = false;
    this.controller.redraw();
  }

  /** Every frame in track mode: the clip or the headset moves the points (the gizmos move them as they are dragged), and the avatar solves. */
  private frame(seconds: number): void {
    const driver = this.driver,
      live = this.live;
    if (!driver || !live) return;
    try {
      if (this.clips?.playing != null) {
        this.clips.advance(seconds);
        this.clips.read(this.points);
      } else if (this.vr && this.xr) {
        const sample = this.vr.sample();
        if (sample) this.xr.input(sample, this.points); // before the calibration the avatar stands still
      }
      for (let k = 0; k < this.translated.length; k++) if (this.translated[k]) driver.carryFrame(k, this.points);
      this.translated.fill(false);
      this.outcome = driver.update(this.points.input);
    } catch (e) {
      this.failed(`track mode: ${errorText(e)}`);
      this.leave();
      return;
    }
    this.solves++;
    live.view.update(driver.poses(), driver.solver.bones, null);
    if (this.clips?.playing != null || this.vr) this.controller.stage.invalidate(); // the avatar moves by itself
    this.gizmos.sync(this.points, driver.solver.tips());
    this.onSolved();
  }
}

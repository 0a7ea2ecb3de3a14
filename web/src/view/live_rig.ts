// One loaded rig with everything made for it: the IK session (WebAssembly), the bone view, the
// step-mode ghost, the joint-limit sectors and the skinned mesh. dispose() frees all of it;
// create() frees what it made if any part fails, so a failed load leaks nothing. A rig the
// importer recognised as a humanoid switches between its anatomical limits and the file's own, and
// its hips float: they are a target of their own, and move when the body needs them to
// (floating_hips.ts, hips_target.ts).
import type { Object3D } from 'three';

import type { IkCoreModule } from '../ik/module.js';
import type { RigSpec } from '../ik/rig_arrays.js';
import { floatingHipsWithTarget, floatingRootUnit } from '../rig/humanoid/floating_hips.js';
import type { HumanoidMap } from '../rig/humanoid/humanoid_roles.js';
import { type DragTolerances, dragTolerances, restHeight, rigSize } from '../rig/tolerances.js';
import { LimitsView } from './limits_view.js';
import { RigView } from './rig_view.js';
import { HipsTarget } from '../live/hips_target.js';
import type { RigSource } from './rig_source.js';
import { IkSession } from '../live/session.js';

/** A humanoid's floating hips: its height at rest (rig units) and map. */
interface Floating {
  height: number;
  humanoid: HumanoidMap;
}

/**
 * The rig's spec with its humanoid limits when `humanoid` is set and it has them, else the file's;
 * `floating`: with the hips floating (their own limits and the root's move, floating_hips.ts) and
 * an effector after the file's.
 */
function limitedSpec(source: RigSource, humanoid: boolean, floating: Floating | null): RigSpec {
  const limits = humanoid ? source.humanoidLimits : undefined;
  const spec = limits ? { ...source.spec, lower: limits.lower, upper: limits.upper } : source.spec;
  return floating ? floatingHipsWithTarget(spec, floating.humanoid, floating.height) : spec;
}

/** Whether `source` floats: a recognised humanoid with hips, its height at rest; null for any other rig. */
function floatingOf(module: IkCoreModule, source: RigSource): Floating | null {
  const humanoid = source.humanoid;
  if (!humanoid || humanoid.bones.hips === undefined || !source.humanoidLimits) return null;
  const rest = new IkSession(module, source.spec);
  try {
    return { height: restHeight(rest.rig.boneTips(rest.restPose())), humanoid };
  } finally {
    rest.dispose();
  }
}

export class LiveRig {
  /** Bone selected for the limits readout, or null. */
  selectedBone: number | null = null;

  /** The hips target of a floating humanoid (hips_target.ts), or null: the root stays put. */
  readonly hipsTarget: HipsTarget | null;
  /** The solver option rootUnit for this rig (floating_hips.ts), 1 when it does not float. */
  readonly rootUnit: number;
  /** redraw()'s poses, 16 per bone (rewritten by each). */
  private poses = new Float64Array(0);

  private constructor(
    readonly source: RigSource,
    private readonly floating: Floating | null,
    /** Replaced (the old one disposed) when the limits switch. */
    public session: IkSession,
    readonly view: RigView,
    readonly ghost: RigView,
    readonly limits: LimitsView,
  ) {
    const map = floating?.humanoid;
    this.hipsTarget = map ? new HipsTarget(map) : null;
    this.rootUnit = floating ? floatingRootUnit(floating.height) : 1;
  }

  /**
   * Everything for `source`. `withMesh`: build the skinned mesh (when the file has one);
   * `humanoid`: start with the humanoid limits if the rig has them (the panel's default).
   */
  static async create(module: IkCoreModule, source: RigSource, withMesh = true, humanoid = true): Promise<LiveRig> {
    const made: { dispose(): void }[] = [];
    try {
      const floating = floatingOf(module, source);
      const session = new IkSession(module, limitedSpec(source, humanoid, floating));
      session.pinsFrames = source.humanoidLimits !== undefined;
      made.push(session);
      // A file saved posed opens posed: its rest is the bind pose, its nodes' pose the start
      // (gltf_rig.ts startAngles), the targets on its tips. R goes back to the rest.
      const start = source.gltf?.info.startAngles;
      if (start) {
        const angles = new Float64Array(session.rig.numAngles); // a floating root's move after the bones' angles: 0
        angles.set(start);
        session.angles.set(session.rig.project(angles));
        session.targets = session.tips();
      }
      const poses = session.poses();
      const view = new RigView(source.spec, poses);
      made.push(view);
      const ghost = new RigView(source.spec, poses, true);
      made.push(ghost);
      ghost.root.visible = false;
      const limits = new LimitsView(session.spec, view.size);
      made.push(limits);
      if (withMesh && source.makeMesh) view.attachMesh(await source.makeMesh());
      const live = new LiveRig(source, floating, session, view, ghost, limits);
      live.redraw();
      return live;
    } catch (e) {
      for (const m of made.reverse()) m.dispose();
      throw e;
    }
  }

  get name(): string {
    return this.source.name;
  }

  /** Whether the importer gave this rig humanoid limits to switch to. */
  get hasHumanoidLimits(): boolean {
    return this.source.humanoidLimits !== undefined;
  }

  /**
   * Switches to the humanoid limits (on) or the file's own (off): a new session with the same
   * effectors and targets, the pose clamped into the new limits. Solvers are made anew.
   */
  useHumanoidLimits(on: boolean): void {
    const spec = limitedSpec(this.source, on, this.floating);
    const next = this.session.withLimits(spec.lower, spec.upper);
    this.session.dispose();
    this.session = next;
    this.limits.useSpec(next.spec);
    this.redraw();
  }

  /** The rig's drag tolerances (a tip distance and a gradient tolerance, see tolerances.ts). */
  tolerances(): DragTolerances {
    const rig = this.session.rig;
    return dragTolerances(rigSize(rig.boneTips(new Float64Array(rig.numAngles))));
  }

  /** The objects to add to the scene. */
  get objects(): Object3D[] {
    return [this.view.root, this.ghost.root, this.limits.root];
  }

  /** Poses the view (bones, mesh, limits) from the session's current angles. */
  redraw(): void {
    const s = this.session;
    if (this.poses.length !== 16 * s.rig.numBones) this.poses = new Float64Array(16 * s.rig.numBones);
    this.view.update(s.poses(this.poses), s.effectors(), this.selectedBone);
    this.limits.select(this.selectedBone);
    this.limits.update(this.view, s.angles);
  }

  /** Shows `angles` as the ghost (the previous iterate), or hides it with null. */
  showGhost(angles: Float64Array | null): void {
    this.ghost.root.visible = angles !== null;
    if (angles) this.ghost.update(this.session.rig.poses(angles), new Int32Array(0), null);
  }

  dispose(): void {
    this.limits.dispose();
    this.ghost.dispose();
    this.view.dispose();
    this.session.dispose();
  }
}

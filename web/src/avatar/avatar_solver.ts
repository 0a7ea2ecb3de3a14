// A whole body from three tracked points: the head's and both hands' positions and
// orientations in, every joint out, on any recognised humanoid. The rig floats (its hips move,
// rig.h FloatingRoot), its feet stay planted, its knees take poles while it
// crouches, and each update() is one solve from the last pose, as the page solves a frame:
// Levenberg-Marquardt with strict priority, no restarts. It solves on the part of the rig
// the tracked and planted bones hang from (sub_rig.ts: no fingers, toes or eyes) and writes that
// pose into the whole rig's. No three.js and no DOM: a page, a widget or a Node script drives it.
// With three points the feet stand where they stood and step when the body leaves them
// (foot_steps.ts), the foot in the air giving way to everything else when a frame cannot meet
// every goal. With six (the hips and feet as well) the feet go where they are tracked, and the hips
// as near where they are tracked as the spine and legs reach (hips_reach.ts). The upper
// arms leave the T-pose in the plane their hands are asked to go in (swing_planes.ts). Each frame
// also asks for a share of the way back to a body's posture where the tracked points leave room:
// the spine untwisted, the hips facing the feet's way and over them, the knees bent as a squat's
// in a crouch (posture.ts).
import type { IkCoreModule } from '../ik/module.js';
import type { RigSpec } from '../ik/rig_arrays.js';
import { type PoleLimb, poleLimbs } from '../live/pole_limbs.js';
import { FRAME_DEFAULTS, FRAME_STEPS_BEFORE_BUDGET } from '../live/live_solve.js';
import { initialPole } from '../live/pole_placement.js';
import { floatingHipsSpec, floatingRootUnit, KNEES_STRAIGHT_DEG } from '../rig/humanoid/floating_hips.js';
import { IkRig } from '../ik/rig.js';
import { IkSession } from '../live/session.js';
import type { SolveOutcome, SolveSettings } from '../live/method_solver.js';
import type { HumanoidMap, HumanoidRole } from '../rig/humanoid/humanoid_roles.js';
import { dragTolerances, restHeight } from '../rig/tolerances.js';
import { FootSteps } from './foot_steps.js';
import { HipsReach } from './hips_reach.js';
import { Posture } from './posture.js';
import { scatterAngles, type SubRig, subHumanoid, subRig } from './sub_rig.js';
import { SEAT_SWING_DEG, seatSwingPlane } from './swing_planes.js';

/** A tracked pose: a position (rig units) and an orientation, a unit quaternion [x, y, z, w] of the bone's frame, rig coordinates. */
export interface TrackedPose {
  position: ArrayLike<number>;
  orientation: ArrayLike<number>;
}

/**
 * One frame of tracking: the head and both hands (3 points); with the hips and both feet, 6. A
 * foot not given stays planted where it last was; hips not given go where the body takes them.
 */
export interface AvatarInput {
  head: TrackedPose;
  leftHand: TrackedPose;
  rightHand: TrackedPose;
  hips?: TrackedPose;
  leftFoot?: TrackedPose;
  rightFoot?: TrackedPose;
}

/** The effectors' roles, in effector order (AvatarSolver.bones): the head and hands always tracked, the feet and hips when given. */
const ROLES: readonly HumanoidRole[] = ['head', 'leftHand', 'rightHand', 'leftFoot', 'rightFoot', 'hips'];
const INPUTS: ReadonlyArray<keyof AvatarInput> = ['head', 'leftHand', 'rightHand', 'leftFoot', 'rightFoot', 'hips'];
const HIPS = 5;

/**
 * The head this share of the height below where it stands makes a crouch: the knees take poles.
 * At 0.01 a nod or a lean took them too, and their soft rows slowed the turn in place (3 times the
 * time per frame, jitter 1.33 against 1.06); with no poles the stress clip's crouch bent a knee the
 * wrong way once.
 */
const CROUCH_SHARE = 0.03;
/**
 * The head higher than where it stands by more than this share of the height (half of δ): a frame
 * that misses with the heels down lifts them (tiptoe), as a crouch does. Standing, the head is as
 * high as the straight legs and spine take it: a head and hands tracked 0.3% of the height (5 mm on
 * the character) higher than the clip's missed every frame, each after 50 iterations, the hands and
 * feet pulled up to 140 δ off; on tiptoe 0.1-1.75%, 2.5% and 3% higher were on target on every
 * frame of idle. Not at the standing height itself: there a hand gizmo dragged faster than a frame
 * follows (track mode) missed a frame, lifted the heels and left the head 2.2 δ off.
 */
const TIPTOE_SHARE = 5e-4;

/**
 * Per-frame solve: at most the page's iterations (FRAME_DEFAULTS), so that a stream of inputs gives
 * the same poses on any machine; the time budget (ms) only guards against a runaway (a solve that
 * hits it depends on the machine's speed).
 */
const FRAME_BUDGET_MS = 100;
/**
 * lm's first damping of each frame. The default, 1, suits a target dragged far: here, where a
 * frame's targets are a few δ from the last pose, it cut the first step to a third of the way
 * (4-5 iterations a frame on reach_wave); 1e-3 takes 1-2, and on the project's clips gave the
 * lowest jitter of 1, 1e-2, 1e-3, 1e-4 and 1e-6.
 */
const FRAME_MU = 1e-3;
/**
 * Every frame takes at least one iteration: one that starts within the tolerance (the target
 * moved less than δ) is polished rather than left, or the frames alternate between no step and a
 * double one (idle: jitter ratio 1.46 with 0, 1.18 with 1).
 */
const FRAME_MIN_ITERATIONS = 1;
/**
 * Rejected steps after which a frame's lm iteration is stuck. The default, 30, suits a solve from
 * afar; in a frame one stuck iteration (at a stationary point, the closest point of a target out of
 * reach) cost 30 factorisations, 40% of all the factorisations over the clips. After 10, Nielsen's
 * rule has raised the damping 2^55-fold; at 5 (2^15) a hand gizmo dragged in track mode left the
 * head 2.6 δ off its target (tests/browser/track.test.ts).
 */
const FRAME_REJECTIONS = 10;
/**
 * Iterations a frame takes towards its knees' poles once the tracked points and planted feet are
 * on target (the solver option softIterations); the next frame goes on from there. Without a cap a
 * pole taking hold cost 7 iterations in one frame (the stress clip's slowest frames after its
 * jumps), with 2 it costs 4-5, every measure of the track experiment as it was but the stress
 * clip's jitter (1.056 -> 1.050); with 1 the stress clip's crouch fell behind and 7% of its frames
 * missed.
 */
const FRAME_SOFT_ITERATIONS = 2;
/**
 * The solves left a tracked point off its target this many frames in a row: the stance is out of
 * reach, and a foot steps (foot_steps.ts). One frame off (a target moved faster than a frame's
 * iterations follow: a gizmo dragged, a step landing) is not; stepping then walked the feet of an
 * avatar whose hands only swayed.
 */
const MISSED_FRAMES = 5;

export class AvatarSolver {
  /** The whole rig, floating (its hips move), its end effectors `bones`. */
  readonly rig: IkRig;
  /** The whole pose: 3 angles per bone (degrees), then the root's translation (rig units). Always this array. */
  readonly angles: Float64Array;
  /** The whole rig's indices of the head, the left and right hands, the left and right feet and the hips (the effectors' order). */
  readonly bones: Int32Array;
  /** The rig's height at rest, rig units; δ, the tip tolerance, is 0.1% of it. */
  readonly height: number;
  /** The bones the solves move (the tracked and planted ones and every bone above them), whole-rig indices in rig order; the others keep their angles. */
  readonly movingBones: Int32Array;
  /** The part of the rig the solves move, and its live state. */
  private readonly part: SubRig;
  private readonly session: IkSession;
  private readonly settings: SolveSettings;
  private readonly limbs: PoleLimb[];
  private readonly poleBones: number[];
  /** The head's height at rest (rig units). */
  private readonly standingHeadY: number;
  /** Where the untracked feet stand, and their steps. */
  private readonly steps: FootSteps;
  /** The hips' tip at rest, and where the floating root has taken it since (rig units; the hips' turn aside). */
  private readonly restHips: Float64Array;
  private readonly hips = new Float64Array(3);
  /** The heels are lifted: a crouch, or a head higher than it stands, could not be met with them down, and the head has not been between the two since. */
  private heelsLifted = false;
  /** Frames in a row whose solves left a tracked point off its target. */
  private missed = 0;
  /** The part's bone poses where placePoles() reads them (16 per bone, row-major). */
  private readonly poses: Float64Array;
  /** The part's left and right upper arms (whose swing planes seatSwingPlane() turns where their swing is 0, and while they leave the rest pose). */
  private readonly arms: Array<number | undefined>;
  /** Whether each upper arm is still leaving the rest pose: it has not swung SEAT_SWING_DEG since. */
  private readonly leaving = [true, true];
  /** Each frame's preferred move: a share of the way back to a body's posture (posture.ts). */
  private readonly posture: Posture;
  /** Tracked hips brought within reach of the tracked head and feet (hips_reach.ts). */
  private readonly hipsReach: HipsReach;
  /** Where the feet stand this frame (planted(), null while stepping), for the posture. */
  private readonly feetNow: Array<{ position: ArrayLike<number> } | null> = [null, null];

  /**
   * An avatar of `spec` (a humanoid's rig, its limits in place) mapped by `humanoid`, standing in
   * its rest pose. Throws an Error naming the roles missing for tracking.
   */
  constructor(module: IkCoreModule, spec: RigSpec, humanoid: HumanoidMap) {
    const bones = ROLES.map((role) => humanoid.bones[role]);
    const missing = ROLES.filter((_, i) => bones[i] === undefined);
    if (missing.length > 0) throw new Error(`the avatar needs these humanoid bones, not found: ${missing.join(', ')}`);
    this.bones = Int32Array.from(bones as number[]);
    const whole = new IkRig(module, { ...spec, effectors: this.bones });
    try {
      this.height = restHeight(whole.boneTips(whole.project(new Float64Array(whole.numAngles))));
    } finally {
      whole.dispose();
    }
    const h = this.height;
    this.rig = new IkRig(module, { ...floatingHipsSpec(spec, humanoid, h), effectors: this.bones });
    this.angles = this.rig.project(new Float64Array(this.rig.numAngles));
    this.part = subRig(this.rig.spec, Array.from(this.bones));
    this.movingBones = this.part.bones;
    try {
      this.session = new IkSession(module, this.part.spec);
    } catch (e) {
      this.rig.dispose();
      throw e;
    }
    const drag = dragTolerances(h);
    this.settings = {
      ...drag,
      maxIterations: FRAME_DEFAULTS.maxIterations,
      timeBudgetMs: FRAME_BUDGET_MS,
      restarts: 0,
      paperMode: false,
      strictPriority: true,
      lmInitialMu: FRAME_MU,
      minIterations: FRAME_MIN_ITERATIONS,
      stepsBeforeBudget: FRAME_STEPS_BEFORE_BUDGET,
      lmMaxRejections: FRAME_REJECTIONS,
      softIterations: FRAME_SOFT_ITERATIONS,
      rootUnit: floatingRootUnit(h),
    };
    const s = this.session;
    // Every effector holds its frame: the tracked ones the tracker's, the feet where they stand;
    // the hips have no goal until they are tracked.
    const rotations = s.tipRotations();
    for (let k = 0; k < bones.length; k++) s.setOrientationGoal(k, k !== HIPS, rotations.subarray(4 * k, 4 * k + 4));
    s.goals.setPosition(HIPS, false);
    // Poles on the knees only: they give a straight leg the way to bend when the hips go down. The
    // arms take none: a hand's position and frame leave its elbow one turn about the shoulder-wrist
    // line, which each frame's least change from the last keeps (a fixed pole pulled it off the
    // tracked hand on 30% of the frames of an arm motion).
    const partHumanoid = subHumanoid(this.part, humanoid);
    this.arms = [partHumanoid.bones.leftUpperArm, partHumanoid.bones.rightUpperArm];
    const knees = [partHumanoid.bones.leftLowerLeg, partHumanoid.bones.rightLowerLeg];
    this.limbs = poleLimbs(this.part.spec, s.effectors(), partHumanoid).filter((l) => knees.includes(l.bone));
    this.poleBones = this.limbs.map((l) => l.bone);
    this.poses = new Float64Array(16 * this.part.spec.parents.length);
    const tips = s.tips();
    this.standingHeadY = tips[1];
    const pose = (k: number) => ({
      position: Array.from(tips.subarray(3 * k, 3 * k + 3)),
      orientation: Array.from(rotations.subarray(4 * k, 4 * k + 4)),
    });
    this.restHips = tips.slice(3 * HIPS, 3 * HIPS + 3);
    this.steps = new FootSteps([pose(3), pose(4)], this.restHips, pose(0), h);
    this.posture = new Posture(s.rig, partHumanoid, s.angles);
    this.hipsReach = new HipsReach(s.rig, partHumanoid, s.angles);
    // The solver and its workspace now, by a solve that leaves the pose as it is: made by the first
    // update(), they doubled that frame's time (the solver), then made it its clip's slowest (the
    // workspace, sized at a solve's start: each clip's frame 0 took 4-7 times its median).
    s.trySolve('lm', this.settings);
  }

  /**
   * The head's, hands', feet's and hips' tips at the current pose, 3 per bone in `bones` order (rig
   * units): written into `out` when given (no allocation), else a new array.
   */
  tips(out?: Float64Array): Float64Array {
    return this.session.tips(out);
  }

  /** Their bone frames at the current pose, 4 per bone [x, y, z, w], rig coordinates (a new array). */
  tipRotations(): Float64Array {
    return this.session.tipRotations();
  }

  /**
   * Where each foot (left, right) is planted, its tip in rig units, or null while it steps; the
   * tracked feet of 6 points count as planted where they were given.
   */
  plantedFeet(): Array<number[] | null> {
    return [0, 1].map((k) => this.steps.planted(k)?.position ?? null);
  }

  /**
   * Solves one frame towards `input` from the last pose; the pose is the result. The outcome is
   * one record rewritten by every update (no new object per frame: copy what you keep).
   */
  update(input: AvatarInput): SolveOutcome {
    const s = this.session;
    let feet: readonly TrackedPose[] | null = null;
    if (input.leftFoot && input.rightFoot) this.steps.plant([input.leftFoot, input.rightFoot]);
    else {
      // The hips where the root's translation took them (their turn moves their tip a little: a
      // step decision does not need it, and this costs no forward kinematics).
      const root = s.angles.length - 3;
      for (let i = 0; i < 3; i++) this.hips[i] = this.restHips[i] + s.angles[root + i];
      feet = this.steps.update(input.head, this.hips, this.missed >= MISSED_FRAMES);
    }
    // An upper arm at its swing's 0 (the T-pose) swings the way its hand is asked to go; leaving the
    // rest pose, until its swing is SEAT_SWING_DEG (swing_planes.ts).
    for (let i = 0; i < 2; i++) {
      const arm = this.arms[i];
      if (arm === undefined) continue;
      if (Math.abs(s.angles[3 * arm + 1]) > SEAT_SWING_DEG) this.leaving[i] = false;
      seatSwingPlane(s.rig, s.angles, arm, 1 + i, (i ? input.rightHand : input.leftHand).position, this.leaving[i]);
    }
    const swinging = this.steps.stepping();
    s.yielding = -1;
    for (let k = 0; k < INPUTS.length; k++) {
      const pose = input[INPUTS[k]] ?? (k === 3 || k === 4 ? feet![k - 3] : undefined);
      if (k === HIPS) {
        s.goals.setPosition(HIPS, pose !== undefined);
        s.setOrientationGoal(HIPS, pose !== undefined, pose?.orientation);
      }
      if (!pose) continue;
      // Tracked hips and feet: the hips within the spine's and the legs' reach (hips_reach.ts).
      const at =
        k === HIPS && input.leftFoot && input.rightFoot
          ? this.hipsReach.clampHips(pose, input.head, input.leftFoot, input.rightFoot)
          : pose.position;
      for (let i = 0; i < 3; i++) s.targets[3 * k + i] = at[i];
      for (let i = 0; i < 4; i++) s.goals.rotations[4 * k + i] = pose.orientation[i];
    }
    // The knees take their poles only while the head is lower than it stands (a crouch) and a
    // knee is nearly straight: standing, their soft rows held the hard goals off target for whole
    // clips (idle: 12% of the frames on target with them, 100% without).
    const crouching = input.head.position[1] < this.standingHeadY - CROUCH_SHARE * this.height;
    if (crouching && this.kneesStraight()) this.placePoles();
    else if (s.goals.poleBones.length > 0) s.goals.setPoles([], []);
    // A crouch, or a head higher than it stands, keeps the heels down until a frame cannot be met
    // so: then the planted feet hold their places but not their frames, and that frame is solved
    // again; until the head is between the two (a crouch: until it is up).
    const threePoints = !input.leftFoot && !input.rightFoot;
    const tall = input.head.position[1] > this.standingHeadY + TIPTOE_SHARE * this.height;
    this.liftHeels((crouching || tall) && this.heelsLifted && threePoints);
    // The posture for the first solve only: the solves that follow a miss (a foot giving way, the
    // heels lifting) meet the goals as they can.
    this.feetNow[0] = this.steps.planted(0);
    this.feetNow[1] = this.steps.planted(1);
    const drop = crouching ? this.standingHeadY - input.head.position[1] : 0;
    s.preferMove('lm', this.posture.move(s.angles, this.feetNow, s.goals.rotations, input.hips !== undefined, drop));
    let outcome = s.solve('lm', this.settings);
    if (!outcome.reached && swinging >= 0) {
      // A foot in the air gives way first: the tracked points and the planted foot are held. Only
      // then: a solve in priority mode took 5-9 iterations where the goals as equals took 1-2
      // (the step frames were the slowest of turn_in_place and stress, p99 0.5-0.66 ms).
      s.yielding = 3 + swinging;
      outcome = s.solve('lm', this.settings);
    }
    if (!outcome.reached && (crouching || tall) && !this.heelsLifted && threePoints) {
      this.liftHeels(true);
      outcome = s.solve('lm', this.settings);
    }
    this.missed = outcome.reached ? 0 : this.missed + 1;
    scatterAngles(this.part, s.angles, this.angles);
    return outcome;
  }

  /**
   * Lifts the heels (the planted feet's orientation goals off: each foot keeps the ball of the foot,
   * its bone's tip, where it stands and may turn, as a person's heel rises) or puts them down (the
   * goals on, at the planted frames). Held flat, the ankles' 30 degrees stop a squat with the head
   * upright, straight down: the hips have to stay under the head and the shins lean past what the
   * ankles allow (tests/avatar: from a sixth of the height down the feet were pulled off their
   * places). Lifted at a fixed depth instead (the head 5% of the height down), the crouch clip's
   * heels rose where the clip keeps them flat: jitter 1.69 and arms and spine 1.8% of the height
   * from the clip's, against 1.32 and 0.8% when they rise only as needed.
   */
  private liftHeels(lifted: boolean): void {
    const goals = this.session.goals;
    this.heelsLifted = lifted;
    for (const k of [3, 4])
      if ((goals.orientation[k] === 1) === lifted)
        this.session.setOrientationGoal(k, !lifted, goals.rotations.subarray(4 * k, 4 * k + 4));
  }

  /** Whether a knee bends less than KNEES_STRAIGHT_DEG (its a1, degrees). */
  private kneesStraight(): boolean {
    const a = this.session.angles;
    return this.poleBones.some((b) => Math.abs(a[3 * b + 1]) < KNEES_STRAIGHT_DEG);
  }

  /** The knees' poles where they bend now (one leg length out the way each knee bends): they follow the body. */
  private placePoles(): void {
    const goals = this.session.goals,
      poses = this.session.poses(this.poses);
    if (goals.poleBones.length !== this.poleBones.length)
      goals.setPoles(this.poleBones, new Float64Array(3 * this.poleBones.length));
    this.limbs.forEach((limb, j) => goals.polePoints.set(initialPole(this.session.spec, poses, limb), 3 * j));
  }

  dispose(): void {
    this.session.dispose();
    this.rig.dispose();
  }
}

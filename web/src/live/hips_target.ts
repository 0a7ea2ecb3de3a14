// The hips target of a floating humanoid in drag mode (floating_hips.ts). The hips are
// an end effector, and what is dragged decides what the body carries:
// - the hips: they go where their target is dragged, the feet stay planted, and the head and hands
//   come along (their position goals are off; their frames stay pinned as in any drag);
// - the head: the hips are free (their goal off), the hands come along, the head keeps its frame,
//   the planted feet stay flat, the trunk is pulled towards its pose and the knees take poles while
//   straight, once the head is lower than where its drag began: a head pulled down squats (with
//   the hands held, a crouch of a quarter of the height is out of reach: the shoulders go down
//   further than the arms reach);
// - a hand, a foot or nothing: the hips stay where they are, as the other targets do (a foot
//   lifted with the hips free moved them 6 mm, and a posed file saved so reopened with that move
//   as its rest: a root joint's rest is its node's place, bind_pose.ts).
// A target whose goal is off follows its bone's tip after every solve, so it is drawn on the body
// and picks up from there when it is dragged next. No three.js and no DOM.
import { KNEES_STRAIGHT_DEG } from '../rig/humanoid/floating_hips.js';
import type { HumanoidMap } from '../rig/humanoid/humanoid_roles.js';
import { type PoleLimb, poleLimbs } from './pole_limbs.js';
import { initialPole } from './pole_placement.js';
import type { IkSession } from './session.js';
import type { SolveSettings } from './method_solver.js';

/**
 * The trunk's pull towards each frame's start while the head or the hips are dragged (the solver
 * option restWeight, restFromStart, on the hips, spine, chest, neck and head): the legs and the
 * hips' move take the motion first, the trunk what they cannot. A head pulled down by 25% of the
 * character's height then squats, the hips 23% lower and 0.17 m back, the knees over the toes and
 * the spine within 8 degrees of upright; without it the least change folded the trunk (hips tilted
 * 20, spine 25 + 25 degrees) over vertical shins, the hips 14% lower and 0.39 m back. At 10 the
 * spine bent 44 degrees again.
 */
const TRUNK_PULL = 1;
/**
 * The per-frame time budget while the head or the hips are dragged: none (0), the frame's
 * iteration cap alone stops its solve. The crouch is one solve's work: from the straight legs of
 * the rest pose a solve of 50 iterations bends the knees. Frames cut at a few iterations each
 * (a loaded machine, a quick drag) went another way and stayed there: the first steps bow the
 * neck and spine (a straight knee lowers nothing to first order), each frame's trunk pull holds
 * the bow it starts from, and a frame that starts on target keeps its start unless it gets back
 * on target. With 10 iterations a frame the head pulled down at once stayed bowed on its target
 * for 400 frames, each solving again; at 5 it did not move at all.
 */
const CARRY_BUDGET_MS = 0;
/** A drag of a hand, a foot or nothing carries no other effector. */
const NO_RIDERS: readonly number[] = [];
const TRUNK_ROLES = ['hips', 'spine', 'chest', 'upperChest', 'neck', 'head'] as const;

export class HipsTarget {
  /** The effectors this made free for a hips drag (bone indices), to give their goals back. */
  private freed: number[] = [];

  /** The head's orientation goal is this one's: set when a drag of the head began (keepHeadFrame). */
  private headFrame = false;
  /** The effector bone dragged at the last solve (-1: none). */
  private lastDragged = -1;
  /** The dragged target's height (rig units) when the drag of the head or the hips began. */
  private carriedFromY = 0;
  /** The knees' poles this one set for a crouch (the goals' poleBones array then), or null: the page's pole handles own the poles. */
  private kneePoles: Int32Array | null = null;
  readonly hips: number;
  private readonly head: number;
  private readonly hands: number[];
  /** What a hips drag carries: the head and the hands. */
  private readonly hipsRiders: number[];
  private readonly knees: number[];
  private readonly feet: number[];
  private readonly trunk: number[];
  /** The trunk's stiffness (Goals.stiffness), made for the rig's bone count on first use. */
  private trunkStiffness = new Float64Array(0);
  /** The head or the hips are the dragged target (beforeSolve). */
  private carrying = false;

  /** For a floating humanoid mapped by `humanoid` (it has hips). */
  constructor(private readonly humanoid: HumanoidMap) {
    const b = humanoid.bones;
    this.hips = b.hips!;
    this.head = b.head ?? -1;
    this.hands = [b.leftHand ?? -1, b.rightHand ?? -1];
    this.hipsRiders = [this.head, ...this.hands];
    this.knees = [b.leftLowerLeg ?? -1, b.rightLowerLeg ?? -1];
    this.feet = [b.leftFoot ?? -1, b.rightFoot ?? -1];
    this.trunk = TRUNK_ROLES.map((r) => b[r]).filter((bone): bone is number => bone !== undefined);
  }

  /**
   * Sets the goals for a per-frame solve that serves the drag of target `target` (an effector
   * index: the one dragged now, or whose drag the solves still finish), or of none (null): see the
   * file's header (the head and the hips carry the body only while they are dragged).
   */
  beforeSolve(session: IkSession, target: number | null): void {
    const effectors = session.effectors(),
      goals = session.goals;
    const k = effectors.indexOf(this.hips);
    if (k < 0) return;
    const dragged = target === null ? -1 : effectors[target];
    this.carrying = dragged === this.hips || dragged === this.head;
    goals.setPosition(k, dragged !== this.head);
    const riders = dragged === this.hips ? this.hipsRiders : dragged === this.head ? this.hands : NO_RIDERS;
    // The freed effectors no longer carried get their goals back; the others stay freed (in place: this runs every frame).
    let kept = 0;
    for (const bone of this.freed) {
      if (riders.includes(bone)) {
        this.freed[kept++] = bone;
        continue;
      }
      const j = effectors.indexOf(bone);
      if (j >= 0) goals.setPosition(j, true);
    }
    this.freed.length = kept;
    for (const bone of riders) {
      const j = effectors.indexOf(bone);
      if (j < 0 || goals.position[j] === 0) continue;
      goals.setPosition(j, false);
      this.freed.push(bone);
    }
    this.keepHeadFrame(session, dragged);
    const draggedY = this.carrying && target !== null ? session.targets[3 * target + 1] : 0;
    if (this.carrying && dragged !== this.lastDragged) this.carriedFromY = draggedY;
    this.lastDragged = dragged;
    if (this.carrying) {
      // The feet stay flat where they stand: the hips' move lets a leg keep both its foot's place
      // and frame (pinned_frames.ts counts the leg's own 5 angles only), and with the frame free a
      // crouch pivoted each foot about its tip, the ankle 7% of the height below the floor.
      for (const bone of this.feet) if (bone >= 0) goals.keepFrame(effectors.indexOf(bone));
    } else if (dragged >= 0) goals.keepFrame(k); // a hand or foot dragged: the hips keep their turn too, as a fixed root (a hand across the chest spun the body about them)
    this.placeKneePoles(session, this.carrying && draggedY < this.carriedFromY);
  }

  /**
   * The solve's settings while the head or the hips are dragged: no time budget (each frame's
   * solve runs to its end, see CARRY_BUDGET_MS) and the trunk's rest pull (TRUNK_PULL:
   * `settings.restWeight` and the session's stiffness). Call after the page's still body
   * (still_body.ts), which clears the rest pull on a humanoid. Allocates once per rig.
   */
  applyCarry(session: IkSession, settings: SolveSettings): void {
    if (!this.carrying) return;
    settings.timeBudgetMs = CARRY_BUDGET_MS;
    if (settings.paperMode) return;
    const n = session.spec.parents.length;
    if (this.trunkStiffness.length !== n) {
      this.trunkStiffness = new Float64Array(n);
      for (const b of this.trunk) this.trunkStiffness[b] = 1;
    }
    session.goals.stiffness = this.trunkStiffness;
    settings.restWeight = TRUNK_PULL;
    settings.restFromStart = true;
  }

  /**
   * The head dragged keeps the frame it had (an orientation goal, unless it has one of its own)
   * until the drag ends: a head pulled down then crouches the body rather than bowing it (with the
   * head free to turn, the least change folded the body at the hips over straight legs, the hips
   * 0.34 m back and 8.6% of the height down for a head 25% down).
   */
  private keepHeadFrame(session: IkSession, dragged: number): void {
    const k = session.effectors().indexOf(this.head);
    if (k < 0) return;
    if (dragged === this.head && this.lastDragged !== this.head && session.goals.orientation[k] === 0) {
      session.setOrientationGoal(k, true);
      this.headFrame = true;
    } else if (dragged !== this.head && this.headFrame) {
      if (session.goals.orientation[k] === 1) session.setOrientationGoal(k, false);
      this.headFrame = false;
    }
  }

  /**
   * The knees' poles where they bend now, while `crouching` (the head or the hips dragged lower
   * than where their drag began) and a knee is nearly straight; else none. The page's pole
   * handles, when on, are left as they are. Not before the target goes down: placed as soon as
   * the head was grabbed, their pull bent the still body's knees 4 degrees, and from there a head
   * pulled down 8% of the height in one frame bowed the body instead of crouching, and stayed so.
   */
  private placeKneePoles(session: IkSession, crouching: boolean): void {
    const goals = session.goals;
    if (goals.poleBones.length > 0 && goals.poleBones !== this.kneePoles) return;
    const a = session.angles;
    const want = crouching && this.knees.some((b) => b >= 0 && Math.abs(a[3 * b + 1]) < KNEES_STRAIGHT_DEG);
    if (!want) {
      if (this.kneePoles) goals.setPoles([], []);
      this.kneePoles = null;
      return;
    }
    const limbs: PoleLimb[] = poleLimbs(session.spec, session.effectors(), this.humanoid).filter((l) =>
      this.knees.includes(l.bone),
    );
    const poses = session.poses();
    const points = new Float64Array(3 * limbs.length);
    limbs.forEach((limb, j) => points.set(initialPole(session.spec, poses, limb), 3 * j));
    goals.setPoles(
      limbs.map((l) => l.bone),
      points,
    );
    this.kneePoles = limbs.length > 0 ? goals.poleBones : null;
  }

  /**
   * After a solve: the targets of the hips (while free) and of the effectors freed for a hips drag
   * move onto their tips `tips` (3 per effector, rig units, the pose just solved).
   */
  afterSolve(session: IkSession, tips: Float64Array): void {
    follow(session, tips, this.hips);
    for (const bone of this.freed) follow(session, tips, bone);
  }
}

/** The target of effector bone `bone`, when its position goal is off, moved onto its tip in `tips`. */
function follow(session: IkSession, tips: Float64Array, bone: number): void {
  const k = session.effectors().indexOf(bone),
    t = session.targets;
  if (k < 0 || session.goals.position[k] !== 0) return;
  for (let i = 3 * k; i < 3 * k + 3; i++) t[i] = tips[i];
}

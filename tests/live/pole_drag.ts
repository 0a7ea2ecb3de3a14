// Pole handles driven as the page drives them, for the Node tests: a project rig's session with a
// pole on every limb (pole_limbs.ts, placed by pole_placement.ts), the page's per-frame solve
// settings (lm with its first damping FRAME_LM_MU, the rig's drag tolerances, 50 iterations a
// frame, no restarts; the next frame goes on while the budget stopped the last one) and the
// measures the tests check: where a limb's joint points about its root-tip line, and how far the
// tips are from their targets. Rig units.
import { resolve } from 'node:path';

import type { IkCoreModule } from '../../web/src/ik/module.js';
import type { RigSpec } from '../../web/src/ik/rig_arrays.js';
import { budgetStop, FRAME_LM_MU } from '../../web/src/live/live_solve.js';
import { type PoleLimb, poleLimbs } from '../../web/src/live/pole_limbs.js';
import { initialPole, limbPoints } from '../../web/src/live/pole_placement.js';
import { IkSession } from '../../web/src/live/session.js';
import type { SolveSettings } from '../../web/src/live/method_solver.js';
import { add, cross, dot, norm, reject, scale, sub, unit, type Vec3 } from '../../web/src/rig/anatomy/anatomy_vec.js';
import { loadRigFromPath } from '../../web/src/rig/load_rig_node.js';
import { dragTolerances, rigSize } from '../../web/src/rig/tolerances.js';

/** A project rig on the page with its pole handles on. */
export interface PoleRig {
  session: IkSession;
  spec: RigSpec;
  limbs: PoleLimb[];
  /** The per-frame solve's settings (tipTolerance: the page's δ, 0.1% of the rig size). */
  settings: SolveSettings;
}

/**
 * Project rig `name` (web/public/models/NAME.glb) as the page shows it (humanoid limits when it
 * is recognised as one), at its rest pose, with every limb's pole where the page places it.
 * `budgetMs`: the per-frame time budget (the page has 3 ms; WebAssembly in Node is slower until it
 * is warm, so the tests give more and keep the page's 50 iterations a frame). Dispose the session.
 */
export async function poleRig(ik: IkCoreModule, name: string, budgetMs = 1000): Promise<PoleRig> {
  const rig = await loadRigFromPath(resolve(import.meta.dirname, `../../web/public/models/${name}.glb`));
  const session = new IkSession(ik, rig.spec);
  const tol = dragTolerances(rigSize(session.rig.boneTips(new Float64Array(session.rig.numAngles))));
  const settings: SolveSettings = {
    ...tol,
    maxIterations: 50,
    timeBudgetMs: budgetMs,
    restarts: 0,
    paperMode: false,
    lmInitialMu: FRAME_LM_MU,
  };
  const limbs = poleLimbs(rig.spec, session.effectors(), rig.gltf?.humanoid ?? null);
  const poses = session.poses();
  const points = new Float64Array(3 * limbs.length);
  limbs.forEach((limb, j) => points.set(initialPole(rig.spec, poses, limb), 3 * j));
  session.goals.setPoles(
    limbs.map((l) => l.bone),
    points,
  );
  return { session, spec: rig.spec, limbs, settings };
}

/** Frames of the page's solve until one ends for another reason than its budget (at most `frames`); returns the frames solved. */
export function settle(r: PoleRig, frames = 100): number {
  for (let f = 1; f <= frames; f++) if (!budgetStop(r.session.solve('lm', r.settings).stopReason)) return f;
  return frames;
}

/** Pole j's point (a view into the session's goals: writing it moves the pole). */
export function polePoint(r: PoleRig, j: number): Float64Array {
  return r.session.goals.polePoints.subarray(3 * j, 3 * j + 3);
}

/** Limb j's root (shoulder), joint (elbow) and tip (wrist) at the current pose. */
export function limb(r: PoleRig, j: number): { root: Vec3; joint: Vec3; tip: Vec3 } {
  return limbPoints(r.spec, r.session.poses(), r.limbs[j].bone);
}

/** Unit direction of `p` off limb j's root-tip line at the current pose (null on the line). */
export function across(r: PoleRig, j: number, p: ArrayLike<number>): Vec3 | null {
  const { root, tip } = limb(r, j);
  const axis = unit(sub(tip, root));
  return axis ? unit(reject(sub([p[0], p[1], p[2]], root), axis)) : null;
}

/** Angle, DEGREES, about limb j's root-tip line from its joint to point `p` (0: the joint points at p). */
export function swivelTo(r: PoleRig, j: number, p: ArrayLike<number>): number {
  const bend = across(r, j, limb(r, j).joint),
    pole = across(r, j, p);
  if (!bend || !pole) return NaN;
  return (Math.acos(Math.min(1, Math.max(-1, dot(bend, pole)))) * 180) / Math.PI;
}

/** `p` turned by `deg` DEGREES about limb j's root-tip line at the current pose. */
export function turnedAboutLimb(r: PoleRig, j: number, p: ArrayLike<number>, deg: number): Vec3 {
  const { root, tip } = limb(r, j);
  const axis = unit(sub(tip, root)) as Vec3;
  const d = sub([p[0], p[1], p[2]], root);
  const along = scale(axis, dot(d, axis)),
    off = sub(d, along);
  const c = Math.cos((deg * Math.PI) / 180),
    s = Math.sin((deg * Math.PI) / 180);
  return add(root, add(along, add(scale(off, c), scale(cross(axis, off), s))));
}

/** The largest distance from an end effector's tip to its target. */
export function worstTip(session: IkSession): number {
  const tips = session.tips(),
    t = session.targets;
  let worst = 0;
  for (let i = 0; i < tips.length; i += 3)
    worst = Math.max(worst, norm(sub([tips[i], tips[i + 1], tips[i + 2]], [t[i], t[i + 1], t[i + 2]])));
  return worst;
}

/** The end effector (index) whose chain holds limb j's lower bone, nearest it. */
export function limbEffector(r: PoleRig, j: number): number {
  const effectors = r.session.effectors(),
    parents = r.spec.parents;
  let best = -1,
    bestDepth = Infinity;
  effectors.forEach((e, k) => {
    let depth = 0;
    for (let b = e; b >= 0; b = parents[b], depth++)
      if (b === r.limbs[j].bone && depth < bestDepth) [best, bestDepth] = [k, depth];
  });
  return best;
}

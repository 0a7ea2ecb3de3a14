// The selected bone: the readout in the side column (its name, whether its tip is an end
// effector, for each XZX angle its value and limits in degrees, and its bend and twist from rest,
// all as text, never HTML), and
// making its tip an end effector or not. The selected target from the keyboard: Tab and Shift+Tab
// step through the targets, Esc lets the gizmo go (a click on a target selects it: handles.ts).
import type { RigSpec } from '../ik/rig_arrays.js';
import type { LiveController } from '../view/live_controller.js';
import type { LiveRig } from '../view/live_rig.js';
import type { Handles } from '../view/handles.js';
import { unbounded } from '../view/limits_view.js';

const AXES = ['X (twist)', 'Z (swing)', 'X (twist)'];

/** Text lines describing bone i's limits and current angles (degrees, 3 per bone). */
export function describeLimits(spec: RigSpec, i: number, angles: Float64Array): string[] {
  const lines: string[] = [];
  for (let k = 0; k < 3; k++) {
    const lo = spec.lower[3 * i + k],
      hi = spec.upper[3 * i + k],
      a = angles[3 * i + k];
    const range = unbounded(lo, hi)
      ? 'free'
      : lo === hi
        ? `fixed at ${lo.toFixed(1)}°`
        : `[${lo.toFixed(1)}°, ${hi.toFixed(1)}°]`;
    lines.push(`a${k} ${AXES[k]}: ${a.toFixed(1)}° in ${range}`);
  }
  return lines;
}

/**
 * Whether bone i of `spec` is a hinge: a0 moves, a1 and a2 are fixed at 0 (a URDF revolute or
 * continuous joint, docs/urdf.md): one angle about the bone's x axis.
 */
export function isHinge(spec: RigSpec, i: number): boolean {
  const fixedAtZero = (k: number): boolean => spec.lower[3 * i + k] === 0 && spec.upper[3 * i + k] === 0;
  return spec.lower[3 * i] < spec.upper[3 * i] && fixedAtZero(1) && fixedAtZero(2);
}

/** The readout line of hinge bone i (isHinge): its one angle (degrees) and its limits. */
export function describeHinge(spec: RigSpec, i: number, angles: Float64Array): string {
  const lo = spec.lower[3 * i],
    hi = spec.upper[3 * i];
  const range = unbounded(lo, hi) ? 'free' : `[${lo.toFixed(1)}°, ${hi.toFixed(1)}°]`;
  return `angle about its axis (a0): ${angles[3 * i].toFixed(1)}° in ${range}`;
}

/**
 * A joint's turn from its rest read as a bend and a twist (degrees), from its XZX angles a0, a1,
 * a2 (degrees): Rx(a0) Rz(a1) Rx(a2) = S Rx(a0 + a2) with S = Rx(a0) Rz(a1) Rx(-a0) a swing about
 * an axis across the bone, so the bone bends by |a1| (in the plane a0 picks) and twists about itself
 * by a0 + a2 (in (-180, 180]). Both are 0 at rest whatever a0 and a2 are: a humanoid's limits turn
 * a0's range to the joint's anatomical plane and a2's the other way, so a straight spine at rest
 * can read a0 = 75, a2 = -75.
 */
export function bendAndTwist(a0: number, a1: number, a2: number): { bend: number; twist: number } {
  const twist = a0 + a2 - 360 * Math.ceil((a0 + a2 - 180) / 360);
  return { bend: Math.abs(a1), twist };
}

/**
 * Writes `live`'s selected bone into `box` (no rig or no bone selected: the how-to line). For a rig
 * with humanoid limits to switch to, `humanoidLimits` says which limits are in use.
 */
export function showSelection(box: HTMLElement, live: LiveRig | null, humanoidLimits: boolean): void {
  const bone = live?.selectedBone ?? null;
  box.replaceChildren();
  if (!live || bone === null) {
    box.textContent =
      'Click a bone to make its tip an end effector or remove it (shift-click: show its joint limits only).';
    return;
  }
  const { spec, angles } = live.session;
  const title = document.createElement('strong');
  const effector = live.session.effectors().includes(bone) ? ' (end effector)' : '';
  title.textContent = `${spec.names[bone] || `bone ${bone}`}${effector}`;
  const list = document.createElement('ul');
  // A hinge (a robot's joint) has one angle: it neither bends nor twists as a bone of three does.
  const hinge = isHinge(spec, bone);
  for (const line of hinge ? [describeHinge(spec, bone, angles)] : describeLimits(spec, bone, angles)) {
    const li = document.createElement('li');
    li.textContent = line;
    list.append(li);
  }
  const turn = document.createElement('small');
  turn.className = 'from-rest';
  if (hinge) {
    turn.textContent = 'a hinge: one angle about its axis (a1, a2 fixed at 0)';
  } else {
    const { bend, twist } = bendAndTwist(angles[3 * bone], angles[3 * bone + 1], angles[3 * bone + 2]);
    turn.textContent = `from rest: bent ${bend.toFixed(1)}°, twisted ${twist.toFixed(1)}°`;
    turn.title =
      'a0 picks the plane the bone bends in, a1 bends it in that plane, a0 + a2 twists it about itself: at rest a0 and a2 cancel';
  }
  box.append(title, list, turn, document.createElement('br'));
  if (live.hasHumanoidLimits) {
    const source = document.createElement('small');
    source.textContent = `limits: ${humanoidLimits ? 'humanoid (anatomical)' : 'the file’s (humanoid limits off)'}`;
    box.append(source);
  }
}

/**
 * Bone `bone`'s tip becomes an end effector, or stops being one, on the rig `controller` shows; a
 * new effector's target takes the gizmo, and the solve goes on. False, and nothing changes, for
 * the rig's last end effector.
 */
export function toggleEffector(controller: LiveController, bone: number): boolean {
  const list = Array.from(controller.live?.session.effectors() ?? []);
  const at = list.indexOf(bone);
  if (at >= 0 && list.length === 1) return false;
  if (at >= 0) list.splice(at, 1);
  else list.push(bone);
  controller.setEffectors(list, at < 0 ? list.length - 1 : undefined);
  controller.invalidate();
  return true;
}

/**
 * The gizmo takes the target after (step 1) or before (step -1) the one it holds, in effector
 * order, wrapping; holding none (or a pole handle), the first or the last. No targets: nothing.
 */
export function stepTarget(handles: Handles, step: 1 | -1): void {
  const n = handles.count,
    k = handles.selected;
  if (n === 0) return;
  handles.select(k === null ? (step > 0 ? 0 : n - 1) : (k + step + n) % n);
}

/** The gizmo lets go: no target (and no pole handle) is selected. */
export function deselectTarget(handles: Handles): void {
  if (handles.selected !== null || handles.selectedPole !== null) handles.select(null);
}

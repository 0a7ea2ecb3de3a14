// Clicks and taps on the 3D view: a pointer that goes down and up without moving (and not on the
// gizmo) is a click; it is reported with a ray through the pointer. Works for mouse, pen and touch.
// A press on something a click would select (a target the gizmo does not hold) can be held back
// from the gizmo until it is seen to be a click or a drag (holdClickablePresses).
import { type Camera, MathUtils, PerspectiveCamera, Raycaster, Vector2 } from 'three';

export interface ViewClick {
  raycaster: Raycaster;
  shiftKey: boolean;
  /**
   * A CSS pixel's width at unit distance from the camera along the ray (world units per world
   * unit): a tolerance of k pixels at distance t along the ray is k * pixelSlope * t. 0 when the
   * camera is not a perspective one.
   */
  pixelSlope: number;
}

export function listenForClicks(
  canvas: HTMLCanvasElement,
  camera: Camera,
  isBusy: () => boolean,
  onClick: (click: ViewClick) => void,
): () => void {
  const raycaster = new Raycaster();
  const ndc = new Vector2();
  let down: { x: number; y: number; t: number; id: number } | null = null;
  const onDown = (e: PointerEvent): void => {
    down = e.isPrimary && !isBusy() ? { x: e.clientX, y: e.clientY, t: performance.now(), id: e.pointerId } : null;
  };
  const onUp = (e: PointerEvent): void => {
    const d = down;
    down = null;
    if (!d || d.id !== e.pointerId || isBusy()) return;
    if (Math.hypot(e.clientX - d.x, e.clientY - d.y) > clickSlop(e.pointerType) || performance.now() - d.t > 600)
      return;
    const rect = canvas.getBoundingClientRect();
    ndc.set(((e.clientX - rect.left) / rect.width) * 2 - 1, -((e.clientY - rect.top) / rect.height) * 2 + 1);
    raycaster.setFromCamera(ndc, camera);
    onClick({ raycaster, shiftKey: e.shiftKey, pixelSlope: pixelSlope(camera, rect.height) });
  };
  canvas.addEventListener('pointerdown', onDown);
  window.addEventListener('pointerup', onUp);
  return () => {
    canvas.removeEventListener('pointerdown', onDown);
    window.removeEventListener('pointerup', onUp);
  };
}

/** ViewClick.pixelSlope of `camera` drawn `height` CSS pixels high. */
function pixelSlope(camera: Camera, height: number): number {
  if (!(camera instanceof PerspectiveCamera) || !(height > 0)) return 0;
  return (2 * Math.tan((MathUtils.DEG2RAD * camera.getEffectiveFOV()) / 2)) / height;
}

/** How far (CSS pixels) a pointer may move between down and up and still click. */
export function clickSlop(pointerType: string): number {
  return pointerType === 'touch' ? 10 : 4;
}

/** Presses this module replays to the view's controls: they are not held again. */
const replayed = new WeakSet<Event>();

/**
 * Presses that land on something a click would select are held back from the view's other
 * pointer listeners (the gizmo, the orbit, listenForClicks) until the pointer shows what they are:
 * released within the click slop, they are a click and `claim`'s action runs; moved farther, they
 * are a drag and the press is replayed where it began, so the gizmo (or the orbit) takes it as it
 * would have. `claim(raycaster)` is asked at each primary pointer-down, before those listeners:
 * the action a click there runs, or null to leave the press alone. Returns a function that stops it.
 */
export function holdClickablePresses(
  canvas: HTMLCanvasElement,
  camera: Camera,
  claim: (raycaster: Raycaster) => (() => void) | null,
): () => void {
  const raycaster = new Raycaster();
  const ndc = new Vector2();
  let held: { down: PointerEvent; action: () => void } | null = null;

  const release = (): void => {
    held = null;
    window.removeEventListener('pointermove', onMove, true);
    window.removeEventListener('pointerup', onUp, true);
    window.removeEventListener('pointercancel', onCancel, true);
  };
  const replay = (): void => {
    const d = held?.down;
    release();
    if (!d) return;
    const again = new PointerEvent('pointerdown', {
      bubbles: true,
      cancelable: true,
      composed: true,
      pointerId: d.pointerId,
      pointerType: d.pointerType,
      isPrimary: d.isPrimary,
      clientX: d.clientX,
      clientY: d.clientY,
      screenX: d.screenX,
      screenY: d.screenY,
      button: d.button,
      buttons: d.buttons,
      pressure: d.pressure,
      width: d.width,
      height: d.height,
      shiftKey: d.shiftKey,
      ctrlKey: d.ctrlKey,
      altKey: d.altKey,
      metaKey: d.metaKey,
    });
    replayed.add(again);
    canvas.dispatchEvent(again);
  };
  const onDown = (e: PointerEvent): void => {
    if (replayed.has(e)) return;
    if (held) {
      // Another finger: the held press was the start of a gesture, not a click.
      if (e.pointerId !== held.down.pointerId) replay();
      return;
    }
    if (!e.isPrimary || e.button !== 0) return;
    const rect = canvas.getBoundingClientRect();
    ndc.set(((e.clientX - rect.left) / rect.width) * 2 - 1, -((e.clientY - rect.top) / rect.height) * 2 + 1);
    raycaster.setFromCamera(ndc, camera);
    const action = claim(raycaster);
    if (!action) return;
    e.stopImmediatePropagation();
    held = { down: e, action };
    window.addEventListener('pointermove', onMove, true);
    window.addEventListener('pointerup', onUp, true);
    window.addEventListener('pointercancel', onCancel, true);
  };
  const onMove = (e: PointerEvent): void => {
    const d = held?.down;
    if (!d || e.pointerId !== d.pointerId) return;
    if (Math.hypot(e.clientX - d.clientX, e.clientY - d.clientY) > clickSlop(d.pointerType)) replay(); // this move then reaches the control that took the press
  };
  const onUp = (e: PointerEvent): void => {
    const h = held;
    if (!h || e.pointerId !== h.down.pointerId) return;
    release();
    if (Math.hypot(e.clientX - h.down.clientX, e.clientY - h.down.clientY) <= clickSlop(h.down.pointerType)) h.action();
  };
  const onCancel = (e: PointerEvent): void => {
    if (held && e.pointerId === held.down.pointerId) release();
  };
  canvas.addEventListener('pointerdown', onDown, true);
  return () => {
    release();
    canvas.removeEventListener('pointerdown', onDown, true);
  };
}

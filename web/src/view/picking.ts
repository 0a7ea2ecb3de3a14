// Clicks and taps on the 3D view: a pointer that goes down and up without moving (and not on the
// gizmo) is a click; it is reported with a ray through the pointer. Works for mouse, pen and touch.
import { type Camera, Raycaster, Vector2 } from 'three';

export interface ViewClick {
  raycaster: Raycaster;
  shiftKey: boolean;
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
    const slop = e.pointerType === 'touch' ? 10 : 4;
    if (Math.hypot(e.clientX - d.x, e.clientY - d.y) > slop || performance.now() - d.t > 600) return;
    const rect = canvas.getBoundingClientRect();
    ndc.set(((e.clientX - rect.left) / rect.width) * 2 - 1, -((e.clientY - rect.top) / rect.height) * 2 + 1);
    raycaster.setFromCamera(ndc, camera);
    onClick({ raycaster, shiftKey: e.shiftKey });
  };
  canvas.addEventListener('pointerdown', onDown);
  window.addEventListener('pointerup', onUp);
  return () => {
    canvas.removeEventListener('pointerdown', onDown);
    window.removeEventListener('pointerup', onUp);
  };
}

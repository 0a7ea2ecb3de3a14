// Makes a loaded model a faint, see-through copy of itself (track mode's ghost of a clip): each
// material transparent at a given opacity and tinted towards the page's ghost blue, drawn after
// the solid model without writing depth, so what stands behind it still shows.
import { Color, type Material, type Mesh, type Object3D } from 'three';

/** The step-mode ghost's colour (rig_view.ts), which faint models lean towards. */
const GHOST_TINT = new Color(0x8fe3ff);
/** How far a material's own colour moves towards GHOST_TINT (0: its own, 1: the tint). */
const TINT_SHARE = 0.5;

/** Makes every mesh under `root` faint: materials see-through at `opacity` (0..1), tinted, drawn late; meshes never culled (a skinned mesh's bounds do not follow its pose). */
export function makeFaint(root: Object3D, opacity: number): void {
  const done = new Set<Material>();
  root.traverse((o) => {
    const mesh = o as Mesh;
    if (!mesh.isMesh) return;
    mesh.renderOrder = 8;
    mesh.frustumCulled = false;
    for (const m of Array.isArray(mesh.material) ? mesh.material : [mesh.material]) {
      if (done.has(m)) continue;
      done.add(m);
      m.transparent = true;
      m.opacity = opacity;
      m.depthWrite = false;
      const color = (m as Material & { color?: Color }).color;
      if (color instanceof Color) color.lerp(GHOST_TINT, TINT_SHARE);
    }
  });
}

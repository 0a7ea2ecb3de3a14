// Frees the GPU-side resources of a three.js subtree: geometries, materials, their textures and
// skinned meshes' skeletons. For objects made from a file (a glTF scene).
import { type Material, type Object3D, SkinnedMesh, Texture } from 'three';

function disposeMaterial(m: Material, seen: Set<object>): void {
  if (seen.has(m)) return;
  seen.add(m);
  for (const value of Object.values(m)) {
    if (value instanceof Texture && !seen.has(value)) {
      seen.add(value);
      value.dispose();
    }
  }
  m.dispose();
}

export function disposeObject3D(root: Object3D): void {
  const seen = new Set<object>();
  root.traverse((o) => {
    const mesh = o as Object3D & { geometry?: { dispose(): void }; material?: Material | Material[] };
    if (mesh.geometry && !seen.has(mesh.geometry)) {
      seen.add(mesh.geometry);
      mesh.geometry.dispose();
    }
    if (mesh.material)
      for (const m of Array.isArray(mesh.material) ? mesh.material : [mesh.material]) disposeMaterial(m, seen);
    if (o instanceof SkinnedMesh && !seen.has(o.skeleton)) {
      seen.add(o.skeleton);
      o.skeleton.dispose();
    }
  });
  root.removeFromParent();
}

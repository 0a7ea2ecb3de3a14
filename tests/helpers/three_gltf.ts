// three.js helpers for the rig tests: GLTFLoader in Node, skinned vertex positions.
import { Vector3, type Bone, type Object3D, type SkinnedMesh } from 'three';
import { GLTFLoader, type GLTF } from 'three/examples/jsm/loaders/GLTFLoader.js';

/** Parses .glb bytes with three.js's GLTFLoader (works in Node for files without images). */
export async function parseGlb(bytes: Uint8Array): Promise<GLTF> {
  const ab = bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength) as ArrayBuffer;
  return new GLTFLoader().parseAsync(ab, '');
}

export function skinnedMeshes(root: Object3D): SkinnedMesh[] {
  const out: SkinnedMesh[] = [];
  root.traverse((o) => {
    if ((o as SkinnedMesh).isSkinnedMesh) out.push(o as SkinnedMesh);
  });
  return out;
}

/** World position of vertex v of a skinned mesh as three.js skins it (call updateMatrixWorld first). */
export function skinnedVertexWorld(mesh: SkinnedMesh, v: number): Vector3 {
  return mesh.getVertexPosition(v, new Vector3()).applyMatrix4(mesh.matrixWorld);
}

/** The (rig bone, weight) pairs of vertex v, mapping the mesh's skeleton bones to rig bones. */
export function vertexInfluences(mesh: SkinnedMesh, v: number, bones: Bone[]): [number, number][] {
  const idx = mesh.geometry.getAttribute('skinIndex'),
    wt = mesh.geometry.getAttribute('skinWeight');
  const out: [number, number][] = [];
  for (let k = 0; k < 4; k++) {
    const w = wt.getComponent(v, k);
    if (w === 0) continue;
    const bone = bones.indexOf(mesh.skeleton.bones[idx.getComponent(v, k)]);
    if (bone < 0) throw new Error(`vertex ${v} follows a bone that is not in the rig`);
    out.push([bone, w]);
  }
  return out;
}

/** Applies a row-major 4x4 (16 numbers at offset) to a point. */
export function applyRowMajor(m: ArrayLike<number>, offset: number, p: Vector3): Vector3 {
  const o = offset;
  return new Vector3(
    m[o] * p.x + m[o + 1] * p.y + m[o + 2] * p.z + m[o + 3],
    m[o + 4] * p.x + m[o + 5] * p.y + m[o + 6] * p.z + m[o + 7],
    m[o + 8] * p.x + m[o + 9] * p.y + m[o + 10] * p.z + m[o + 11],
  );
}

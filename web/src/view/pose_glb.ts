// Pose export: the original glTF file with every bone's node set to its solved local transform,
// written as one .glb. The file is read and written with glTF-Transform (never by hand), so meshes,
// skins, materials, animations, extras (extras.ik) and every other node are kept. The local matrix
// of bone i is the one PoseWriter gives three.js (pose_writer.ts):
//   local_i = restLocal_i * restWorld_i^-1 * (T_p^-1 T_i) * restWorld_i
// written as translation, rotation quaternion and scale. A component the pose leaves unchanged (to
// 1e-9 relative) keeps the file's own numbers, so zero angles give back the file's transforms. A
// node the file gave as `matrix` is written as TRS, as glTF-Transform always does. Files with glTF
// extensions glTF-Transform knows are carried over; compressed geometry (Draco, meshopt) and
// extensions it does not know (VRM's, for one) are refused rather than silently dropped.
import { Logger, WebIO, type Document, type GLTF } from '@gltf-transform/core';
import { ALL_EXTENSIONS } from '@gltf-transform/extensions';

import type { RigSpec } from '../ik/rig_arrays.js';
import { failIn } from '../rig/rig_format_error.js';
import { parseGltfContainer, type SiblingReader } from '../rig/gltf/gltf_file.js';
import type { GltfRigInfo } from '../rig/gltf/gltf_rig.js';
import { det3, fromTRS, invertAffine, maxAbs, maxAbsDiff, multiply, polarRotation, type Mat4 } from '../rig/mat4.js';
import { fromRotation, type Quat } from '../rig/quat.js';

/** Relative agreement within which a decomposed component keeps the file's own value. */
export const KEEP_FILE_TOLERANCE = 1e-9;

/**
 * Largest difference between the written TRS and the posed local matrix, relative to the matrix's
 * largest linear entry (translation: to its largest component). Files store quaternions as float32
 * or to about 9 digits, so their rest matrices are orthonormal only to 1e-7..1e-10, and a rotation
 * conjugated by them keeps a shear of that size that no TRS carries (knight.glb: 1.1e-9). A real
 * non-uniform scale under a rotation shears far more (1% of scale difference: 1e-2).
 */
export const TRS_REBUILD_TOLERANCE = 1e-6;

type Vec3 = [number, number, number];

/** A local transform as glTF stores it: translation, unit quaternion (x, y, z, w), scale. */
export interface NodeTRS {
  translation: Vec3;
  rotation: Quat;
  scale: Vec3;
}

const close = (a: ArrayLike<number>, b: ArrayLike<number>): boolean =>
  maxAbsDiff(a, b) <= KEEP_FILE_TOLERANCE * Math.max(maxAbs(a), maxAbs(b));

/**
 * The TRS of the row-major affine `m` (a node's local matrix, 16 numbers), keeping each component
 * of `file` (the node's own TRS) that agrees with it to KEEP_FILE_TOLERANCE relative; the rotation
 * is the polar factor (the nearest rotation). `error` is the largest relative difference of the
 * rebuilt matrix from `m` (see TRS_REBUILD_TOLERANCE). Returns null when that error passes
 * TRS_REBUILD_TOLERANCE (shear: a non-uniform scale under a rotation) or the matrix is singular.
 */
export function decomposeLocal(m: ArrayLike<number>, file: NodeTRS): (NodeTRS & { error: number }) | null {
  const t: Vec3 = [m[3], m[7], m[11]];
  const columnNorm = (c: number): number => Math.hypot(m[c], m[4 + c], m[8 + c]);
  const norms: Vec3 = [columnNorm(0), columnNorm(1), columnNorm(2)];
  if (!(norms[0] > 0 && norms[1] > 0 && norms[2] > 0)) return null;
  const absFile = file.scale.map(Math.abs);
  let s: Vec3;
  if (close(norms, absFile)) s = [...file.scale];
  else {
    s = norms.map((n, k) => (file.scale[k] < 0 ? -n : n)) as Vec3;
  }
  if (det3(m) * s[0] * s[1] * s[2] < 0) s[0] = -s[0]; // the rotation must have determinant +1
  const unmirrored = Float64Array.from(m, (v, k) => (k < 12 && s[k % 4] < 0 ? -v : v)); // A * diag(sign s)
  let q = fromRotation(polarRotation(unmirrored));
  const f = file.rotation;
  const fn = Math.hypot(...f);
  const fileUnit = fn > 0 ? (f.map((v) => v / fn) as Quat) : f;
  if (close(q, fileUnit)) q = [...f];
  else if (
    close(
      q.map((v) => -v),
      fileUnit,
    )
  )
    q = [...f];
  const translation = close(t, file.translation) ? ([...file.translation] as Vec3) : t;
  const back = fromTRS(translation, q, s);
  const linear = (a: ArrayLike<number>): number[] => [a[0], a[1], a[2], a[4], a[5], a[6], a[8], a[9], a[10]];
  const linearError = maxAbsDiff(linear(back), linear(m)) / maxAbs(linear(m));
  const translationError = maxAbsDiff([back[3], back[7], back[11]], t) / (maxAbs(t) || 1);
  const error = Math.max(linearError, translationError);
  return error <= TRS_REBUILD_TOLERANCE ? { translation, rotation: q, scale: s, error } : null;
}

/**
 * The posed local matrix of every bone's node (16 per bone, row-major, relative to the glTF parent
 * node, scene units): restLocal_i * restWorld_i^-1 * (T_p^-1 T_i) * restWorld_i. `poses` is
 * IkRig.poses(angles) (16 per bone, row-major T_i).
 */
export function posedLocalMatrices(info: GltfRigInfo, spec: RigSpec, poses: ArrayLike<number>): Float64Array {
  const n = spec.parents.length;
  if (info.boneNodes.length !== n)
    throw new Error(`posed locals: ${info.boneNodes.length} glTF joints for a rig of ${n} bones`);
  if (poses.length !== 16 * n) throw new Error(`posed locals: poses has ${poses.length} values, expected ${16 * n}`);
  for (let k = 0; k < poses.length; k++)
    if (!Number.isFinite(poses[k]))
      throw new Error(`posed locals: poses[${k}] (bone ${spec.names[k >> 4] ?? k >> 4}) is not finite`);
  const out = new Float64Array(16 * n);
  const block = (a: ArrayLike<number>, i: number): Float64Array =>
    Float64Array.from({ length: 16 }, (_, k) => a[16 * i + k]);
  for (let i = 0; i < n; i++) {
    const W = block(info.restWorld, i);
    const Winv = invertAffine(W);
    if (!Winv) throw new Error(`posed locals: bone ${spec.names[i]}: rest world matrix is singular`);
    let rel: Mat4 = block(poses, i);
    const p = spec.parents[i];
    if (p >= 0) {
      const Tp = invertAffine(block(poses, p));
      if (!Tp) throw new Error(`posed locals: bone ${spec.names[p]}: pose matrix is singular`);
      rel = multiply(Tp, rel);
    }
    out.set(multiply(multiply(block(info.restLocal, i), Winv), multiply(rel, W)), 16 * i);
  }
  return out;
}

/** Extensions that store geometry compressed: reading them needs a decoder and writing an encoder. */
const COMPRESSION = new Set(['KHR_draco_mesh_compression', 'EXT_meshopt_compression']);
/** The extensions pose export carries over (glTF-Transform's own: materials, lights, textures, ...). */
const CARRIED = new Set(ALL_EXTENSIONS.map((e) => e.EXTENSION_NAME).filter((name) => !COMPRESSION.has(name)));

/** The glTF-Transform reader/writer used for pose export (warnings of glTF-Transform kept quiet). */
function gltfIO(): WebIO {
  return new WebIO()
    .setLogger(new Logger(Logger.Verbosity.ERROR))
    .registerExtensions(ALL_EXTENSIONS.filter((e) => CARRIED.has(e.EXTENSION_NAME)));
}

/** Reads `bytes` (.glb, or .gltf with side files through readSibling or data: URIs) into a Document. */
async function readDocument(bytes: Uint8Array, fileName: string, readSibling?: SiblingReader): Promise<Document> {
  const container = parseGltfContainer(bytes, fileName);
  const json = container.json;
  const used = json.extensionsUsed;
  const lost = Array.isArray(used) ? used.map(String).filter((name) => !CARRIED.has(name)) : [];
  if (lost.length > 0)
    failIn(
      fileName,
      `pose export cannot carry the extension(s) ${lost.join(', ')} (compressed geometry or an extension glTF-Transform does not know), which would be lost`,
    );
  const io = gltfIO();
  if (container.bin !== undefined || fileName.toLowerCase().endsWith('.glb')) return io.readBinary(bytes);
  const resources: Record<string, Uint8Array<ArrayBuffer>> = {};
  for (const list of [json.buffers, json.images]) {
    if (!Array.isArray(list)) continue;
    for (const item of list as { uri?: unknown }[]) {
      const uri = item?.uri;
      if (typeof uri !== 'string' || uri.startsWith('data:') || uri in resources) continue;
      if (!readSibling) failIn(fileName, `the file refers to "${uri}", and no reader for side files was given`);
      resources[uri] = new Uint8Array(await readSibling(decodeURIComponent(uri)));
    }
  }
  return io.readJSON({ json: json as unknown as GLTF.IGLTF, resources });
}

/**
 * The original glTF file `original` (named `fileName`; a .glb, or a .gltf whose side files
 * `readSibling` reads) with each rig bone's node posed by `poses` (IkRig.poses(angles): 16 per
 * bone, row-major T_i, scene units), written as one .glb. `info` and `spec` are the import of
 * that same file (loadRig). Everything else in the file is kept; .gltf side buffers are merged
 * into the GLB's one buffer and images embedded. Throws an Error naming the file for a file that
 * does not match `info`, uses glTF extensions, or whose posed local matrix has no exact TRS.
 */
export async function posedGlb(
  original: Uint8Array,
  fileName: string,
  info: GltfRigInfo,
  spec: RigSpec,
  poses: ArrayLike<number>,
  readSibling?: SiblingReader,
): Promise<Uint8Array> {
  const locals = posedLocalMatrices(info, spec, poses);
  const doc = await readDocument(original, fileName, readSibling);
  const root = doc.getRoot();
  const nodes = root.listNodes();
  info.boneNodes.forEach((index, i) => {
    const node = nodes[index];
    if (!node || node.getName() !== info.nodeNames[i])
      throw new Error(
        `${fileName}: glTF node ${index} is not the joint "${info.nodeNames[i]}" of bone ${spec.names[i]}: the rig was read from another file`,
      );
    const file: NodeTRS = { translation: node.getTranslation(), rotation: node.getRotation(), scale: node.getScale() };
    const trs = decomposeLocal(locals.subarray(16 * i, 16 * i + 16), file);
    if (!trs)
      throw new Error(
        `${fileName}: bone ${spec.names[i]}: its posed local matrix is no translation * rotation * scale (a non-uniform scale under a rotation); glTF cannot store it`,
      );
    node.setTranslation(trs.translation).setRotation(trs.rotation).setScale(trs.scale);
  });
  // A GLB holds one buffer: move every accessor onto the first and drop the others.
  const buffers = root.listBuffers();
  if (buffers.length > 0) {
    const first = buffers[0].setURI('');
    root.listAccessors().forEach((a) => a.setBuffer(first));
    buffers.slice(1).forEach((b) => b.dispose());
  }
  return gltfIO().writeBinary(doc);
}

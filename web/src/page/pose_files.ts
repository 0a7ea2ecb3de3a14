// Saving and loading poses from the page: the posed character as .glb (the rig's own file with the
// solved joints written into its nodes, pose_glb.ts), the pose as JSON (angles and targets keyed by
// bone name, or "#index" for bones without a name of their own such as an A7 rig's, pose_json.ts),
// and a JSON pose file read back as a PoseState for the rig shown (its size checked before reading).
import type { LiveRig } from '../view/live_rig.js';
import { poseWithOrientations, type PoseState } from '../live/pose_state.js';
import { MAX_POSE_CHARS, PoseFormatError, poseFromJson, poseToJson } from '../rig/pose_json.js';

/** Why the rig shown cannot be saved as a posed .glb, or null when it can. */
export function glbExportProblem(live: LiveRig | null): string | null {
  if (!live) return 'no rig is loaded';
  if (!live.source.gltf)
    return `${live.name} is ${live.source.urdf ? 'a URDF robot' : 'an A7 rig'} (bones only): there is no glTF file to pose; save the pose as .json`;
  return null;
}

/** The rig's name as a file name stem (letters, digits, dot, dash and underscore kept). */
export function fileStem(name: string): string {
  return name.replace(/\.(glb|gltf|json)$/i, '').replace(/[^\w.-]+/g, '_') || 'rig';
}

/**
 * The posed .glb of the rig shown at its current pose (glTF-Transform is loaded on first use).
 * Throws an Error naming the problem.
 */
export async function posedGlbBytes(live: LiveRig): Promise<Uint8Array> {
  const file = live.source.gltf;
  if (!file) throw new Error(glbExportProblem(live) ?? 'no glTF to pose');
  const { posedGlb } = await import('../view/pose_glb.js');
  return posedGlb(file.bytes, file.fileName, file.info, file.spec, live.session.poses(), file.readSibling);
}

/** The pose file (ik-pose JSON text) of the rig shown: angles, effectors, targets and orientation goals. */
export function poseJsonText(live: LiveRig): string {
  const { session } = live;
  const names = session.spec.names;
  const goals = session.goals;
  const effectors = session.effectors();
  const n = 3 * names.length; // a floating root's move follows the bones' angles
  return poseToJson({
    rigName: live.name,
    boneNames: names,
    angles: session.angles.subarray(0, n),
    root: session.angles.length > n ? session.angles.subarray(n) : undefined,
    effectors,
    targets: session.targets,
    orientations: Array.from(effectors, (_, k) =>
      goals.orientation[k] ? goals.rotations.subarray(4 * k, 4 * k + 4) : null,
    ),
  });
}

/**
 * A pose file's text read for the rig shown, as the state to restore (angles clamped into the
 * limits in use) and the reader's warnings. A file listing no end effectors keeps the rig's, with
 * their targets on the tips of the pose read. Throws a PoseFormatError naming the field.
 */
export function readPoseText(text: string, live: LiveRig): { state: PoseState; warnings: string[] } {
  const { session } = live;
  const read = poseFromJson(text, session.spec);
  // A rig whose hips float (floating_hips.ts) takes the file's root move (none: where it stands),
  // clamped into its reach; another rig has no root to move and says so.
  const angles = new Float64Array(session.angles.length);
  angles.set(read.angles);
  if (read.root && angles.length > read.angles.length) angles.set(read.root, read.angles.length);
  else if (read.root)
    read.warnings.push(
      `the pose moves the root by [${Array.from(read.root).join(', ')}], which this rig cannot (its hips do not float): ignored`,
    );
  const pose = session.rig.project(angles);
  if (read.effectors.length === 0) {
    const effectors = session.effectors();
    const targets = session.rig.tips(pose);
    return { state: poseWithOrientations(pose, effectors, targets, []), warnings: read.warnings };
  }
  return {
    state: poseWithOrientations(pose, read.effectors, read.targets, read.orientations),
    warnings: read.warnings,
  };
}

/**
 * The pose file `file` read for the rig shown (readPoseText). A file over MAX_POSE_CHARS bytes is
 * refused before it is read. Throws a PoseFormatError naming the file and the field or limit.
 */
export async function readPoseFile(file: File, live: LiveRig): Promise<{ state: PoseState; warnings: string[] }> {
  if (file.size > MAX_POSE_CHARS)
    throw new PoseFormatError(
      `pose file ${file.name}: ${(file.size / 1048576).toFixed(1)} MB, more than a pose file holds (at most ${MAX_POSE_CHARS / 1048576} MB)`,
    );
  return readPoseText(await file.text(), live);
}

/** Offers `data` to the user as a download called `name`. */
export function download(data: Uint8Array | string, name: string, type: string): void {
  const blob = new Blob([data as BlobPart], { type });
  const url = URL.createObjectURL(blob);
  const a = document.createElement('a');
  a.href = url;
  a.download = name;
  a.hidden = true;
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 10_000);
}

/** Whether `text` (a .json file's start) is a pose file rather than an A7 rig. */
export function looksLikePoseFile(text: string): boolean {
  return /^\s*\{\s*"format"\s*:\s*"ik-pose"/.test(text.slice(0, 200));
}

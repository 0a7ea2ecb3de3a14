// Several files from the user at once: a folder dropped on the page, or files chosen together. One is
// the rig file (a .urdf before a .glb, .gltf or .json); the others are the files it may refer to (a
// URDF's meshes, a .gltf's buffers and images), found by the tail of their path.

/** Rig file types, the first preferred when several are given. */
const RIG_TYPES = [/\.urdf$/i, /\.glb$/i, /\.gltf$/i, /\.json$/i];

/** Most files read from one dropped folder (its subfolders included). */
export const MAX_DROPPED_FILES = 10_000;

/** A file and its path within what was dropped or chosen ("robot/meshes/base.stl"; a lone file: its name). */
export interface PathFile {
  path: string;
  file: File;
}

/** The rig file among `files` (see RIG_TYPES), or undefined, and the others. */
export function pickRigFile(files: readonly PathFile[]): { rig: PathFile | undefined; others: PathFile[] } {
  for (const type of RIG_TYPES) {
    const rig = files.find((f) => type.test(f.file.name));
    if (rig) return { rig, others: files.filter((f) => f !== rig) };
  }
  return { rig: undefined, others: [...files] };
}

/**
 * The file among `others` that `uri` (as a rig file writes it: "package://pkg/meshes/a.stl",
 * "meshes/a.stl", "../a.bin") names: the one whose path ends with the longest tail of the uri's
 * path segments ("pkg/meshes/a.stl", then "meshes/a.stl", then "a.stl"). Undefined when none does.
 */
export function findSibling(uri: string, others: readonly PathFile[]): File | undefined {
  let path = uri.replace(/^package:\/\//, '').replace(/^file:\/\//, '');
  try {
    path = decodeURIComponent(path);
  } catch {
    // a stray % stays as written
  }
  const parts = path.split('/').filter((p) => p !== '' && p !== '.' && p !== '..');
  for (let start = 0; start < parts.length; start++) {
    const tail = parts.slice(start).join('/');
    const found = others.find((f) => f.path === tail || f.path.endsWith(`/${tail}`));
    if (found) return found.file;
  }
  return undefined;
}

/**
 * Every file of a drop: folders walked (the File and Directory Entries API), each file with its
 * path; at most MAX_DROPPED_FILES. Falls back to the plain file list where entries are not offered.
 */
export async function droppedFiles(data: DataTransfer): Promise<PathFile[]> {
  const entries = Array.from(data.items ?? [])
    .map((item) => (typeof item.webkitGetAsEntry === 'function' ? item.webkitGetAsEntry() : null))
    .filter((e): e is FileSystemEntry => e !== null);
  if (entries.length === 0) return Array.from(data.files, (file) => ({ path: file.name, file }));
  const out: PathFile[] = [];
  const walk = async (entry: FileSystemEntry): Promise<void> => {
    if (out.length >= MAX_DROPPED_FILES) return;
    if (entry.isFile) {
      const file = await new Promise<File>((resolve, reject) => (entry as FileSystemFileEntry).file(resolve, reject));
      out.push({ path: entry.fullPath.replace(/^\//, ''), file });
      return;
    }
    const reader = (entry as FileSystemDirectoryEntry).createReader();
    for (;;) {
      const batch = await new Promise<FileSystemEntry[]>((resolve, reject) => reader.readEntries(resolve, reject));
      if (batch.length === 0) return;
      for (const child of batch) await walk(child);
    }
  };
  for (const entry of entries) await walk(entry);
  return out;
}

/** Files chosen together in a file chooser, with their paths (webkitRelativePath for a folder chosen, else the name). */
export function chosenFiles(list: FileList): PathFile[] {
  return Array.from(list, (file) => ({ path: file.webkitRelativePath || file.name, file }));
}

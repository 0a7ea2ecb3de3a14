// Reading a rig file and a .gltf's side buffers from disk (Node only), confined to the model's
// folder: a buffer uri must be a relative path that stays inside that folder once resolved (no
// "..", no absolute or UNC path, no symbolic link leading out of it), and every file read must be
// a regular file (not /dev/zero, a FIFO or a folder) of at most MAX_RIG_FILE_BYTES. A refused uri
// is reported as written in the file, without looking at the disk and without the resolved path,
// so a rig cannot find out which files exist outside its folder.
import { constants } from 'node:fs';
import { open, realpath } from 'node:fs/promises';
import { isAbsolute, relative, resolve, sep, win32 } from 'node:path';

import { MAX_RIG_FILE_BYTES } from './rig_limits.js';

/** Why a side file was refused or could not be read; the message names the uri, never the resolved path. */
export class SideFileError extends Error {}

/** The error code of a failed file operation (ENOENT, EACCES, ...), or its message. */
function reason(e: unknown): string {
  return (e as NodeJS.ErrnoException).code ?? (e as Error).message;
}

/**
 * Reads the regular file at `path`, at most MAX_RIG_FILE_BYTES. Throws SideFileError for
 * anything else (not a regular file, too large, unreadable), with a message that names no path.
 */
export async function readRegularFile(path: string): Promise<Uint8Array> {
  let handle;
  try {
    // Non-blocking, so that opening a FIFO (which waits for a writer) returns at once and is refused below.
    handle = await open(path, constants.O_RDONLY | (constants.O_NONBLOCK ?? 0));
  } catch (e) {
    throw new SideFileError(reason(e));
  }
  try {
    const stat = await handle.stat();
    if (!stat.isFile()) throw new SideFileError('not a regular file');
    if (stat.size > MAX_RIG_FILE_BYTES)
      throw new SideFileError(`${stat.size} bytes, more than the ${MAX_RIG_FILE_BYTES} a rig file may have`);
    return new Uint8Array(await handle.readFile());
  } finally {
    await handle.close();
  }
}

/** Is `child` (an absolute path) `folder` itself or inside it? */
function inside(folder: string, child: string): boolean {
  const rel = relative(folder, child);
  return rel !== '' && !rel.startsWith(`..${sep}`) && rel !== '..' && !isAbsolute(rel);
}

const OUTSIDE = "outside the model's folder (a side file must be a relative path inside it)";

/**
 * A reader for the side files of the glTF in `folder`: `uri` is a buffer's uri, URI-decoded.
 * Throws SideFileError for a uri that leaves the folder and for anything readRegularFile refuses.
 */
export function sideFileReader(folder: string): (uri: string) => Promise<Uint8Array> {
  return async (uri) => {
    if (uri === '' || isAbsolute(uri) || win32.isAbsolute(uri) || uri.includes('\0')) throw new SideFileError(OUTSIDE);
    const base = resolve(folder);
    const path = resolve(base, uri);
    if (!inside(base, path)) throw new SideFileError(OUTSIDE);
    // Symbolic links may still lead out: compare the real paths (the file must exist by now).
    let real: string, realBase: string;
    try {
      [real, realBase] = await Promise.all([realpath(path), realpath(base)]);
    } catch (e) {
      throw new SideFileError(reason(e));
    }
    if (!inside(realBase, real)) throw new SideFileError(OUTSIDE);
    return readRegularFile(real);
  };
}

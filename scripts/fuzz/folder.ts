// The model folder of a file case on disk: regular files, symbolic links, FIFOs, folders and
// sparse files, made afresh for each case.
import { spawnSync } from 'node:child_process';
import {
  closeSync,
  constants,
  lstatSync,
  mkdirSync,
  openSync,
  readdirSync,
  rmSync,
  symlinkSync,
  truncateSync,
  writeFileSync,
} from 'node:fs';
import { join } from 'node:path';

export type Entry =
  | { kind: 'file'; name: string; bytes: Uint8Array }
  | { kind: 'symlink'; name: string; target: string }
  | { kind: 'fifo'; name: string }
  | { kind: 'dir'; name: string }
  | { kind: 'sparse'; name: string; size: number };

/** Empties `folder` (creating it if needed) and makes `entries` in it. */
export function prepareFolder(folder: string, entries: readonly Entry[]): void {
  rmSync(folder, { recursive: true, force: true });
  mkdirSync(folder, { recursive: true });
  for (const e of entries) {
    const path = join(folder, e.name);
    if (e.kind === 'file') writeFileSync(path, e.bytes);
    else if (e.kind === 'symlink') symlinkSync(e.target, path);
    else if (e.kind === 'dir') mkdirSync(path);
    else if (e.kind === 'sparse') {
      writeFileSync(path, '');
      truncateSync(path, e.size);
    } else if (spawnSync('mkfifo', [path]).status !== 0) throw new Error(`mkfifo ${path} failed`);
  }
}

/**
 * Opens every FIFO in `folder` for writing without blocking and closes it again, so a reader
 * blocked in open() (a loader that waits on a FIFO) returns and its thread can be stopped.
 */
export function releaseFifos(folder: string): void {
  let names: string[];
  try {
    names = readdirSync(folder);
  } catch {
    return;
  }
  for (const name of names) {
    const path = join(folder, name);
    try {
      if (lstatSync(path).isFIFO()) closeSync(openSync(path, constants.O_WRONLY | constants.O_NONBLOCK));
    } catch {
      // No reader is waiting (ENXIO): nothing to release.
    }
  }
}

// A rig path that is no readable rig file: a FIFO, a folder, a link to /dev/zero, a link loop,
// a dangling link, an empty file, a sparse file past the size limit.
import type { Entry } from './folder.js';
import type { Rand } from './random.js';

/** A hostile entry named `name` (the path that will be loaded) and its description. */
export function hostileMain(r: Rand, name: string): { entries: Entry[]; description: string } {
  return r.pick<() => { entries: Entry[]; description: string }>([
    () => ({ entries: [{ kind: 'fifo', name }], description: `${name} is a FIFO` }),
    () => ({ entries: [{ kind: 'dir', name }], description: `${name} is a folder` }),
    () => ({ entries: [{ kind: 'symlink', name, target: '/dev/zero' }], description: `${name} links to /dev/zero` }),
    () => ({ entries: [{ kind: 'symlink', name, target: name }], description: `${name} links to itself` }),
    () => ({ entries: [{ kind: 'symlink', name, target: 'missing' }], description: `${name} is a dangling link` }),
    () => ({ entries: [{ kind: 'file', name, bytes: new Uint8Array(0) }], description: `${name} is empty` }),
    () => ({
      entries: [{ kind: 'sparse', name, size: 600 * 2 ** 20 }],
      description: `${name} is a 600 MiB sparse file`,
    }),
  ])();
}

// Memory check: the WebAssembly heap after 10^6 solves is the size it was after 10^3.
// Solves incremental targets (bench-node/targets.ts's steps) on the project's lamp with the
// default method through IkSolver, creating and disposing a rig and a solver every 1000 solves as
// a page would on reloads.
// Usage: npx tsx bench-node/report/heap_growth.ts [--solves 1000000]
// Prints the heap size (bytes) after 10^3 solves and at the end, and exits 1 if it grew.
// bench:report calls measureHeapGrowth directly.
import { resolve } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

import { loadIkNode } from '#ik/node.js';
import { IkRig } from '#ik/rig.js';
import { IkSolver } from '#ik/solver.js';
import { loadRigFromPath } from '#rig/load_rig_node.js';
import { streamFor } from '../prng.js';
import { incrementalAngles } from '../targets.js';

const lamp = fileURLToPath(new URL('../../web/public/models/lamp.glb', import.meta.url));

export interface HeapGrowth {
  solves: number;
  seconds: number;
  /** The WebAssembly heap after the first 1000 solves, and at the end, bytes. */
  bytesAfterThousand: number;
  bytesAtEnd: number;
}

/** Runs `total` solves (at least 1000) on a fresh WebAssembly instance and measures its heap. */
export async function measureHeapGrowth(total: number): Promise<HeapGrowth> {
  const ik = await loadIkNode();
  const spec = (await loadRigFromPath(lamp)).spec;
  const rand = streamFor(1, 'heap-growth');
  let bytesAfterThousand = 0;
  let solves = 0;
  const t0 = performance.now();
  for (let batch = 0; solves < total; batch++) {
    const rig = new IkRig(ik, spec);
    const solver = new IkSolver(rig, 'lm');
    let angles: Float64Array = new Float64Array(rig.numAngles);
    for (let k = 0; k < 1000 && solves < total; k++, solves++) {
      const goal = incrementalAngles(spec, angles, rand);
      angles = solver.solve(angles, rig.tips(goal)).angles;
    }
    solver.dispose();
    rig.dispose();
    if (batch === 0) bytesAfterThousand = ik.HEAPU8.length;
  }
  return { solves, seconds: (performance.now() - t0) / 1000, bytesAfterThousand, bytesAtEnd: ik.HEAPU8.length };
}

/** The measurement as the lines the command prints. */
export function heapGrowthText(h: HeapGrowth): string {
  return [
    `solves: ${h.solves} in ${h.seconds.toFixed(1)} s`,
    `heap after 10^3 solves: ${h.bytesAfterThousand} bytes`,
    `heap after ${h.solves} solves: ${h.bytesAtEnd} bytes`,
    h.bytesAtEnd === h.bytesAfterThousand
      ? 'heap unchanged'
      : `heap grew by ${h.bytesAtEnd - h.bytesAfterThousand} bytes`,
  ].join('\n');
}

if (process.argv[1] && import.meta.url === pathToFileURL(resolve(process.argv[1])).href) {
  const at = process.argv.indexOf('--solves');
  const h = await measureHeapGrowth(at > 0 ? Number(process.argv[at + 1]) : 1_000_000);
  console.log(heapGrowthText(h));
  process.exit(h.bytesAtEnd === h.bytesAfterThousand ? 0 : 1);
}

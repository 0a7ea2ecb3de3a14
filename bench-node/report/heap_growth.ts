// Memory check (issue 6): the WebAssembly heap after 10^6 solves is the size it was after 10^3.
// Solves incremental targets on the project's lamp with the default method through IkSolver,
// creating and disposing a rig and a solver every 1000 solves as a page would on reloads.
// Usage: npx tsx bench-node/report/heap_growth.ts [--solves 1000000]
// Prints the heap size (bytes) after 10^3 solves and at the end, and exits 1 if it grew.
import { loadIkNode } from '../../web/src/ik/node.js';
import { IkRig } from '../../web/src/ik/rig.js';
import { IkSolver } from '../../web/src/ik/solver.js';
import { loadRigFromPath } from '../../web/src/rig/load_rig_node.js';

const at = process.argv.indexOf('--solves');
const total = at > 0 ? Number(process.argv[at + 1]) : 1_000_000;
const ik = await loadIkNode();
const spec = (await loadRigFromPath('web/public/models/lamp.glb')).spec;
const heapBytes = (): number => ik.HEAPU8.length;

let state = 0x12345;
const rand = (): number => ((state = (Math.imul(state, 1103515245) + 12345) >>> 0) / 2 ** 32) * 2 - 1;
let afterThousand = 0;
let solved = 0;
const t0 = performance.now();
for (let batch = 0; solved < total; batch++) {
  const rig = new IkRig(ik, spec);
  const solver = new IkSolver(rig, 'lm');
  let angles: Float64Array = new Float64Array(rig.numAngles);
  for (let k = 0; k < 1000 && solved < total; k++, solved++) {
    const goal = rig.project(angles.map((a) => a + 5 * rand()));
    const result = solver.solve(angles, rig.tips(goal));
    angles = result.angles;
  }
  solver.dispose();
  rig.dispose();
  if (batch === 0) afterThousand = heapBytes();
}
const end = heapBytes();
const seconds = (performance.now() - t0) / 1000;
console.log(`solves: ${solved} in ${seconds.toFixed(1)} s`);
console.log(`heap after 10^3 solves: ${afterThousand} bytes`);
console.log(`heap after ${solved} solves: ${end} bytes`);
console.log(end === afterThousand ? 'heap unchanged' : `heap grew by ${end - afterThousand} bytes`);
process.exit(end === afterThousand ? 0 : 1);

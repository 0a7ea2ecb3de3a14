// The deep-chain figure: a 10,000-bone chain goes from file bytes to a rig in WebAssembly (the
// loader's checks, the tree walk, the core's build) in well under a second, because each step is
// linear. Printed by `npm run fuzz`; the README's Limits table says well under a second.
import type { IkCoreModule } from '#ik/module.js';
import { IkRig } from '#ik/rig.js';
import { loadRig } from '#rig/load_rig.js';
import { chainParents, treeA7, treeGlb } from '../rig_files/tree_rigs.js';
import { BROKEN } from './report.js';

const BONES = 10_000;
const RUNS = 5;

/** Median milliseconds of RUNS loads of `bytes` as `file` into an IkRig. */
async function medianLoadMs(ik: IkCoreModule, bytes: Uint8Array, file: string): Promise<number> {
  const times: number[] = [];
  for (let run = 0; run < RUNS; run++) {
    const t0 = performance.now();
    const rig = new IkRig(ik, (await loadRig(bytes, file)).spec);
    times.push(performance.now() - t0);
    if (rig.numBones !== BONES) throw new Error(`${file}: ${rig.numBones} bones, expected ${BONES}`);
    rig.dispose();
  }
  return times.sort((a, b) => a - b)[RUNS >> 1];
}

/** One line: the median time from file to rig of a 10,000-bone chain, as .glb and as A7 .json. */
export async function deepChainSummary(ik: IkCoreModule): Promise<string> {
  const parents = chainParents(BONES);
  const glb = await medianLoadMs(ik, treeGlb(parents), 'chain.glb');
  const a7 = await medianLoadMs(ik, new TextEncoder().encode(treeA7(parents)), 'chain.json');
  const holds = Math.max(glb, a7) < 1000 ? 'holds' : BROKEN;
  return `${BONES}-bone chain, file bytes to a rig in WebAssembly (median of ${RUNS}): .glb ${glb.toFixed(0)} ms, A7 .json ${a7.toFixed(0)} ms; promised under 1 s: ${holds}`;
}

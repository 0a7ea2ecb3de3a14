// A file case: a rig file (and side files) written to the model folder, loaded with
// loadRigFromPath, then built and solved. A load must fail with an error naming the file, or
// give a rig the core accepts and solves cleanly; it must never succeed through a uri outside
// the folder.
import { join } from 'node:path';

import type { IkCoreModule } from '#ik/module.js';
import { loadRigFromPath } from '#rig/load_rig_node.js';
import type { LoadedRig } from '#rig/load_rig.js';
import type { BudgetSample } from './case_id.js';
import { classifyThrown } from './classify_error.js';
import { prepareFolder, type Entry } from './folder.js';
import type { Outcome } from './outcome.js';
import type { Rand } from './random.js';
import { probeLoadedRig } from './rig_probe.js';

export interface FileCase {
  description: string;
  entries: Entry[];
  /** The file to load, in the folder. */
  main: string;
  /** Set when a buffer uri points outside the folder: any successful load read outside it. */
  outsideUri?: string;
  /** Set when a successful load is wrong in itself, saying why. */
  mustFail?: string;
}

/** The warning a load gives when the bind matrices disagree with the pose: the sentinel's bind matrices do. */
const SENTINEL_WARNING = 'not in the bind pose';

/** Runs `fc` in `folder` on module `ik`. */
export async function runFileCase(
  ik: IkCoreModule,
  folder: string,
  fc: FileCase,
  r: Rand,
  budgets: BudgetSample[],
): Promise<Outcome> {
  prepareFolder(folder, fc.entries);
  let loaded: LoadedRig;
  try {
    loaded = await loadRigFromPath(join(folder, fc.main));
  } catch (e) {
    return classifyThrown(e, fc.main);
  }
  if (fc.outsideUri !== undefined) {
    const read = loaded.warnings.some((w) => w.includes(SENTINEL_WARNING))
      ? ': the sentinel bind matrices are in the rig'
      : '';
    return {
      kind: 'outside',
      message: `loaded although a buffer uri "${fc.outsideUri}" points outside the folder${read}`,
    };
  }
  if (fc.mustFail) return { kind: 'wrong', message: `loaded although ${fc.mustFail}` };
  return probeLoadedRig(ik, loaded.spec, fc.main, r, budgets);
}

// The fuzzer as a test (issue "Hostile and careless input"): a fixed seed, a few hundred cases of
// each kind, none of which may crash the module, hang, return a silently wrong result or load a
// buffer from outside the model's folder, nor take over twice its time budget (budgets >= 10 ms);
// and many refused solves must not leak the stack.
// `npm run fuzz` runs more cases with other seeds (scripts/fuzz.ts).
import { describe, expect, it } from 'vitest';

import { loadIkNode } from '../../web/src/ik/node.js';
import { FUZZ_KINDS } from './case_id.js';
import { brokenPromises, budgetSummary, countOutcomes, countTable, failureList } from './report.js';
import { runFuzz } from './run_fuzz.js';
import { stackLeakCheck } from './stack_leak.js';

const SEED = 1;
const CASES_PER_KIND = 200;
const STACK_THROWS = 200_000;

describe('fuzz', () => {
  it(`${CASES_PER_KIND} cases of each kind (seed ${SEED}): no crash, hang, silent wrong result, read outside the folder or broken budget`, async () => {
    const reports = await runFuzz({ seed: SEED, cases: CASES_PER_KIND * FUZZ_KINDS.length, kinds: FUZZ_KINDS, workers: 2, hangSeconds: 5 });
    const budget = budgetSummary(reports);
    console.log(`${countTable(reports)}\n${budget}`);
    const c = countOutcomes(reports);
    expect({ crash: c.crash, hang: c.hang, silentWrong: c.wrong, readOutside: c.outside }, failureList(reports)).toEqual({
      crash: 0,
      hang: 0,
      silentWrong: 0,
      readOutside: 0,
    });
    expect(brokenPromises(budget)).toEqual([]);
  }, 180_000);

  it(`${STACK_THROWS} refused solves leave the module working (no stack leak)`, async () => {
    const result = stackLeakCheck(await loadIkNode(), STACK_THROWS);
    console.log(`stack leak: ${result.reachesWasm ? 'refused by the core' : 'refused before the core'}: ${result.message}`);
    expect(result.problem).toBeUndefined();
    expect(result.throws).toBe(STACK_THROWS);
  });
});

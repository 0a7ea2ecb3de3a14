// The fuzzer as a test: a fixed seed, a few hundred cases of
// each kind, none of which may crash the module, hang, return a silently wrong result or load a
// buffer from outside the model's folder; and many refused solves must not leak the stack. The
// time-budget line is printed, not asserted (a timed unit test fails on a loaded machine): `npm
// run fuzz` judges it and exits non-zero when it says BROKEN.
// `npm run fuzz` runs more cases with other seeds (scripts/fuzz.ts).
import { describe, expect, it } from 'vitest';

import { loadIkNode } from '../../web/src/ik/node.js';
import { FUZZ_KINDS } from '../../scripts/fuzz/case_id.js';
import { budgetSummary, countOutcomes, countTable, failureList } from '../../scripts/fuzz/report.js';
import { runFuzz } from '../../scripts/fuzz/run_fuzz.js';
import { stackLeakCheck } from '../../scripts/fuzz/stack_leak.js';

const SEED = 1;
const CASES_PER_KIND = 200;
const STACK_THROWS = 200_000;

describe('fuzz', () => {
  it(`${CASES_PER_KIND} cases of each kind (seed ${SEED}): no crash, hang, silent wrong result or read outside the folder`, async () => {
    const reports = await runFuzz({
      seed: SEED,
      cases: CASES_PER_KIND * FUZZ_KINDS.length,
      kinds: FUZZ_KINDS,
      workers: 2,
      hangSeconds: 5,
    });
    console.log(`${countTable(reports)}\n${budgetSummary(reports)}`);
    const c = countOutcomes(reports);
    expect(
      { crash: c.crash, hang: c.hang, silentWrong: c.wrong, readOutside: c.outside },
      failureList(reports),
    ).toEqual({
      crash: 0,
      hang: 0,
      silentWrong: 0,
      readOutside: 0,
    });
  }, 180_000);

  it(`${STACK_THROWS} refused solves leave the module working (no stack leak)`, async () => {
    const result = stackLeakCheck(await loadIkNode(), STACK_THROWS);
    console.log(
      `stack leak: ${result.reachesWasm ? 'refused by the core' : 'refused before the core'}: ${result.message}`,
    );
    expect(result.problem).toBeUndefined();
    expect(result.throws).toBe(STACK_THROWS);
  });
});

// Runs one case in a worker: draws it from its seed, runs it, then runs the canary. A crash, or
// a canary that fails, makes the worker load a fresh instance of the core for the next case.
import type { IkCoreModule } from '#ik/module.js';
import { runApiCase } from './api_case.js';
import { a7Case, type A7Seed } from './a7_case.js';
import { canaryProblem } from './canary.js';
import type { BudgetSample, CaseId, CaseReport } from './case_id.js';
import { classifyThrown } from './classify_error.js';
import { runFileCase } from './file_case.js';
import type { Fixture } from './fixture.js';
import type { GltfBase } from './gltf_bases.js';
import { gltfCase } from './gltf_case.js';
import { worse, type Outcome } from './outcome.js';
import { runPoseCase } from './pose_case.js';
import { Rand } from './random.js';

/** What a worker keeps between cases. */
export interface CaseEnv {
  ik: IkCoreModule;
  /** A fresh instance of the core (after a crash). */
  reload(): Promise<IkCoreModule>;
  fixture: Fixture;
  folder: string;
  bases: GltfBase[];
  seeds: A7Seed[];
}

async function runKind(
  env: CaseEnv,
  id: CaseId,
  note: (text: string) => void,
  drawn: () => void,
  budgets: BudgetSample[],
): Promise<Outcome> {
  const r = Rand.forCase(id.seed, id.kind, id.index);
  if (id.kind === 'api') return runApiCase(r, env.ik, note, budgets);
  if (id.kind === 'pose') return runPoseCase(r, note);
  const fc = id.kind === 'a7' ? a7Case(r, env.seeds) : gltfCase(r, env.bases, env.fixture);
  note(fc.description);
  drawn();
  return runFileCase(env.ik, env.folder, fc, r, budgets);
}

/**
 * Runs case `id`; `note` gets the parts of its description as they are drawn, `drawn` is called
 * once a file case's input is drawn (an api case draws each step as it runs it).
 */
export async function runCase(
  env: CaseEnv,
  id: CaseId,
  note: (text: string) => void,
  drawn: () => void,
): Promise<CaseReport> {
  const began = performance.now();
  const parts: string[] = [];
  const budgets: BudgetSample[] = [];
  const noted = (text: string): void => {
    parts.push(text);
    note(text);
  };
  let outcome: Outcome;
  try {
    outcome = await runKind(env, id, noted, drawn, budgets);
  } catch (e) {
    const c = classifyThrown(e);
    outcome = { kind: c.kind === 'clear' ? 'unclear' : c.kind, message: `escaped the case: ${c.message}` };
  }
  const canary = canaryProblem(env.ik);
  if (canary) outcome = worse(outcome, { kind: 'crash', message: `the module is unusable after the case: ${canary}` });
  if (outcome.kind === 'crash') env.ik = await env.reload();
  return { id, description: parts.join('; '), outcome, budgets, seconds: (performance.now() - began) / 1000 };
}

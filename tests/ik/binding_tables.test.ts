// The names the TypeScript API shares with the bindings, written once on each side and checked
// here: SolverOptions (web/src/ik/solver.ts) documents exactly the core's options, each with the
// core's default (read from the interface's source with the TypeScript compiler, so no list of
// names is repeated here), and the result numbers the core writes (wasm/src/solvers/
// summary_numbers.def) are exactly SolverResult's numeric and boolean fields, its flags the
// booleans: a solve in one call (solve()) and step by step (start(), step(), result()) agree.
import { readFileSync } from 'node:fs';
import { resolve } from 'node:path';

import ts from 'typescript';
import { beforeAll, describe, expect, it } from 'vitest';

import type { IkCoreModule } from '../../web/src/ik/module.js';
import { loadIkNode } from '../../web/src/ik/node.js';
import { IkRig } from '../../web/src/ik/rig.js';
import { IkSolver, type SolverResult } from '../../web/src/ik/solver.js';
import { disposeAfterAll } from '../helpers/owned.js';
import { straightLimb } from '../../scripts/rig_files/rig_builder.js';

let ik: IkCoreModule;
const keep = disposeAfterAll();

beforeAll(async () => {
  ik = await loadIkNode();
});

/** Each SolverOptions field of web/src/ik/solver.ts with the text of its doc comment. */
function documentedOptions(): Map<string, string> {
  const file = resolve(import.meta.dirname, '../../web/src/ik/solver.ts');
  const source = ts.createSourceFile(file, readFileSync(file, 'utf8'), ts.ScriptTarget.ES2022, true);
  const fields = new Map<string, string>();
  source.forEachChild((node) => {
    if (!ts.isInterfaceDeclaration(node) || node.name.text !== 'SolverOptions') return;
    for (const member of node.members) {
      const docs = ts.getJSDocCommentsAndTags(member).map((d) => ts.getTextOfJSDocComment(d.comment) ?? '');
      fields.set(member.name!.getText(source), docs.join(' '));
    }
  });
  return fields;
}

/** The value a doc comment gives after "Default" (a number, true/false, or 180/pi), or undefined. */
function statedDefault(doc: string): number | boolean | undefined {
  const m = /Default:? ([^\s,;()]+?)\.?(?:\s|$|,|;|\()/.exec(doc);
  if (!m) return undefined;
  const text = m[1];
  if (text === 'true' || text === 'false') return text === 'true';
  if (text === '180/pi') return 180 / Math.PI;
  return Number(text);
}

type ResultNumber = Exclude<keyof SolverResult, 'angles' | 'stopReason' | 'message'>;
const resultNumbers = {
  E: true,
  initialE: true,
  gradNorm: true,
  tipDistance: true,
  reached: true,
  iterations: true,
  functionEvaluations: true,
  jacobianEvaluations: true,
  restarts: true,
  escapes: true,
  chainRestarts: true,
  elapsedSeconds: true,
  outOfReach: true,
  orientationOutOfReach: true,
  goalsGivenUp: true,
} satisfies Record<ResultNumber, true>;

describe('tables shared with the bindings', () => {
  it("SolverOptions names exactly the core's options, each documented with the core's default", () => {
    const core = ik.Solver.defaultOptions() as Record<string, number | boolean>;
    const documented = documentedOptions();
    expect([...documented.keys()].sort()).toEqual(Object.keys(core).sort());
    for (const [name, doc] of documented) {
      const stated = statedDefault(doc);
      expect(stated, `${name}: its doc comment states no default ("Default X.")`).not.toBeUndefined();
      if (typeof stated === 'number') expect(stated, name).toBeCloseTo(core[name] as number, 12);
      else expect(stated, name).toBe(core[name]);
    }
  });

  it("reads a doc comment's default", () => {
    expect(statedDefault('Stop when E < this. Default 2e-4. Unused when')).toBe(2e-4);
    expect(statedDefault('first trial step. Default 180/pi.')).toBe(180 / Math.PI);
    expect(statedDefault('Default true.')).toBe(true);
    expect(statedDefault('Default 64 per solve.')).toBe(64);
    expect(statedDefault('(replaces the E test). Default 0 (the E test).')).toBe(0);
    expect(statedDefault('no default here')).toBeUndefined();
  });

  it("the result numbers are SolverResult's, and a solve in one call and step by step read alike", () => {
    expect([...ik.Solver.ioStats()].sort()).toEqual(Object.keys(resultNumbers).sort());
    const rig = keep(new IkRig(ik, straightLimb()));
    // A straight limb whose target lies along it: an escape and iterations, so the numbers differ.
    const solver = keep(new IkSolver(rig, 'lm', { restarts: 0, tipTolerance: 1e-6 }));
    const start = new Float64Array(rig.numAngles);
    const fast = solver.solve(start, [1.5, 0, 0]);
    solver.start(start, [1.5, 0, 0]);
    while (solver.step());
    const slow = solver.result();
    const flags = new Set(ik.Solver.ioFlags());
    for (const name of Object.keys(resultNumbers) as ResultNumber[]) {
      expect(typeof fast[name], name).toBe(flags.has(name) ? 'boolean' : 'number');
      if (name !== 'elapsedSeconds') expect(fast[name], name).toBe(slow[name]);
    }
    expect([...flags].sort()).toEqual(['orientationOutOfReach', 'outOfReach', 'reached']);
    expect(fast.escapes + fast.iterations).toBeGreaterThan(0);
    expect(slow.stopReason).toBe(fast.stopReason);
    expect(Array.from(fast.angles)).toEqual(Array.from(slow.angles));
  });
});

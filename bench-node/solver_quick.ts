// A minimal speed check of the solvers through the embind API (IkSolver) in Node: per rig and
// method, median iterations and median time per solve on PROTOCOL.md's incremental and random
// targets (report tolerances, 1 s budget). The full benchmark is `npm run bench` (cli.ts); this
// one exists to measure the binding's own overhead next to wasm/tools/solver_speed.cpp.
//
// Usage: npx tsx bench-node/solver_quick.ts [--rigs knight,beast] [--samples 200] [--restarts N]
// Exits 1 if a solve leaves the limits or does not stop for a tolerance, the step or the clock.
import { readFileSync } from 'node:fs';
import { resolve } from 'node:path';

import { loadIkNode } from '../web/src/ik/node.js';
import { IkRig } from '../web/src/ik/rig.js';
import { IkSolver, SOLVER_METHODS, type StopReason } from '../web/src/ik/solver.js';
import { parseA7Rig } from '../web/src/rig/a7_rig.js';
import { mulberry32 } from './prng.js';

function arg(name: string, fallback: string): string {
  const i = process.argv.indexOf(`--${name}`);
  return i >= 0 && i + 1 < process.argv.length ? process.argv[i + 1] : fallback;
}

const rigs = arg('rigs', 'knight,beast').split(',');
const samples = Number(arg('samples', '200'));
const restarts = Number(arg('restarts', '0'));
const a7Dir = resolve(import.meta.dirname, '../../shared/rigs/a7');

function median(values: number[]): number {
  const v = [...values].sort((a, b) => a - b);
  const n = v.length;
  return n % 2 ? v[(n - 1) / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

interface Case {
  start: Float64Array;
  target: Float64Array;
}

function targets(rig: IkRig, incremental: boolean, count: number, seed: number): Case[] {
  const rand = mulberry32(seed);
  const cases: Case[] = [];
  let previous: Float64Array = new Float64Array(rig.numAngles);
  for (let k = 0; k < count; k++) {
    const raw = previous.map((a) => (incremental ? a + 5 * (2 * rand() - 1) : 360 * (2 * rand() - 1)));
    const goal = rig.project(raw);
    cases.push({ start: incremental ? previous : new Float64Array(rig.numAngles), target: rig.tips(goal) });
    previous = goal;
  }
  return cases;
}

const ik = await loadIkNode();
const good: StopReason[] = ['converged_E', 'converged_grad', 'zero_step', 'timeout'];
let status = 0;
console.log('rig              set          method  n     it_med  t_med_us  success');
for (const name of rigs) {
  const rig = new IkRig(ik, parseA7Rig(readFileSync(resolve(a7Dir, `${name}.json`), 'utf8'), name));
  const beast = name === 'beast';
  const ftol = beast ? 0.002 : 2e-4;
  for (const set of ['incremental', 'random'] as const) {
    for (const method of SOLVER_METHODS) {
      const n = method === 'gd' ? Math.min(samples, 50) : samples;
      const cases = targets(rig, set === 'incremental', n, 2020);
      const solver = new IkSolver(rig, method, { gradientTolerance: beast ? 0.01 : 1e-4, errorTolerance: ftol, restarts });
      const warm = performance.now(); // untimed warm-up: V8 compiles hot WebAssembly in tiers
      for (let k = 0; performance.now() - warm < 300; k++) solver.solve(cases[k % n].start, cases[k % n].target);
      const iterations: number[] = [], micros: number[] = [];
      let successes = 0;
      for (const c of cases) {
        const t0 = performance.now();
        const r = solver.solve(c.start, c.target);
        micros.push(1000 * (performance.now() - t0));
        iterations.push(r.iterations);
        if (r.E < ftol) successes++;
        const inside = r.angles.every((x, i) => x >= rig.lower[i] && x <= rig.upper[i]);
        if (!inside || !good.includes(r.stopReason)) {
          console.error(`${name} ${set} ${method}: ${r.stopReason} ${inside ? '' : 'outside the limits'}`);
          status = 1;
        }
      }
      solver.dispose();
      const row = [name.padEnd(16), set.padEnd(12), method.padEnd(7), String(n).padEnd(5)];
      row.push(median(iterations).toFixed(1).padStart(7), median(micros).toFixed(2).padStart(9));
      row.push(`${((100 * successes) / n).toFixed(1)}%`.padStart(8));
      console.log(row.join(' '));
    }
  }
  rig.dispose();
}
process.exit(status);

// Solver options and method names, sane or careless or hostile: non-objects, Maps, arrays,
// unknown or misspelt names, wrong types, out-of-range values, getters with side effects.
// Every accepted combination stays bounded in time: a time budget or an iteration cap is kept.
import { FUZZ_THROW } from './classify_error.js';
import type { Acceptance } from './hostile_args.js';
import { changeEffectors, type ApiState } from './api_state.js';
import type { Rand } from './random.js';

export interface OptionsArg {
  value: unknown;
  text: string;
  /** Whether the constructor and setOptions() must accept it. */
  accept: Acceptance;
  /** Accepted there, but out of range: start() and solve() must refuse it. */
  outOfRange?: boolean;
}

/** Options that keep a solve short (what the setup and the sane variants use). */
export function saneOptions(r: Rand): Record<string, unknown> {
  const o: Record<string, unknown> = { timeBudgetSeconds: r.pick([0.002, 0.01, 0.03]), seed: r.int(1000) };
  if (r.chance(0.3)) o.restarts = r.pick([0, 3]);
  if (r.chance(0.2)) o.paperMode = true;
  if (r.chance(0.2)) o.tipTolerance = r.pick([0, 1e-3]);
  if (r.chance(0.2)) o.historyCapacity = r.pick([0, 1, 100]);
  if (r.chance(0.2)) o.escapeSaddles = r.chance(0.5);
  if (r.chance(0.2)) o.maxIterations = r.pick([1, 10, 1000]);
  return o;
}

/** [name, value] pairs of the wrong type: the constructor and setOptions() must refuse them. */
const BAD_TYPES: [string, unknown][] = [
  ['maxIterations', 1.5],
  ['maxIterations', '5'],
  ['maxIterations', 2 ** 31],
  ['maxIterations', 5n],
  ['historyCapacity', 2 ** 40],
  ['timeBudgetSeconds', null],
  ['timeBudgetSeconds', '1'],
  ['seed', -1],
  ['seed', 2 ** 32],
  ['seed', 0.5],
  ['paperMode', 1],
  ['paperMode', 'yes'],
  ['escapeSaddles', null],
  ['errorTolerance', new Number(1)],
];

/** [name, value] pairs out of range: accepted by the constructor and setOptions(), start() and solve() must refuse them. */
const OUT_OF_RANGE: [string, unknown][] = [
  ['maxIterations', -1],
  ['historyCapacity', -1],
  ['historyCapacity', 1e8],
  ['historyCapacity', 2 ** 31 - 1],
  ['maxBacktracks', 2 ** 31 - 1],
  ['maxBacktracks', -1],
  ['timeBudgetSeconds', -1],
  ['timeBudgetSeconds', NaN],
  ['errorTolerance', -1],
  ['errorTolerance', NaN],
  ['gradientTolerance', -1],
  ['tipTolerance', NaN],
  ['tipTolerance', -1],
  ['backtrackFactor', 0],
  ['backtrackFactor', 1],
  ['backtrackFactor', 2],
  ['backtrackFactor', NaN],
  ['armijoC1', -1],
  ['armijoC1', 1],
  ['fdStepDeg', 0],
  ['fdStepDeg', -1e-7],
  ['gdInitialStep', Infinity],
  ['gdInitialStep', 0],
  ['lmInitialMu', -1],
  ['lmInitialMu', NaN],
  ['lmDampingFloor', -1],
  ['lmMaxRejections', -5],
  ['softIterations', -1],
  ['restarts', -1],
  ['stallIterations', -1],
  ['chainRestarts', -1],
  ['gnSingularCutoff', -1],
  ['gnSingularCutoff', NaN],
  ['gnMaxStepDeg', 0],
  ['newtonMaxStepDeg', -1],
  ['errorTolerance', 0],
  ['fdStepDeg', 1e-300],
  ['fdStepDeg', 1e300],
  ['restWeight', 1e10],
  ['restWeight', 1e150],
  ['restWeight', 1e308],
  ['rootUnit', 0],
  ['rootUnit', -1],
  ['rootUnit', NaN],
  ['rootUnit', Infinity],
  ['rootUnit', 1e200],
];

/** [name, value] pairs in range but at an edge: accepted, and the solve must still end and be clean. */
const EDGE_VALUES: [string, unknown][] = [
  ['timeBudgetSeconds', 1e-9],
  ['timeBudgetSeconds', 5e-324],
  ['timeBudgetSeconds', 1e-6],
  ['timeBudgetSeconds', 0],
  ['timeBudgetSeconds', Infinity],
  ['maxIterations', 0],
  ['maxIterations', 2 ** 31 - 1],
  ['historyCapacity', 0],
  ['historyCapacity', 1_000_000],
  ['maxBacktracks', 0],
  ['maxBacktracks', 1000],
  ['restarts', 2 ** 31 - 1],
  ['stallIterations', 0],
  ['stallIterations', 1],
  ['chainRestarts', 2 ** 31 - 1],
  ['lmMaxRejections', 2 ** 31 - 1],
  ['lmInitialMu', 1e300],
  ['lmInitialMu', 0],
  ['lmDampingFloor', 0],
  ['lmDampingFloor', 1e300],
  ['errorTolerance', 5e-324],
  ['gradientTolerance', 0],
  ['tipTolerance', 1e300],
  ['gnSingularCutoff', 0],
  ['gnMaxStepDeg', 1e300],
  ['newtonMaxStepDeg', 1e-300],
  ['gdInitialStep', 1e-300],
  ['gdInitialStep', 1e300],
  ['backtrackFactor', 1e-300],
  ['armijoC1', 0],
  ['fdStepDeg', 1e-9],
  ['fdStepDeg', 1],
  ['seed', 2 ** 32 - 1],
  ['paperMode', true],
  ['restWeight', 1000],
  ['rootUnit', 1e-150],
  ['rootUnit', 1e150],
];

/** A bounded options object with `name` set to `value`: a time budget bounds an iteration cap and the other way round. */
function bounded(name: string, value: unknown): Record<string, unknown> {
  const o: Record<string, unknown> =
    name === 'timeBudgetSeconds' ? { maxIterations: 200, restarts: 1 } : { timeBudgetSeconds: 0.02 };
  o[name] = value;
  return o;
}

function show(v: unknown): string {
  return typeof v === 'bigint' ? `${v}n` : typeof v === 'string' ? JSON.stringify(v) : String(v);
}

/** An options argument for new IkSolver() or setOptions(). */
export function optionsArg(r: Rand, s: ApiState): OptionsArg {
  return r.weighted<() => OptionsArg>([
    [8, () => ({ value: saneOptions(r), text: 'sane options', accept: 'must' })],
    [
      3,
      () => {
        const [name, value] = r.pick(BAD_TYPES);
        return { value: bounded(name, value), text: `options {${name}: ${show(value)}}`, accept: 'mustNot' };
      },
    ],
    [
      4,
      () => {
        const [name, value] = r.pick(OUT_OF_RANGE);
        return {
          value: bounded(name, value),
          text: `options {${name}: ${show(value)}}`,
          accept: 'must',
          outOfRange: true,
        };
      },
    ],
    [
      6,
      () => {
        const [name, value] = r.pick(EDGE_VALUES);
        return { value: bounded(name, value), text: `options {${name}: ${show(value)}}`, accept: 'either' };
      },
    ],
    [
      2,
      () => {
        const name = r.pick([
          'maxIteration',
          'MaxIterations',
          'max_iterations',
          '',
          'constructor',
          'toString',
          '__proto__',
          'x'.repeat(10_000),
        ]);
        const o = JSON.parse(`{"timeBudgetSeconds": 0.01, ${JSON.stringify(name)}: 5}`) as unknown;
        return { value: o, text: `options with the unknown name "${name.slice(0, 20)}"`, accept: 'mustNot' };
      },
    ],
    [
      3,
      () => {
        const [text, value] = r.pick<[string, unknown]>([
          ['[]', []],
          ['[0.01]', [0.01]],
          ['a Map', new Map([['timeBudgetSeconds', 0.01]])],
          ['a Set', new Set()],
          ['a Date', new Date(0)],
          ['"lm"', 'lm'],
          ['42', 42],
          ['true', true],
          ['a function', () => 0],
          ['a Symbol', Symbol('o')],
          ['Object.create(null)', Object.create(null)],
          ['an inherited {maxIterations: 5}', Object.create({ maxIterations: 5 })],
          ['a frozen {}', Object.freeze({ timeBudgetSeconds: 0.01 })],
          ['a Number object', new Number(1)],
        ]);
        return { value, text: `options = ${text}`, accept: 'either' };
      },
    ],
    [
      3,
      () => {
        const [what, effect] = r.pick<[string, () => void]>([
          ['disposes the rig', () => s.rig.dispose()],
          ['disposes the solver', () => s.solver.dispose()],
          [
            'throws',
            () => {
              throw new Error(FUZZ_THROW);
            },
          ],
          ['sets the effectors to [0]', () => changeEffectors(s, [0])],
          ['returns a value only', () => undefined],
        ]);
        const o = Object.defineProperty({ timeBudgetSeconds: 0.01 }, 'maxIterations', {
          get: () => (effect(), 50),
          enumerable: true,
        });
        return {
          value: o,
          text: `options whose maxIterations getter ${what}`,
          accept: what === 'throws' ? 'mustNot' : 'either',
        };
      },
    ],
    [
      1,
      () => {
        const proxy = new Proxy(
          {},
          {
            ownKeys: () => ['maxIterations'],
            getOwnPropertyDescriptor: () => ({ enumerable: true, configurable: true }),
            get: () => undefined,
          },
        );
        return { value: proxy, text: 'options as a Proxy listing maxIterations with no value', accept: 'either' };
      },
    ],
  ])();
}

/** A solver method name: one of `methods` (the core's registry), or not a method at all. */
export function methodArg(r: Rand, methods: readonly string[]): { value: unknown; text: string; accept: Acceptance } {
  if (r.chance(0.7)) {
    const m = r.pick(methods);
    return { value: m, text: m, accept: 'either' };
  }
  const v = r.pick<unknown>([
    'LM',
    '',
    'lm ',
    'lm\0',
    '__proto__',
    'constructor',
    'toString',
    'x'.repeat(100_000),
    42,
    null,
    undefined,
    {},
    ['lm'],
    new String('lm'),
    Symbol('lm'),
  ]);
  const text =
    typeof v === 'string'
      ? JSON.stringify(v.slice(0, 20))
      : typeof v === 'symbol'
        ? 'a Symbol'
        : `${String(v)} (${typeof v})`;
  return { value: v, text: `method ${text}`, accept: v instanceof String || v === undefined ? 'either' : 'mustNot' };
}

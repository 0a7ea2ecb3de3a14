// `npm run fuzz -- --cases N [--seed S] [--kind a7,gltf,api] [--case K]`: feeds the rig loaders
// and the solver API careless and hostile input (scripts/fuzz/), prints the outcome counts per kind,
// the time budget's worst ratio, the stack-leak check, the time to load a 10,000-bone chain, and
// every failing case with the command that replays it.
// Exit code 1 on any crash, hang, unclear error, silent wrong result or read outside the model folder, a stack
// leak, or a promise line (time budget, deep chain) that says BROKEN.
import { Command, InvalidArgumentError, Option } from 'commander';
import { SingleBar } from 'cli-progress';

import { loadIkNode } from '#ik/node.js';
import { FUZZ_KINDS, type FuzzKind } from './fuzz/case_id.js';
import { deepChainSummary } from './fuzz/deep_chain.js';
import { budgetSummary, countTable, exitCode, failureList } from './fuzz/report.js';
import { runFuzz } from './fuzz/run_fuzz.js';
import { stackLeakCheck } from './fuzz/stack_leak.js';

function integer(min: number): (text: string) => number {
  return (text) => {
    const v = /^\d+$/.test(text) ? Number(text) : NaN;
    if (!Number.isSafeInteger(v) || v < min) throw new InvalidArgumentError(`expected an integer >= ${min}`);
    return v;
  };
}

function kinds(text: string): FuzzKind[] {
  const list = text.split(',').map((k) => k.trim());
  const bad = list.find((k) => !(FUZZ_KINDS as readonly string[]).includes(k));
  if (bad !== undefined) throw new InvalidArgumentError(`unknown kind "${bad}" (known: ${FUZZ_KINDS.join(', ')})`);
  return list as FuzzKind[];
}

const program = new Command('npm run fuzz --')
  .description('Fuzz the A7 and glTF rig loaders and the IkRig/IkSolver API')
  .option('--cases <n>', 'cases in all, spread over the kinds', integer(1), 300)
  .option('--seed <s>', 'seed of the run (default: a random one, printed)', integer(0))
  .option('--kind <list>', `kinds of cases, comma-separated (${FUZZ_KINDS.join(',')})`, kinds, [...FUZZ_KINDS])
  .option('--case <k>', 'replay case number k of each kind given (with --seed)', integer(0))
  .option('--workers <n>', 'worker threads', integer(1), 1)
  .option('--hang-seconds <s>', 'a case running longer than this is a hang', integer(1), 5)
  .addOption(
    new Option('--stack-throws <n>', 'refused solves of the stack-leak check (0: skip it)')
      .argParser(integer(0))
      .default(1_000_000),
  )
  .option('--no-progress', 'no progress bar on stderr');

async function main(): Promise<number> {
  program.parse();
  const o = program.opts<{
    cases: number;
    seed?: number;
    kind: FuzzKind[];
    case?: number;
    workers: number;
    hangSeconds: number;
    stackThrows: number;
    progress: boolean;
  }>();
  const seed = o.seed ?? Math.floor(Math.random() * 2 ** 31);
  const total = o.case === undefined ? o.cases : o.kind.length;
  process.stdout.write(
    `fuzz: seed ${seed}, ${total} cases (${o.kind.join(', ')})${o.case === undefined ? '' : `, case ${o.case}`}\n`,
  );

  const bar =
    o.progress && process.stderr.isTTY
      ? new SingleBar({
          format: '{bar} {value}/{total} cases | {failing} failing | ETA {eta_formatted}',
          stream: process.stderr,
          hideCursor: true,
          clearOnComplete: true,
        })
      : undefined;
  bar?.start(total, 0, { failing: 0 });
  let failing = 0;
  const reports = await runFuzz({
    seed,
    cases: o.cases,
    kinds: o.kind,
    only: o.case,
    workers: o.workers,
    hangSeconds: o.hangSeconds,
    onReport: (r) => {
      if (r.outcome.kind !== 'ok' && r.outcome.kind !== 'clear') failing++;
      bar?.increment(1, { failing });
    },
  });
  bar?.stop();

  const budget = budgetSummary(reports);
  process.stdout.write(`\n${countTable(reports)}\n\n${budget}\n`);
  let leak = false;
  if (o.stackThrows > 0 && o.case === undefined) {
    const r = stackLeakCheck(await loadIkNode(), o.stackThrows);
    leak = r.problem !== undefined;
    process.stdout.write(
      `stack leak: ${r.throws} refused solves (${r.reachesWasm ? 'refused by the core' : 'refused before the core'}: ${r.message}), ` +
        `${leak ? `FAILED: ${r.problem}` : 'then a valid solve works'}\n`,
    );
  }
  const deepChain = o.case === undefined ? await deepChainSummary(await loadIkNode()) : '';
  if (deepChain) process.stdout.write(`${deepChain}\n`);
  const failures = failureList(reports);
  if (failures) process.stdout.write(`\n${failures}\n`);
  return exitCode(reports, leak, [budget, deepChain]);
}

process.exitCode = await main();

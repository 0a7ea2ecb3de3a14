// The native engine: the same C++ core built with g++ (build/native/ik_bench_native, source
// wasm/tools/ik_bench_native.cpp), driven by the same target sets. The rig goes over as A7 JSON,
// the starts and targets as float64 binary; batches of whole independent ranges (as for the
// workers) run in up to `workers` processes at once; each writes one result line per solve.
import { spawn, spawnSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';

import type { RigSpec } from '#ik/rig_arrays.js';
import { writeA7Rig } from '#rig/a7/a7_writer.js';
import { pinnedFramesArgument } from './drag_goals.js';
import { BenchError, quote } from './errors.js';
import type { SolveResult } from './metrics.js';
import { batchesOf } from './run_wasm.js';
import type { RunSettings } from './runner.js';
import type { TargetSet } from './target_set.js';

/**
 * The native tool: build/native/ik_bench_native, or ik_bench_native in the build folder named by
 * the environment variable IK_NATIVE_BUILD (for a build of one's own beside a shared build/native).
 */
export const nativeToolPath = process.env.IK_NATIVE_BUILD
  ? join(process.env.IK_NATIVE_BUILD, 'ik_bench_native')
  : fileURLToPath(new URL('../build/native/ik_bench_native', import.meta.url));

const BATCHES_PER_PROCESS = 4;

/** The job file: header "IKBJOB1\0", int32 count, #angles, #residuals, #orientation numbers (0,
 *  or with --goals pose 4 per effector); then per sample float64 chained, dragged, start
 *  (#angles), target (#residuals), orientations (quaternions x, y, z, w). */
export function encodeJob(set: TargetSet, begin: number, end: number): Uint8Array {
  const m = set.numAngles,
    r = set.numResiduals,
    o = set.orientations ? (4 * r) / 3 : 0,
    stride = 2 + m + r + o;
  const count = end - begin;
  const bytes = new Uint8Array(24 + 8 * stride * count);
  bytes.set(new TextEncoder().encode('IKBJOB1\0'), 0);
  const header = new DataView(bytes.buffer, 8, 16);
  [count, m, r, o].forEach((v, i) => header.setInt32(4 * i, v, true));
  const body = new DataView(bytes.buffer, 24);
  let offset = 0;
  const put = (x: number): void => {
    body.setFloat64(offset, x, true);
    offset += 8;
  };
  for (let k = begin; k < end; k++) {
    put(k > begin ? set.chained[k] : 0);
    put(set.dragged[k]);
    for (let i = 0; i < m; i++) put(set.starts[k * m + i]);
    for (let i = 0; i < r; i++) put(set.targets[k * r + i]);
    for (let i = 0; i < o; i++) put(set.orientations![k * o + i]);
  }
  return bytes;
}

/** One line of RESULTS.jsonl (see ik_bench_native.cpp); null stands for NaN. */
interface NativeResult {
  E: number | null;
  iterations: number;
  seconds: number;
  stop_reason: string;
  wobble_during: number | null;
  wobble_after: number | null;
  tip_distance: number | null;
  jump_deg: number | null;
  /** The largest distance a joint moved from the start to the solution (rig units). */
  jump_move?: number | null;
  /** Records with a dragged effector: the solution (degrees). */
  angles?: number[];
  /** --goals pose only. */
  rot_err_deg?: number | null;
  twist_max?: number | null;
}

/** Parses RESULTS.jsonl (see ik_bench_native.cpp), `expected` lines; `file` names it in errors. */
export function decodeResults(text: string, expected: number, file: string): SolveResult[] {
  const lines = text.split('\n').filter((l) => l.length > 0);
  if (lines.length !== expected)
    throw new BenchError(`native engine: ${file} has ${lines.length} results, expected ${expected}`);
  return lines.map((line) => {
    const r = JSON.parse(line) as NativeResult;
    const num = (x: number | null): number => x ?? NaN;
    return {
      E: num(r.E),
      tipDistance: num(r.tip_distance),
      iterations: r.iterations,
      seconds: r.seconds,
      stopReason: r.stop_reason,
      wobbleDuring: num(r.wobble_during),
      wobbleAfter: num(r.wobble_after),
      jumpDeg: num(r.jump_deg),
      ...(r.jump_move === undefined ? {} : { jointMove: num(r.jump_move) }),
      ...(r.angles === undefined ? {} : { angles: Float64Array.from(r.angles) }),
      ...(r.rot_err_deg === undefined ? {} : { rotErrDeg: num(r.rot_err_deg) }),
      ...(r.twist_max === undefined ? {} : { twistMax: num(r.twist_max) }),
    };
  });
}

function runProcess(args: string[]): Promise<void> {
  return new Promise((resolve, reject) => {
    const child = spawn(nativeToolPath, args, { stdio: ['ignore', 'ignore', 'pipe'] });
    let stderr = '';
    child.stderr.on('data', (d: Buffer) => (stderr += d.toString()));
    child.on('error', (e) => reject(new BenchError(`native engine: ${e.message}`)));
    child.on('close', (code) => {
      if (code === 0) resolve();
      else reject(new BenchError(`native engine: ${stderr.trim().split('\n')[0] || `exit code ${code}`}`));
    });
  });
}

/**
 * Throws BenchError when the native tool is missing, or does not know one of `methods` (a build
 * older than the WebAssembly module): it lists its methods with --list-methods.
 */
export function checkNativeTool(methods: readonly string[]): void {
  const build = 'bash scripts/setup.sh --native';
  if (!existsSync(nativeToolPath))
    throw new BenchError(`native engine: ${nativeToolPath} is missing; build it with "${build}"`);
  const listed = spawnSync(nativeToolPath, ['--list-methods'], { encoding: 'utf8' });
  const known = listed.status === 0 ? (JSON.parse(listed.stdout) as string[]) : [];
  const unknown = methods.find((m) => !known.includes(m));
  // kdl is there only when CMake found Orocos KDL (liborocos-kdl-dev, which the build installs).
  const why = unknown?.startsWith('kdl') ? ` (${unknown} needs Orocos KDL: the package liborocos-kdl-dev)` : '';
  if (unknown !== undefined)
    throw new BenchError(
      `native engine: ${nativeToolPath} has no method ${quote(unknown)}${why} (it knows: ${known.join(', ') || 'none'}); rebuild it with "${build}"`,
    );
}

/** Runs every sample of `set` with the native tool; results in sample order. */
export async function runNative(
  spec: RigSpec,
  settings: RunSettings,
  set: TargetSet,
  processes: number,
  onProgress: (solved: number) => void,
): Promise<SolveResult[]> {
  checkNativeTool([settings.method]);
  const dir = mkdtempSync(join(tmpdir(), 'ik-bench-'));
  try {
    const rigFile = join(dir, 'rig.json');
    writeFileSync(rigFile, writeA7Rig(spec));
    const batches = batchesOf(set, processes * BATCHES_PER_PROCESS);
    const results: SolveResult[][] = new Array(batches.length);
    let next = 0;
    const lane = async (): Promise<void> => {
      while (next < batches.length) {
        const b = next++;
        const [begin, end] = batches[b];
        const input = join(dir, `job${b}.bin`),
          output = join(dir, `results${b}.jsonl`);
        writeFileSync(input, encodeJob(set, begin, end));
        const args = [
          '--rig',
          rigFile,
          '--method',
          settings.method,
          '--input',
          input,
          '--output',
          output,
          '--gradient-tolerance',
          String(settings.gradientTolerance),
          '--error-tolerance',
          String(settings.errorTolerance),
          '--tip-tolerance',
          String(settings.tipTolerance),
          '--time-budget',
          String(settings.timeBudgetSeconds),
        ];
        if (settings.paper) args.push('--paper');
        if (settings.restarts !== undefined) args.push('--restarts', String(settings.restarts));
        if (settings.maxJointMove !== undefined) args.push('--max-joint-move', String(settings.maxJointMove));
        if (settings.pageGoals)
          args.push('--page-goals', pinnedFramesArgument(spec, spec.effectors, settings.pinFrames ?? false));
        if (settings.goals === 'pose') args.push('--goals', 'pose');
        if (settings.orientationToleranceDeg !== undefined)
          args.push('--orientation-tolerance', String(settings.orientationToleranceDeg));
        await runProcess(args);
        results[b] = decodeResults(readFileSync(output, 'utf8'), end - begin, output);
        onProgress(end - begin);
      }
    };
    await Promise.all(Array.from({ length: Math.min(processes, batches.length) }, lane));
    return results.flat();
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
}

// A worker thread: instantiates the WebAssembly module it was handed (compiled once by the main
// thread), then runs batches of solves with one Runner per (rig, settings) and replies per batch.
import { parentPort, workerData } from 'node:worker_threads';

import type { IkCoreModule } from '#ik/module.js';
import { loadIk } from '#ik/module.js';
import { IkRig } from '#ik/rig.js';
import { errorOf, tipDistance } from './evaluate.js';
import type { SolveResult } from './metrics.js';
import { largestRotationErrorDeg, largestTwistComponent } from './pose_goals.js';
import { makeRunner } from './make_runner.js';
import { StepMeasurer } from './step_measures.js';
import type { Runner } from './runner.js';
import { warmUp } from './warm_up.js';
import type { WorkerInit, WorkerReply, WorkerTask } from './worker_protocol.js';

const port = parentPort;
if (!port) throw new Error('worker.ts runs only as a worker thread');
const init = workerData as WorkerInit;

const ik: IkCoreModule = await loadIk({
  instantiateWasm(imports, done) {
    void WebAssembly.instantiate(init.wasmModule, imports).then((instance) => done(instance, init.wasmModule));
    return {};
  },
});

let cached: { key: string; runner: Runner; rig: IkRig; measurer?: StepMeasurer } | undefined;

function runnerFor(task: WorkerTask): { runner: Runner; rig: IkRig; measurer?: StepMeasurer } {
  const key = `${task.rigKey}\u0000${JSON.stringify(task.settings)}`;
  if (cached?.key === key) return cached;
  cached?.runner.dispose();
  cached?.rig.dispose();
  const rig = new IkRig(ik, task.spec);
  const runner = makeRunner(ik, task.spec, task.settings);
  const rotations = task.settings.goals === 'pose' ? (a: Float64Array) => rig.tipRotations(a) : undefined;
  warmUp(runner, task.spec, (a) => rig.tips(a), init.warmUpMs, rotations);
  cached = { key, rig, runner };
  return cached;
}

function run(task: WorkerTask): SolveResult[] {
  const entry = runnerFor(task);
  const { runner, rig } = entry;
  const measurer = task.limbs ? (entry.measurer ??= new StepMeasurer(task.spec, rig, task.limbs)) : undefined;
  const m = task.numAngles,
    r = task.numResiduals,
    q = (4 * r) / 3;
  const results: SolveResult[] = [];
  let lastReport = performance.now();
  // Where the previous solve ended: a chained step's start, for the step measures.
  let previous: Float64Array | null = null;
  for (let k = 0; k < task.count; k++) {
    const chained = task.chained[k] === 1 && k > 0;
    const start = chained ? null : task.starts.subarray(k * m, (k + 1) * m);
    const target = task.targets.subarray(k * r, (k + 1) * r);
    const orientations = task.orientations?.subarray(k * q, (k + 1) * q) ?? null;
    let result: SolveResult;
    try {
      result = runner.solve({ start, target, orientations, dragged: task.dragged[k] });
    } catch (e) {
      const stopReason = `exception: ${(e as Error).message.split('\n')[0]}`;
      result = {
        E: NaN,
        tipDistance: NaN,
        iterations: 0,
        seconds: 0,
        stopReason,
        wobbleDuring: NaN,
        wobbleAfter: NaN,
        jumpDeg: NaN,
      };
    }
    // A solve that failed before producing a pose (invalid input, an exception) is counted with
    // the E, tip distance (and orientation error) of its start, so averages stay finite and the
    // failure shows in the stop reasons.
    if (!Number.isFinite(result.E)) {
      const startAngles = task.starts.subarray(k * m, (k + 1) * m);
      const tips = rig.tips(startAngles);
      result.E = errorOf(tips, target);
      result.tipDistance = tipDistance(tips, target);
      if (orientations) {
        const rotations = rig.tipRotations(startAngles);
        result.rotErrDeg = largestRotationErrorDeg(rotations, orientations);
        result.twistMax = largestTwistComponent(tips, target, rotations, orientations);
      }
    }
    // The step's joint move and flip, from where it started to the pose the runner returned.
    const from = chained ? previous : task.starts.subarray(k * m, (k + 1) * m);
    if (measurer && from && result.angles) Object.assign(result, measurer.measure(from, result.angles));
    previous = result.angles ? result.angles.slice() : null;
    delete result.angles;
    results.push(result);
    const now = performance.now();
    if (now - lastReport > 100 || k === task.count - 1) {
      port!.postMessage({ kind: 'progress', id: task.id, solved: k + 1 } satisfies WorkerReply);
      lastReport = now;
    }
  }
  return results;
}

port.on('message', (task: WorkerTask) => {
  let reply: WorkerReply;
  try {
    reply = { kind: 'done', id: task.id, results: run(task) };
  } catch (e) {
    reply = { kind: 'failed', id: task.id, message: (e as Error).message.split('\n')[0] };
  }
  port.postMessage(reply);
});
port.postMessage({ kind: 'ready' } satisfies WorkerReply);

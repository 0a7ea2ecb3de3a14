// A fuzz worker thread: instantiates the core it was handed, then runs the cases it is sent, one
// at a time, reporting each part of a case's description before running it (so the pool can
// describe a case that hangs).
import { parentPort, workerData } from 'node:worker_threads';

import { loadIk, type IkCoreModule } from '#ik/module.js';
import { readA7Seeds } from './a7_case.js';
import { runCase, type CaseEnv } from './case_runner.js';
import { modelFolder } from './fixture.js';
import { loadGltfBases } from './gltf_bases.js';
import type { FromWorker, ToWorker, WorkerInit } from './worker_protocol.js';

const port = parentPort;
if (!port) throw new Error('worker.ts runs only as a worker thread');
const init = workerData as WorkerInit;
const send = (m: FromWorker): void => port.postMessage(m);

/** A fresh instance of the core; its own messages on stderr are dropped (crashes are reported as outcomes). */
function instantiate(): Promise<IkCoreModule> {
  const options = {
    instantiateWasm(
      imports: WebAssembly.Imports,
      done: (instance: WebAssembly.Instance, module?: WebAssembly.Module) => void,
    ) {
      void WebAssembly.instantiate(init.wasmModule, imports).then((instance) => done(instance, init.wasmModule));
      return {};
    },
    printErr: () => undefined,
  };
  return loadIk(options);
}

const env: CaseEnv = {
  ik: await instantiate(),
  reload: instantiate,
  fixture: init.fixture,
  folder: modelFolder(init.fixture, init.worker),
  bases: await loadGltfBases(),
  seeds: readA7Seeds(),
};

port.on('message', (m: ToWorker) => {
  void runCase(
    env,
    m.id,
    (text) => send({ type: 'note', text }),
    () => send({ type: 'drawn' }),
  ).then((report) => send({ type: 'done', report }));
});
send({ type: 'ready' });

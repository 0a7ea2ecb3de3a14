// Messages between the case pool (main thread) and a fuzz worker thread.
import type { CaseId, CaseReport } from './case_id.js';
import type { Fixture } from './fixture.js';

/** What a worker gets at start. */
export interface WorkerInit {
  /** The core, compiled once by the main thread. */
  wasmModule: WebAssembly.Module;
  fixture: Fixture;
  /** This worker's number: its model folder is modelFolder(fixture, worker). */
  worker: number;
}

export type ToWorker = { type: 'run'; id: CaseId };

export type FromWorker =
  | { type: 'ready' }
  /** A part of the running case's description (sent before the part runs). */
  | { type: 'note'; text: string }
  /** The running case's input is drawn (a 16,385-bone rig takes seconds of test code): its hang limit starts again. */
  | { type: 'drawn' }
  | { type: 'done'; report: CaseReport };

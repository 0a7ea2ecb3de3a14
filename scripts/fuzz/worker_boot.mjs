// Entry of a fuzz worker thread: worker_threads do not inherit tsx's loader, so register it here
// and load the TypeScript worker.
import { tsImport } from 'tsx/esm/api';

await tsImport('./worker.ts', import.meta.url);

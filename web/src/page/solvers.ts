// The solver factory the page and the widget use: the WebAssembly solvers.
import { createWasmSolver } from './solver_adapter.js';
import type { SolverFactory } from './solver_port.js';

export const createSolver: SolverFactory = createWasmSolver;

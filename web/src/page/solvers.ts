// The solver factory the page and the widget use.
import { createInterimSolver } from './interim_solver.js';
import type { SolverFactory } from './solver_port.js';

export const createSolver: SolverFactory = createInterimSolver;

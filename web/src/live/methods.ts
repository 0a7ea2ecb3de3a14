// The solver methods of the loaded WebAssembly core, read once from its registry
// (IkSolver.methods / label / describe): no list of names lives in TypeScript, so a method
// registered in C++ shows up in the page's menu, plots and compare table and in the widget's menu.
import type { IkCoreModule } from '../ik/module.js';
import { IkSolver } from '../ik/solver.js';

export class MethodList {
  /** Method names in display order; the first (lm) is the default. */
  readonly names: readonly string[];
  private readonly labels: ReadonlyMap<string, string>;
  private readonly lines: ReadonlyMap<string, string>;

  constructor(module: IkCoreModule) {
    this.names = IkSolver.methods(module);
    if (this.names.length === 0) throw new Error('the WebAssembly core registers no solver method');
    this.labels = new Map(this.names.map((m) => [m, IkSolver.label(module, m)]));
    this.lines = new Map(this.names.map((m) => [m, IkSolver.describe(module, m)]));
  }

  /** The method used when none (or an unknown one) is asked for. */
  get default(): string {
    return this.names[0];
  }

  /** `name` if it is a registered method, else the default. */
  pick(name: string | null | undefined): string {
    return typeof name === 'string' && this.labels.has(name) ? name : this.default;
  }

  /** Position of `name` in display order (-1 if unknown). */
  indexOf(name: string): number {
    return this.names.indexOf(name);
  }

  /** A short human name ("Levenberg–Marquardt"); the name itself if unknown. */
  label(name: string): string {
    return this.labels.get(name) ?? name;
  }

  /** One line describing the method; '' if unknown. */
  describe(name: string): string {
    return this.lines.get(name) ?? '';
  }
}

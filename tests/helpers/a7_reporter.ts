// vitest reporter: one line after the run when the A7 folder is absent, counting the tests tagged
// A7_TAG that were skipped (or, under CI, failed) for it.
import type { Reporter, TestModule } from 'vitest/node';

import { A7_TAG, a7Dir, a7Present, a7Required } from './a7_folder.js';

export default class A7Reporter implements Reporter {
  onTestRunEnd(modules: ReadonlyArray<TestModule>): void {
    if (a7Present) return;
    let tests = 0;
    const files = new Set<string>();
    for (const module of modules)
      for (const test of module.children.allTests())
        if (test.tags.includes(A7_TAG)) {
          tests++;
          files.add(module.moduleId);
        }
    if (tests === 0) return;
    const count = (n: number, what: string): string => `${n} ${what}${n === 1 ? '' : 's'}`;
    const outcome = a7Required ? 'failed (CI is set)' : 'skipped';
    const what = `${count(tests, 'A7 test')} in ${count(files.size, 'file')} ${outcome}`;
    console.log(`A7 rigs not found at ${a7Dir}: ${what}; point IK_A7_DIR at the report's A7 rigs to run them`);
  }
}

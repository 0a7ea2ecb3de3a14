// vitest reporter: one line after the run per shared folder that is absent (the A7 rigs, the
// robots), counting the tests tagged with its tag that were skipped (or, under CI, failed) for it.
import type { Reporter, TestModule } from 'vitest/node';

import { a7Required } from '../../scripts/a7_folder.js';
import { sharedFolders } from './shared_folders.js';

export default class A7Reporter implements Reporter {
  onTestRunEnd(modules: ReadonlyArray<TestModule>): void {
    for (const folder of sharedFolders) {
      if (folder.present) continue;
      let tests = 0;
      const files = new Set<string>();
      for (const module of modules)
        for (const test of module.children.allTests())
          if (test.tags.includes(folder.tag)) {
            tests++;
            files.add(module.moduleId);
          }
      if (tests === 0) continue;
      const count = (n: number, what: string): string => `${n} ${what}${n === 1 ? '' : 's'}`;
      const outcome = a7Required ? 'failed (CI is set)' : 'skipped';
      const what = `${count(tests, folder.test)} in ${count(files.size, 'file')} ${outcome}`;
      console.log(`${folder.what} not found at ${folder.dir}: ${what}; ${folder.hint} to run them`);
    }
  }
}

import { defineConfig } from 'vitest/config';

import { A7_TAG, a7Present, a7Required } from './scripts/a7_folder.js';
import { ROBOTS_TAG, robotsPresent } from './tests/helpers/robots_folder.js';

export default defineConfig({
  test: {
    include: ['tests/**/*.test.ts'],
    exclude: ['tests/browser/**'],
    testTimeout: 60_000,
    hookTimeout: 60_000,
    // Tests tagged a7 read the report's A7 rigs, tests tagged robots the shared URDF robots:
    // skipped without them, failed under CI.
    tags: [
      { name: A7_TAG, description: "reads the report's A7 rigs ($IK_A7_DIR)", skip: !a7Present && !a7Required },
      {
        name: ROBOTS_TAG,
        description: 'reads the shared URDF robots ($IK_ROBOTS_DIR)',
        skip: !robotsPresent && !a7Required,
      },
    ],
    globalSetup: ['tests/helpers/test_rigs_setup.ts'],
    setupFiles: ['tests/helpers/a7_setup.ts'],
    reporters: ['default', './tests/helpers/a7_reporter.ts'],
  },
});

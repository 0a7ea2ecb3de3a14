// vitest setup file: under CI a test tagged A7_TAG without the A7 folder fails at once, naming
// the folder (without CI the tag's own option skips it: vitest.config.ts).
import { beforeEach } from 'vitest';

import { A7_TAG, a7MissingMessage, a7Present } from './a7_folder.js';

beforeEach(({ task }) => {
  if (!a7Present && task.tags?.includes(A7_TAG)) throw new Error(a7MissingMessage);
});

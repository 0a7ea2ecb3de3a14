// vitest setup file: under CI a test tagged with a shared folder's tag (A7_TAG, ROBOTS_TAG) without
// that folder fails at once, naming the folder (without CI the tag's own option skips it:
// vitest.config.ts).
import { beforeEach } from 'vitest';

import { sharedFolders } from './shared_folders.js';

beforeEach(({ task }) => {
  for (const folder of sharedFolders)
    if (!folder.present && task.tags?.includes(folder.tag)) throw new Error(folder.missingMessage);
});

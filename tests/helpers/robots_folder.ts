// Where the shared robot arms (URDF) are, and what to do without them, as a7_folder.ts does for the
// A7 rigs: the folder is $IK_ROBOTS_DIR, default ../shared/robots (from the repository root).
// Tests tagged ROBOTS_TAG read it: without the folder they are skipped, unless CI is set: then
// they fail with robotsMissingMessage. Imports nothing from vitest (vitest.config.ts reads it).
import { existsSync } from 'node:fs';
import { resolve } from 'node:path';

import { repoRoot } from '../../scripts/a7_folder.js';

export const robotsDir = resolve(repoRoot, process.env.IK_ROBOTS_DIR || '../shared/robots');
export const robotsPresent = existsSync(robotsDir);

/** The vitest tag of the tests that read the shared robots. */
export const ROBOTS_TAG = 'robots';

export const robotsMissingMessage = `robots folder missing: ${robotsDir} (CI is set; point IK_ROBOTS_DIR at the shared URDF robots)`;

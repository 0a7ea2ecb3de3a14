// Where the report's A7 rigs are, and what to do without them; shared by the test helpers and by
// vitest.config.ts (so it imports nothing from vitest). The folder is $IK_A7_DIR, default
// ../shared/rigs/a7, a relative path starting at the repository root. Tests tagged A7_TAG read it:
// without the folder they are skipped, unless the CI environment variable is set (CI has the
// folder, so nothing may be skipped there): then they fail with a7MissingMessage.
import { existsSync } from 'node:fs';
import { resolve } from 'node:path';

export const repoRoot = resolve(import.meta.dirname, '..');
export const a7Dir = resolve(repoRoot, process.env.IK_A7_DIR || '../shared/rigs/a7');
export const a7Present = existsSync(a7Dir);
export const a7Required = Boolean(process.env.CI);

/** The vitest tag of the tests that read the A7 rigs (or the report's paper folder beside them). */
export const A7_TAG = 'a7';

export const a7MissingMessage = `A7 rigs folder missing: ${a7Dir} (CI is set; point IK_A7_DIR at the report's A7 rigs)`;

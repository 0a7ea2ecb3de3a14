// vitest global setup: writes the project's rigs in A7 format (build/test-rigs, from the current
// models) once before any suite reads them through tests/helpers/a7.ts.
import { writeTestRigs } from '../../scripts/write-test-rigs.js';

export default async function setup(): Promise<void> {
  await writeTestRigs();
}

// The folders from ../shared that some tests read (the report's A7 rigs, the robot arms), for the
// setup file and the reporter: a test tagged with a folder's tag fails under CI without it
// (a7_setup.ts) and is skipped otherwise (vitest.config.ts), and one line after the run counts
// those tests (a7_reporter.ts).
import { A7_TAG, a7Dir, a7MissingMessage, a7Present } from '../../scripts/a7_folder.js';
import { ROBOTS_TAG, robotsDir, robotsMissingMessage, robotsPresent } from './robots_folder.js';

export interface SharedFolder {
  tag: string;
  dir: string;
  present: boolean;
  missingMessage: string;
  /** "A7 rigs": the line after the run reads "A7 rigs not found at DIR". */
  what: string;
  /** "A7 test": what one skipped test is called in that line. */
  test: string;
  /** "point IK_A7_DIR at the report's A7 rigs": how to run them. */
  hint: string;
}

export const sharedFolders: readonly SharedFolder[] = [
  {
    tag: A7_TAG,
    dir: a7Dir,
    present: a7Present,
    missingMessage: a7MissingMessage,
    what: 'A7 rigs',
    test: 'A7 test',
    hint: "point IK_A7_DIR at the report's A7 rigs",
  },
  {
    tag: ROBOTS_TAG,
    dir: robotsDir,
    present: robotsPresent,
    missingMessage: robotsMissingMessage,
    what: 'Robots (URDF)',
    test: 'robot test',
    hint: 'point IK_ROBOTS_DIR at the shared URDF robots',
  },
];

// Test helpers for the shared robot arms (../shared/robots, robots_folder.ts): their files and
// chains (the chains of the folder's README; Baxter's left hand is the link left_hand_link in this
// file), and the test option that skips a suite without the folder (and fails it under CI).
import { resolve } from 'node:path';

import { ROBOTS_TAG, robotsDir } from './robots_folder.js';

export { robotsDir };

/** Test options of a suite or test that reads the shared robots: describe(name, needsRobots, fn). */
export const needsRobots = { tags: [ROBOTS_TAG] };

export interface SharedRobot {
  /** The file's base name: "panda". */
  name: string;
  /** "BASE:TIP". */
  chain: string;
  /** Moving joints in the chain. */
  dof: number;
}

export const sharedRobots: readonly SharedRobot[] = [
  { name: 'panda', chain: 'panda_link0:panda_link8', dof: 7 },
  { name: 'baxter', chain: 'base:left_hand_link', dof: 7 },
  { name: 'pr2', chain: 'torso_lift_link:r_wrist_roll_link', dof: 7 },
  { name: 'kinova', chain: 'j2s6s200_link_base:j2s6s200_end_effector', dof: 6 },
  { name: 'ur5_robot', chain: 'base_link:tool0', dof: 6 },
  { name: 'xarm7', chain: 'link_base:link_eef', dof: 7 },
];

export function robotPath(name: string): string {
  return resolve(robotsDir, `${name}.urdf`);
}

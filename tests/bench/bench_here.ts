// The bench command run in the test's own process (runCommand, what cli.ts calls), its output
// captured: what the command-line tests of tests/bench share.
import { runCommand } from '../../bench-node/command.js';

/** What a run of the command gave: its exit code, stdout and stderr. */
export interface Outcome {
  code: number;
  stdout: string;
  stderr: string;
}

/** The command run in this process on `args`, its output captured (stderr is no terminal). */
export async function benchHere(...args: string[]): Promise<Outcome> {
  const out = { stdout: '', stderr: '' };
  const code = await runCommand(args, { out: (t) => (out.stdout += t), err: (t) => (out.stderr += t), isTTY: false });
  return { code, ...out };
}

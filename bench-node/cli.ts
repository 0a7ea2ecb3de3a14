// `npm run bench -- [options]`: benchmarks the IK methods on the report's target sets and prints a
// table per rig and experiment. See bench-node/README.md for the options, metrics and peers.
import { runCommand } from './command.js';

process.exitCode = await runCommand(process.argv.slice(2));

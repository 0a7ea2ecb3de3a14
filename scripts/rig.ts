// `npm run rig -- FILE [--json]`: prints what the rig importer makes of a file (scripts/rig_inspect.ts).
import { runRigInspect } from './rig_inspect.js';

process.exitCode = await runRigInspect(process.argv.slice(2));

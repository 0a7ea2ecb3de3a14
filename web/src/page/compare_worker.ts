// The compare worker: loads the WebAssembly core once, and for each CompareRequest builds a session
// on the rig, solves from the same start with every method in turn, and posts a 'started' before
// and a 'row' after each method, then 'done'. The page stays responsive meanwhile; cancelling a
// compare terminates the worker (compare_methods.ts makes a new one for the next).
import { loadIk, type IkCoreModule } from '../ik/module.js';
import { errorText } from '../live/error_text.js';
import { IkSession } from '../live/session.js';
import { applyRequest, type CompareReply, type CompareRequest, type CompareRow } from './compare_messages.js';

let core: Promise<IkCoreModule> | null = null;

/** The worker's scope, typed as a worker's (the project's lib is the DOM's). */
const scope = globalThis as unknown as {
  postMessage(message: CompareReply): void;
  addEventListener(type: 'message', f: (e: MessageEvent<CompareRequest>) => void): void;
};

const reply = (message: CompareReply): void => scope.postMessage(message);

async function compare(request: CompareRequest): Promise<void> {
  const { id } = request;
  let session: IkSession;
  try {
    core ??= loadIk();
    session = new IkSession(await core, request.spec);
  } catch (e) {
    reply({ type: 'failed', id, message: errorText(e) });
    return;
  }
  try {
    applyRequest(session, request);
    request.methods.forEach((method, index) => {
      reply({ type: 'started', id, method, index });
      let row: CompareRow;
      try {
        const outcome = session.trySolve(method, request.settings, request.start);
        row = { method, outcome, history: session.history(method), error: null };
      } catch (e) {
        row = { method, outcome: null, history: null, error: errorText(e) };
      }
      reply({ type: 'row', id, row });
    });
    reply({ type: 'done', id });
  } catch (e) {
    reply({ type: 'failed', id, message: errorText(e) });
  } finally {
    session.dispose();
  }
}

scope.addEventListener('message', (e) => void compare(e.data));

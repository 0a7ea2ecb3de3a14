// Sorting a thrown value into crash, unclear error or clear error.
import type { Outcome } from './outcome.js';

/**
 * Messages that tell the user nothing about their input: engine and embind internals, C++
 * exceptions and WebAssembly traps that leaked through.
 */
const UNCLEAR_MESSAGES = [
  'Offset is outside the bounds',
  'Maximum call stack',
  'Cannot convert undefined or null',
  'Cannot pass non-string',
  'bad_alloc',
  'vector',
  'memory access out of bounds',
  'table index',
  'unreachable',
  'RuntimeError',
  'Aborted(',
  'Cannot read properties of',
  'is not a function',
  'is not iterable',
  'Invalid array length',
  'Invalid typed array length',
  'Array buffer allocation failed',
  'Cannot mix BigInt',
];

/** Messages the fuzzer's own hostile callbacks throw: passing them on is the right answer. */
export const FUZZ_THROW = 'fuzz: the caller threw';

/** WebAssembly.Exception (a C++ exception thrown with native WebAssembly exceptions), where the engine has it. */
const WasmException = (WebAssembly as unknown as { Exception?: abstract new () => object }).Exception;

/**
 * The outcome of a call that threw `e`. `file` (file cases): a clear message must name it.
 * A WebAssembly trap or exception, or anything thrown that is not an Error, is a crash.
 */
export function classifyThrown(e: unknown, file?: string): Outcome {
  if (e instanceof WebAssembly.RuntimeError)
    return { kind: 'crash', message: `WebAssembly.RuntimeError: ${e.message}` };
  if (WasmException && e instanceof WasmException)
    return { kind: 'crash', message: 'a WebAssembly.Exception (a C++ exception) escaped' };
  if (!(e instanceof Error)) return { kind: 'crash', message: `threw a non-Error: ${typeof e} ${describeValue(e)}` };
  const message = `${e.name}: ${e.message}`;
  if (e.message.includes(FUZZ_THROW)) return { kind: 'clear', message };
  if (e.message.trim() === '' || UNCLEAR_MESSAGES.some((m) => e.message.includes(m)))
    return { kind: 'unclear', message };
  if (file !== undefined && !e.message.includes(file))
    return { kind: 'unclear', message: `${message} (does not name the file ${file})` };
  return { kind: 'clear', message };
}

function describeValue(v: unknown): string {
  try {
    return String(v).slice(0, 80);
  } catch {
    return '(cannot be printed)';
  }
}

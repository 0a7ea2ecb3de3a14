// The one error type the command line reports as a single line on stderr (exit code 2 for usage
// errors, 1 otherwise), and helpers that keep its messages on one line. Anything else escaping is a
// bug and prints its stack.
export class BenchError extends Error {
  override name = 'BenchError';
  constructor(
    message: string,
    readonly exitCode = 1,
  ) {
    super(message);
  }
}

/**
 * The first line of a caught error's message. A thrown non-Error (the WebAssembly core's C++
 * exceptions that carry no message, such as running out of memory) is described as such.
 */
export function errorLine(e: unknown): string {
  if (e instanceof Error) return e.message.split('\n')[0];
  return `an exception without a message (${Object.prototype.toString.call(e)}; out of memory?)`;
}

/** A value as a message shows it: quoted, escaped (no line breaks), and cut to 60 characters. */
export function quote(value: string): string {
  return JSON.stringify(value.length > 60 ? `${value.slice(0, 57)}...` : value);
}

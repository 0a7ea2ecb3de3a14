// The one error type the command line reports as a single line on stderr (exit code 2 for usage
// errors, 1 otherwise). Anything else escaping is a bug and prints its stack.
export class BenchError extends Error {
  override name = 'BenchError';
  constructor(
    message: string,
    readonly exitCode = 1,
  ) {
    super(message);
  }
}

// The error every rig importer (A7 JSON, glTF, URDF) throws for a file it cannot read: its message
// starts with the file's name and names the field or bone at fault.

export class RigFormatError extends Error {
  override name = 'RigFormatError';
}

/** Throws a RigFormatError whose message starts with the file name. */
export function failIn(file: string, what: string): never {
  throw new RigFormatError(`${file}: ${what}`);
}

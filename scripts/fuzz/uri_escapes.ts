// Buffer uris that lead outside the model folder (to the sentinel beside it, to absolute paths,
// hosts and devices), and side files inside it that are no regular file of sane size.
import type { Entry } from './folder.js';
import type { Fixture } from './fixture.js';

export interface SideFile {
  uri: string;
  /** What the folder must hold for the uri (links, FIFOs...). */
  entries: Entry[];
  text: string;
}

/** Every way out of the folder the fuzzer knows; a load through any of them must fail. */
export function uriEscapes(fixture: Fixture): SideFile[] {
  const abs = fixture.sentinel;
  const plain = (uri: string, text = uri): SideFile => ({ uri, entries: [], text });
  return [
    plain('../sentinel.bin'),
    plain('%2e%2e%2fsentinel.bin'),
    plain('..%2Fsentinel.bin'),
    plain('%2E%2E/sentinel.bin'),
    plain('./../sentinel.bin'),
    plain('sub/../../sentinel.bin'),
    plain('../sentinel.bin?x=1'),
    plain(abs, 'the absolute path of the sentinel'),
    plain(encodeURIComponent(abs), 'the encoded absolute path of the sentinel'),
    plain(`file://${abs}`, 'file:// and the sentinel'),
    plain(`//localhost${abs}`, '//localhost and the sentinel'),
    plain('//host/share/sentinel.bin'),
    plain('\\\\host\\share\\sentinel.bin'),
    plain('C:\\sentinel.bin'),
    plain('C:/sentinel.bin'),
    plain('http://127.0.0.1:9/sentinel.bin'),
    plain('/dev/zero'),
    plain('/proc/self/environ'),
    {
      uri: 'link.bin',
      entries: [{ kind: 'symlink', name: 'link.bin', target: abs }],
      text: 'link.bin, a link to the sentinel',
    },
    {
      uri: 'rel.bin',
      entries: [{ kind: 'symlink', name: 'rel.bin', target: '../sentinel.bin' }],
      text: 'rel.bin, a link to ../sentinel.bin',
    },
    {
      uri: 'up/sentinel.bin',
      entries: [{ kind: 'symlink', name: 'up', target: '..' }],
      text: 'up/sentinel.bin, up a link to ..',
    },
    {
      uri: 'zero.bin',
      entries: [{ kind: 'symlink', name: 'zero.bin', target: '/dev/zero' }],
      text: 'zero.bin, a link to /dev/zero',
    },
  ];
}

/** Side files inside the folder that no load may read: a FIFO, a folder, a sparse file past the size limit. */
export function hostileSideFiles(): SideFile[] {
  return [
    { uri: 'fifo.bin', entries: [{ kind: 'fifo', name: 'fifo.bin' }], text: 'fifo.bin, a FIFO' },
    { uri: 'dir.bin', entries: [{ kind: 'dir', name: 'dir.bin' }], text: 'dir.bin, a folder' },
    {
      uri: 'big.bin',
      entries: [{ kind: 'sparse', name: 'big.bin', size: 600 * 2 ** 20 }],
      text: 'big.bin, a 600 MiB sparse file',
    },
  ];
}

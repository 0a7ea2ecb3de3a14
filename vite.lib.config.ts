import { readFileSync } from 'node:fs';
import { dirname, join, relative, resolve } from 'node:path';

import ts from 'typescript';
import { defineConfig, type Plugin } from 'vite';

// The three.js package (web/src/lib/): `npm run build` writes dist/lib/, a folder `npm pack` or
// `npm publish` takes as it is:
//   index.js (ES module; three.js stays an import, a peer dependency), index.d.ts and the other
//   declarations it names, ik_core.wasm (fetched beside index.js), package.json,
//   avatar-example.html and models/character.glb (the example, run from node_modules/ik-web-avatar/).
// Build: npx vite build --config vite.lib.config.ts

const root = import.meta.dirname;
const entry = resolve(root, 'web/src/lib/index.ts');
const wasmFile = resolve(root, 'web/src/ik/generated/ik_core.wasm');

/**
 * The Emscripten glue finds its .wasm with new URL("ik_core.wasm", import.meta.url). Library mode
 * would inline the .wasm there as base64 (a third larger, compiled only once wholly downloaded): the
 * URL is kept as it is, and the .wasm emitted beside index.js, where it points once bundled. The
 * output drops the comments that kept vite from resolving these URLs, so that an app's bundler
 * (vite, webpack) finds them and ships the .wasm with the app.
 */
function wasmBesideModule(): Plugin {
  return {
    name: 'ik-wasm-beside-module',
    enforce: 'pre',
    transform(code, id) {
      if (!id.endsWith('ik_core.mjs')) return null;
      const out = code.replace(
        /new URL\(\s*(["'])ik_core\.wasm\1\s*,\s*import\.meta\.url\s*\)/g,
        'new URL(/* @vite-ignore */ "ik_core.wasm", import.meta.url)',
      );
      // A new Emscripten may spell it differently: fail rather than ship the .wasm inlined.
      if (out === code)
        this.error(
          'ik_core.mjs: new URL("ik_core.wasm", import.meta.url) was not found; update wasmBesideModule() for this Emscripten',
        );
      return { code: out, map: null };
    },
    renderChunk(code) {
      return { code: code.replaceAll('/* @vite-ignore */', ''), map: null };
    },
    generateBundle() {
      this.emitFile({ type: 'asset', fileName: 'ik_core.wasm', source: readFileSync(wasmFile) });
    },
  };
}

/**
 * The declarations of index.ts and of every file of web/src/lib/ its types name (tsc, tsconfig.lib.json),
 * beside index.js. The public API names only three.js and web/src/lib/: a declaration that imports
 * from elsewhere in the project fails the build (keep internal types out of public signatures).
 */
function packageTypes(): Plugin {
  return {
    name: 'ik-package-types',
    generateBundle() {
      const config = ts.getParsedCommandLineOfConfigFile(
        resolve(root, 'tsconfig.lib.json'),
        {},
        {
          ...ts.sys,
          onUnRecoverableConfigFileDiagnostic: (d) => this.error(ts.flattenDiagnosticMessageText(d.messageText, '\n')),
        },
      )!;
      const program = ts.createProgram(config.fileNames, config.options);
      const libDir = dirname(entry);
      const queue = [entry];
      for (const source of queue) {
        let text = '';
        const emitted = program.emit(program.getSourceFile(source), (_, data) => (text = data), undefined, true);
        const problems = [...ts.getPreEmitDiagnostics(program, program.getSourceFile(source)), ...emitted.diagnostics];
        if (problems.length)
          this.error(
            ts.formatDiagnostics(problems, {
              ...ts.sys,
              getCanonicalFileName: (f) => f,
              getCurrentDirectory: () => root,
              getNewLine: () => '\n',
            }),
          );
        const fileName = relative(libDir, source).replace(/\.ts$/, '.d.ts');
        for (const [, , spec] of text.matchAll(/(?:from |import\()(['"])(\.[^'"]*)\1/g)) {
          const target = resolve(dirname(source), spec.replace(/\.js$/, '.ts'));
          if (dirname(target) !== libDir)
            this.error(`${fileName} names ${spec}: the package's types may name only three.js and web/src/lib/`);
          if (!queue.includes(target)) queue.push(target);
        }
        this.emitFile({ type: 'asset', fileName, source: text });
      }
    },
  };
}

/** package.json (version from the root one), the example page and its model. */
function packageFiles(): Plugin {
  const { version } = JSON.parse(readFileSync(resolve(root, 'package.json'), 'utf8')) as { version: string };
  const manifest = {
    name: 'ik-web-avatar',
    version,
    description:
      'A humanoid three.js character driven by its head and hands: inverse kinematics in WebAssembly (C++/Eigen)',
    type: 'module',
    main: './index.js',
    types: './index.d.ts',
    exports: { '.': { types: './index.d.ts', default: './index.js' }, './ik_core.wasm': './ik_core.wasm' },
    sideEffects: false,
    keywords: ['three', 'threejs', 'ik', 'inverse-kinematics', 'avatar', 'vr', 'webxr', 'webassembly', 'gltf', 'vrm'],
    peerDependencies: { three: '>=0.160.0' },
    engines: { node: '>=20.16' },
  };
  return {
    name: 'ik-package-files',
    generateBundle() {
      this.emitFile({ type: 'asset', fileName: 'package.json', source: `${JSON.stringify(manifest, null, 2)}\n` });
      this.emitFile({
        type: 'asset',
        fileName: 'avatar-example.html',
        source: readFileSync(join(root, 'web/avatar-example.html')),
      });
      this.emitFile({
        type: 'asset',
        fileName: 'models/character.glb',
        source: readFileSync(join(root, 'web/public/models/character.glb')),
      });
    },
  };
}

export default defineConfig({
  publicDir: false,
  plugins: [wasmBesideModule(), packageTypes(), packageFiles()],
  build: {
    outDir: resolve(root, 'dist/lib'),
    emptyOutDir: true,
    target: 'es2022',
    lib: { entry, formats: ['es'], fileName: () => 'index.js' },
    rollupOptions: { external: [/^three($|\/)/] },
  },
});

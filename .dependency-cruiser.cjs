// The layers of the TypeScript tree (npm test runs `npm run lint:deps`). An arrow may only point
// down this list, never up, and no module may take part in a cycle:
//   web/src/ik      the JavaScript API over the WebAssembly core
//   web/src/rig     the rig importers (a7/, gltf/, humanoid/, anatomy/, urdf/)
//   web/src/live    the renderer-free live layer (session, solvers, goals, poles)
//   web/src/avatar  a whole body from tracked points (renderer-free)
//   web/src/view    all three.js code: stage, gizmos, rig view, pose write-back, the live controller
//   web/src/page, web/src/widget, web/src/lib   the front ends (the page, <ik-widget>, the package)
// bench-node/ and scripts/ use the shared library below the front ends by name (#ik/, #rig/, ...);
// product code never imports tests/.
const layers = ['ik', 'rig', 'live', 'avatar', 'view'];
const above = (i) => [...layers.slice(i + 1), 'page', 'widget', 'lib'].join('|');

/** @type {import('dependency-cruiser').IConfiguration} */
module.exports = {
  forbidden: [
    ...layers.map((layer, i) => ({
      name: `${layer}-imports-upward`,
      comment: `web/src/${layer} may import only the layers below it`,
      severity: 'error',
      from: { path: `^web/src/${layer}/` },
      to: { path: `^web/src/(${above(i)})/` },
    })),
    {
      name: 'renderer-free',
      comment: 'ik, rig, live and avatar run without three.js (in Node, in workers)',
      severity: 'error',
      from: { path: '^web/src/(ik|rig|live|avatar)/' },
      to: { path: '^node_modules/(three|@types/three)/' },
    },
    {
      name: 'front-ends-apart',
      comment: 'the page, the widget and the package do not import each other',
      severity: 'error',
      from: { path: '^web/src/(page|widget|lib)/' },
      to: { path: '^web/src/(page|widget|lib)/', pathNot: '^web/src/$1/' },
    },
    {
      name: 'tools-use-the-library',
      comment: 'bench-node and scripts use the shared library, not the front ends',
      severity: 'error',
      from: { path: '^(bench-node|scripts)/' },
      to: { path: '^web/src/(page|widget|lib)/' },
    },
    {
      name: 'tools-import-by-name',
      comment: 'bench-node and scripts import the shared library by name (#ik/, #rig/, ...: package.json imports), not by a path into web/',
      severity: 'error',
      from: { path: '^(bench-node|scripts)/' },
      to: { path: '^web/src/', dependencyTypesNot: ['aliased-subpath-import'] },
    },
    {
      name: 'product-not-tests',
      comment: 'product code and commands never import test code',
      severity: 'error',
      from: { pathNot: '^tests/' },
      to: { path: '^tests/' },
    },
    {
      name: 'bench-not-scripts',
      comment: 'scripts may use bench-node, not the other way round',
      severity: 'error',
      from: { path: '^bench-node/' },
      to: { path: '^scripts/' },
    },
    {
      name: 'no-cycles',
      severity: 'error',
      from: {},
      to: { circular: true },
    },
  ],
  options: {
    doNotFollow: { path: 'node_modules' },
    exclude: { path: '(^|/)generated/' },
    tsConfig: { fileName: 'tsconfig.json' },
    tsPreCompilationDeps: true,
    enhancedResolveOptions: { exportsFields: ['exports'], conditionNames: ['import', 'require', 'node', 'default'], extensions: ['.ts', '.mts', '.js', '.mjs', '.d.ts'] },
  },
};

// ESLint for the TypeScript tree (npm run lint; npm test runs it): the recommended rules of ESLint
// and typescript-eslint. Formatting is Prettier's (.prettierrc.json), not ESLint's.
import js from '@eslint/js';
import tseslint from 'typescript-eslint';

export default tseslint.config(
  { ignores: ['node_modules/', 'build/', 'dist/', 'web/src/ik/generated/', 'test-results/', '**/*.js', '**/*.cjs', '**/*.mjs'] },
  js.configs.recommended,
  ...tseslint.configs.recommended,
  {
    // Small files about one idea, functions that read as named steps: the product and the bench
    // keep under these (code lines, not blanks or comments). The fuzz's and the model scripts'
    // case tables are long lists and are not held to them.
    files: ['web/src/**/*.ts', 'bench-node/**/*.ts'],
    rules: {
      'max-lines-per-function': ['error', { max: 80, skipBlankLines: true, skipComments: true }],
      'max-lines': ['error', { max: 400, skipBlankLines: true, skipComments: true }],
    },
  },
  {
    rules: {
      // A leading underscore marks what is unused on purpose (a destructured part left out, a callback's argument).
      '@typescript-eslint/no-unused-vars': ['error', { argsIgnorePattern: '^_', varsIgnorePattern: '^_', destructuredArrayIgnorePattern: '^_' }],
    },
  },
);

import { resolve } from 'node:path';
import { defineConfig } from 'vite';

// The page lives in web/; `npm start` serves it.
export default defineConfig({
  root: resolve(import.meta.dirname, 'web'),
  publicDir: resolve(import.meta.dirname, 'web/public'),
  server: { port: 5173, strictPort: false },
  build: { outDir: resolve(import.meta.dirname, 'dist/web'), emptyOutDir: true, target: 'es2022' },
});

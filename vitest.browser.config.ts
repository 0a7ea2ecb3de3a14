import { defineConfig } from 'vitest/config';

// Browser tests: playwright-core drives the system Chromium against a vite server each file
// starts and stops itself. Run: npx vitest run --config vitest.browser.config.ts
export default defineConfig({
  test: {
    include: ['tests/browser/**/*.test.ts'],
    testTimeout: 60_000,
    hookTimeout: 120_000,
    fileParallelism: false,
  },
});

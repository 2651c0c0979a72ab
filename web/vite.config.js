// The dashboard's front-end, served by the solver itself (`poresph run --serve`, `poresph serve`).
import { defineConfig } from 'vite';

export default defineConfig({
  base: './',
  build: { chunkSizeWarningLimit: 4000, sourcemap: false },
});

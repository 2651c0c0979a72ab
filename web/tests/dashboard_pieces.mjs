// The dashboard's 3D view shows every particle of extracts written in pieces by a run over two
// processes (.pvtp and its pieces) and of extracts written as unstructured grids (.vtu), through
// `poresph serve` in Debian's Chromium: the legend counts the run's particles, for each extract.
//   node tests/dashboard_pieces.mjs POREPSH_BINARY MPIEXEC CASE WORKDIR
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { launch, startPoresph, until } from './browser.mjs';

const [binary, mpiexec, caseFile, work] = process.argv.slice(2);
fs.mkdirSync(work, { recursive: true });
const sets = ['--set', 'time.end=0.02', '--set', 'output.extract_interval=0.01', '--quiet'];
const env = {
  ...process.env, OMP_NUM_THREADS: '1', OMPI_ALLOW_RUN_AS_ROOT: '1', OMPI_ALLOW_RUN_AS_ROOT_CONFIRM: '1',
  OMPI_MCA_rmaps_base_oversubscribe: '1', OMPI_MCA_mpi_yield_when_idle: '1',
};
const runs = {
  pieces: [mpiexec, ['-n', '2', binary, 'run', caseFile, ...sets], '.pvtp'],
  grids: [binary, ['run', caseFile, ...sets, '--set', 'output.extract_format=vtu'], '.vtu'],
};

const browser = await launch();
let failed = false;
try {
  for (const [name, [program, args, extension]] of Object.entries(runs)) {
    const out = path.join(work, name);
    fs.rmSync(out, { recursive: true, force: true });
    execFileSync(program, [...args, '--out', out], { stdio: 'ignore', env });
    const particles = JSON.parse(fs.readFileSync(path.join(out, 'summary.json'), 'utf8')).particles;
    const files = fs.readdirSync(path.join(out, 'extracts')).filter((f) => f.endsWith(extension));
    assert.ok(files.length >= 2, `${name}: extracts ${fs.readdirSync(path.join(out, 'extracts'))}`);
    const server = await startPoresph(binary, ['serve', out, '--port', '0']);
    try {
      const page = await browser.newPage({ viewport: { width: 1280, height: 1000 } });
      await page.goto(server.url);
      for (const index of [0, files.length - 1]) {
        await until(`${name}: extract ${index}`, async () => (await page.locator('#extract-select option').count()) === files.length);
        await page.locator('#extract-select').selectOption(String(index));
        await until(`${name}: extract ${index} in the 3D view`,
          async () => (await page.locator('#legend').textContent()).endsWith(`of ${particles} particles`));
      }
      console.log(`${name}: ${files.length} ${extension} extracts, each with its ${particles} particles in the 3D view`);
    } finally {
      server.child.kill('SIGTERM');
    }
  }
} catch (e) {
  failed = true;
  console.error(e.message);
} finally {
  await browser.close();
}
process.exit(failed ? 1 : 0);

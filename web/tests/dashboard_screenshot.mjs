// The page of a finished run (`poresph serve`) against a baseline screenshot, with the text that
// changes from run to run (wall times, speed, the machine's name) masked. pixelmatch (YIQ
// threshold 0.1, anti-aliased pixels ignored) with a budget of 0.5 % of the pixels; on failure
// the page and the difference are written beside the run.
//   node tests/dashboard_screenshot.mjs POREPSH_BINARY CASE WORKDIR BASELINE.png
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import pixelmatch from 'pixelmatch';
import { PNG } from 'pngjs';
import { launch, startPoresph, until } from './browser.mjs';

const [binary, caseFile, work, baseline] = process.argv.slice(2);
const BUDGET = 0.005;
fs.mkdirSync(work, { recursive: true });
const out = path.join(work, 'finished');
fs.rmSync(out, { recursive: true, force: true });
// A short run to its end (the live test's case, stopped at 0.03 s), every frame drawn (frames 0-3:
// the render thread would otherwise drop those it has no time for).
const short = path.join(work, 'finished.toml');
fs.writeFileSync(short, fs.readFileSync(caseFile, 'utf8').replace(/^end = .*$/m, 'end = 0.03')
  .replace(/^\[visualisation\]$/m, '[visualisation]\nevery_frame = true'));
execFileSync(binary, ['run', short, '--out', out, '--pipeline', 'phases', '--quiet'], { stdio: 'ignore', env: { ...process.env, OMP_NUM_THREADS: '1' } });

const server = await startPoresph(binary, ['serve', out, '--port', '0']);
const browser = await launch();
let failed = false;
try {
  const page = await browser.newPage({ viewport: { width: 1280, height: 1500 }, deviceScaleFactor: 1 });
  await page.goto(server.url);
  await until('the finished state', async () => (await page.locator('#state').textContent()) === 'completed');
  await until('the last frame', async () => (await page.locator('#frame-label').textContent()).startsWith('frame 3 '));
  await until('its image', () => page.evaluate(() => [...document.querySelectorAll('#images img')].every((i) => i.complete && i.naturalWidth > 0)));
  await until('the last extract in the 3D view', async () => (await page.locator('#extract-select').inputValue()) === '1'
    && (await page.locator('#legend').textContent()).includes('particles'));
  await page.waitForTimeout(500);
  const shot = await page.screenshot({
    fullPage: true,
    mask: ['#elapsed', '#sps', '#left', '#device'].map((s) => page.locator(s)),
  });
  const actual = PNG.sync.read(shot);
  const name = path.basename(baseline, '.png');
  if (!fs.existsSync(baseline)) {
    fs.writeFileSync(path.join(work, `${name}.png`), shot);
    throw new Error(`no baseline ${baseline}; the page is in ${path.join(work, `${name}.png`)}`);
  }
  const expected = PNG.sync.read(fs.readFileSync(baseline));
  assert.deepEqual([actual.width, actual.height], [expected.width, expected.height], 'page size differs from the baseline');
  const diff = new PNG({ width: actual.width, height: actual.height });
  const bad = pixelmatch(actual.data, expected.data, diff.data, actual.width, actual.height, { threshold: 0.1 });
  const share = bad / (actual.width * actual.height);
  console.log(`screenshot: ${bad} pixels differ (${(100 * share).toFixed(3)} %, budget ${100 * BUDGET} %)`);
  if (share > BUDGET) {
    fs.writeFileSync(path.join(work, `${name}.png`), shot);
    fs.writeFileSync(path.join(work, `${name}.diff.png`), PNG.sync.write(diff));
    throw new Error(`the page differs from ${baseline} in ${(100 * share).toFixed(3)} % of its pixels; see ${work}`);
  }
} catch (e) {
  failed = true;
  console.error(e.message);
} finally {
  await browser.close();
  server.child.kill('SIGTERM');
}
process.exit(failed ? 1 : 0);

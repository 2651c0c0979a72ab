// The dashboard of a short real run, in a real browser: status updates, a new frame arrives, the
// timeline moves, the 3D colouring changes, pause really pauses the solver, resume, the output
// cadence changes, stop (with a final checkpoint); a second browser that closes does not stop the
// run; `poresph serve` attached from another process shows it and controls it.
//   node tests/dashboard_live.mjs POREPSH_BINARY CASE WORKDIR
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { exited, launch, sleep, startPoresph, until } from './browser.mjs';

const [binary, caseFile, work] = process.argv.slice(2);
const out = path.join(work, 'live');
fs.rmSync(out, { recursive: true, force: true });
const status = () => JSON.parse(fs.readFileSync(path.join(out, 'status.json'), 'utf8'));

const run = await startPoresph(binary, ['run', caseFile, '--out', out, '--serve', '0', '--pipeline', 'phases', '--quiet']);
const browser = await launch();
let failed = false;
try {
  const page = await browser.newPage({ viewport: { width: 1280, height: 1500 } });
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  page.on('dialog', (d) => d.accept());
  await page.goto(run.url);
  const text = (sel) => page.locator(sel).textContent();

  // Status: the case, the backend, a running state whose step advances.
  await until('state running', async () => (await text('#state')) === 'running');
  assert.equal(await text('#case-name'), 'dashboard_live');
  assert.match(await text('#device'), /^cpu · /);
  const step0 = Number(await text('#step'));
  await until('the step to advance', async () => Number(await text('#step')) > step0);
  console.log(`status updates: step ${step0} -> ${await text('#step')}`);
  // The density watch's warning (the case's bound is one the run passes at once).
  await until('the density warning', async () => (await text('#warnings')).startsWith("warning: the fluid's density is"));
  assert.ok(await page.locator('#warnings').isVisible());

  // A frame pushed after the page loaded, shown at once (the timeline follows the run).
  const framesAtLoad = await page.evaluate(() => window.dashboard.frames.frames.length);
  await until('a new frame', async () => (await page.evaluate(() => window.dashboard.frames.frames.length)) > framesAtLoad + 1);
  await until('the newest frame on show', async () => {
    const latest = await page.evaluate(() => window.dashboard.frames.frames.length - 1);
    return (await text('#frame-label')).startsWith(`frame ${latest} `);
  });
  const latest = await page.evaluate(() => window.dashboard.frames.frames.length - 1);
  await until('its image loaded', () => page.evaluate(() => [...document.querySelectorAll('#images img')].every((i) => i.complete && i.naturalWidth > 0)));
  console.log(`frames: ${framesAtLoad} at load, ${latest + 1} later`);

  // Timeline back to the first frame.
  await page.locator('#timeline').focus();
  await page.keyboard.press('Home');
  assert.match(await text('#frame-label'), /^frame 0 · step 0 /);
  assert.match(await page.locator('#images img').first().getAttribute('src'), /_000000\.png$/);

  // Play the sequence from the first frame.
  await page.locator('#play').click();
  await until('the sequence to play', async () => !(await text('#frame-label')).startsWith('frame 0 '), 10000);
  await page.locator('#play').click();

  // Charts: the monitors' groups, growing as rows arrive.
  const groups = await page.locator('#charts .chart').evaluateAll((els) => els.map((e) => e.dataset.group));
  assert.ok(groups.includes('Energies (J)') && groups.includes('Saturations'), groups.join());
  const rows = await page.evaluate(() => window.dashboard.charts.rows.length);
  await until('new monitor rows on the charts', async () => (await page.evaluate(() => window.dashboard.charts.rows.length)) > rows);

  // The 3D view: colour by another field; the legend and the picture change.
  await until('an extract in the 3D view', async () => (await text('#legend')).includes('particles'));
  // Pinned to the first extract, so that a new one arriving does not change the picture.
  await page.locator('#extract-select').selectOption('0');
  await until('the first extract on show', () => page.evaluate(() => window.dashboard.view.url.endsWith('particles_000000.vtp')));
  await sleep(300);
  const before = await page.locator('#view3d').screenshot();
  const fields = await page.locator('#field-select option').allTextContents();
  assert.ok(fields.includes('velocity') && fields.includes('pressure'), fields.join());
  const other = (await page.locator('#field-select').inputValue()) === 'velocity' ? 'pressure' : 'velocity';
  await page.locator('#field-select').selectOption(other);
  assert.equal(await page.locator('#legend').getAttribute('data-field'), other);
  assert.match(await text('#legend'), new RegExp(`^${other}: `));
  await sleep(300);
  assert.notDeepEqual(await page.locator('#view3d').screenshot(), before, 'the 3D view did not change with the field');
  // Hiding a phase leaves fewer particles.
  const count = async () => Number((await text('#legend')).match(/· (\d+) of/)[1]);
  const all = await count();
  await page.locator('#phases input').first().uncheck();
  assert.ok((await count()) < all, 'hiding a phase kept every particle');
  await page.locator('#phases input').first().check();
  // A slab keeps a band of them.
  await page.locator('#slab-axis').selectOption('y');
  await page.locator('#slab-on').check();
  const slab = await count();
  assert.ok(slab > 0 && slab < all / 2, `the slab kept ${slab} of ${all}`);
  await page.locator('#slab-on').uncheck();

  // `poresph serve` attached from another process: the same state, and control through it.
  const attached = await startPoresph(binary, ['serve', out, '--port', '0']);
  try {
    const base = attached.url.replace(/\?token=.*/, '');
    const token = attached.url.replace(/.*token=/, '');
    const st = await (await fetch(`${base}api/state`)).json();
    // The token is in no file the dashboard serves.
    for (const f of ['log.txt', 'status.json', 'summary.json', 'case.resolved.toml', 'monitors.csv']) {
      const r = await fetch(`${base}run/${f}`);
      if (r.ok) assert.ok(!(await r.text()).includes(token), `${f} holds the token`);
    }
    assert.equal(st.status.state, 'running');
    assert.equal(st.status.case, 'dashboard_live');
    const post = (action, t) => fetch(`${base}api/control`, {
      method: 'POST', headers: { 'X-Poresph-Token': t }, body: JSON.stringify({ action }),
    });
    assert.equal((await post('pause', 'wrong')).status, 403);
    assert.equal((await post('pause', token)).status, 202);
    await until('the run paused from the attached server', async () => status().state === 'paused');
    await until('the page to see it', async () => (await text('#state')) === 'paused');
    assert.equal((await post('resume', token)).status, 202);
    await until('the run running again', async () => status().state === 'running');
    await until('the page to see it', async () => (await text('#state')) === 'running');
  } finally {
    attached.child.kill('SIGTERM');
    assert.equal(await exited(attached.child), 0);
  }

  // A second browser comes and goes: the run carries on.
  const other_ = await browser.newContext();
  const p2 = await other_.newPage();
  await p2.goto(run.url);
  await until('the second page to connect', async () => (await p2.locator('#state').textContent()) === 'running');
  await other_.close();
  const s1 = status().step;
  await until('the run to go on without the second browser', async () => status().step > s1 + 5);

  // Pause: the solver's own step count stops.
  await page.locator('#pause').click();
  await until('state paused', async () => (await text('#state')) === 'paused');
  const paused = status().step;
  await sleep(1500);
  assert.equal(status().step, paused, 'the solver went on while paused');
  assert.equal(status().state, 'paused');
  assert.equal(Number(await text('#step')), paused);
  console.log(`paused at step ${paused}, still there 1.5 s later`);

  // Resume: it goes on.
  await page.locator('#resume').click();
  await until('state running again', async () => (await text('#state')) === 'running');
  await until('the step to advance after resume', async () => status().step > paused);

  // Output cadence: monitors every 5 ms from now on (the case says 2 ms).
  await page.locator('#controls summary').click();
  await page.locator('#cad-monitor').fill('0.005');
  await page.locator('#cadence').click();
  await until('the new monitor interval', async () => status().monitor_interval === 0.005);
  const since = status().time;
  const times = () => fs.readFileSync(path.join(out, 'monitors.csv'), 'utf8').trim().split('\n').slice(1)
    .map((l) => Number(l.split(',')[1])).filter((t) => t > since + 1e-9);
  await until('two monitor rows at the new cadence', async () => times().length >= 2, 60000);
  const [t1, t2] = times();
  assert.ok(Math.abs(t2 - t1 - 0.005) < 1e-9, `monitor rows ${t1}, ${t2}: not 5 ms apart`);

  // Stop: the final state reaches the page, the solver exits cleanly with a last checkpoint.
  await page.locator('#stop').click();
  await until('state stopped', async () => (await text('#state')) === 'stopped', 30000);
  assert.equal(await exited(run.child), 0);
  const final = status();
  assert.equal(final.state, 'stopped');
  const ckpts = fs.readdirSync(path.join(out, 'checkpoints'));
  assert.ok(ckpts.includes(`step_${String(final.step).padStart(10, '0')}.h5`), `no final checkpoint at step ${final.step}: ${ckpts}`);
  assert.equal(JSON.parse(fs.readFileSync(path.join(out, 'summary.json'), 'utf8')).status, 'stopped');
  assert.deepEqual(errors, []);
  console.log(`stopped at step ${final.step} with a checkpoint`);
} catch (e) {
  failed = true;
  console.error(e);
  console.error(run.output().slice(-3000));
} finally {
  await browser.close();
  if (run.child.exitCode === null) run.child.kill('SIGKILL');
}
process.exit(failed ? 1 : 0);

// poresph dashboard: a run's status, figures, particles and monitors, live over server-sent events.
import './style.css';
import { fetchState, materialNames, subscribe } from './api.js';
import { Charts } from './charts.js';
import { setupControls, updateControls } from './controls.js';
import { Frames } from './frames.js';
import { number } from './format.js';
import { showStatus } from './status.js';
import { View3D } from './view3d.js';

const $ = (id) => document.getElementById(id);

async function main() {
  const state = await fetchState();
  const names = await materialNames().catch(() => []);
  const app = { status: state.status, connected: false, canControl: state.control, extracts: [] };
  window.dashboard = app;  // for the browser tests and the curious

  setupControls();
  const refreshStatus = () => {
    showStatus(app.status, app.connected);
    updateControls(app.status, app.canControl);
  };
  refreshStatus();

  const frames = new Frames($('images'), $('timeline'), $('frame-label'), $('play'));
  state.frames.forEach((f) => frames.add(f));
  app.frames = frames;

  const charts = new Charts($('charts'));
  if (state.columns.length) charts.setColumns(state.columns);
  charts.addRows(state.rows);
  app.charts = charts;

  const view = new View3D($('view3d'), $('legend'));
  app.view = view;
  // One extract loads at a time; while one loads, the latest wanted waits.
  let loading = false;
  let wanted = -1;
  const loadExtract = async (index) => {
    wanted = index;
    $('extract-select').value = String(index);
    if (loading) return;
    loading = true;
    try {
      while (wanted >= 0) {
        const e = app.extracts[wanted];
        wanted = -1;
        try {
          showViewControls(await view.load(e.url));
        } catch (err) {
          $('legend').textContent = `extract ${e.index}: ${err.message}`;
        }
      }
    } finally {
      loading = false;
    }
  };
  const showViewControls = (fields) => {
    const select = $('field-select');
    if ([...select.options].map((o) => o.value).join() !== fields.join()) {
      select.replaceChildren(...fields.map((f) => new Option(f, f)));
    }
    select.value = view.field;
    const phases = $('phases');
    if (phases.childElementCount !== view.materials().length) {
      phases.replaceChildren(...view.materials().map((m) => {
        const label = document.createElement('label');
        const box = document.createElement('input');
        box.type = 'checkbox';
        box.checked = !view.hidden.has(m);
        box.dataset.material = String(m);
        box.addEventListener('change', () => view.setHidden(m, !box.checked));
        label.append(box, ` ${names[m] ?? `material ${m}`}`);
        return label;
      }));
    }
  };
  // A new extract is shown when the view follows the latest one.
  const addExtract = (e) => {
    const following = app.extracts.length === 0 || $('extract-select').value === String(app.extracts.length - 1);
    app.extracts.push(e);
    $('extract-select').append(new Option(`${e.index}: t = ${number(e.time)} s`, String(app.extracts.length - 1)));
    if (following) loadExtract(app.extracts.length - 1);
  };
  state.extracts.forEach(addExtract);
  $('extract-select').addEventListener('change', () => loadExtract(Number($('extract-select').value)));
  $('field-select').addEventListener('change', () => view.setField($('field-select').value));
  const slab = () => view.setSlab({
    on: $('slab-on').checked,
    axis: 'xyz'.indexOf($('slab-axis').value),
    position: Number($('slab-pos').value),
    width: Number($('slab-width').value),
  });
  for (const id of ['slab-on', 'slab-axis', 'slab-pos', 'slab-width']) $(id).addEventListener('input', slab);

  subscribe(state.last_event, {
    status: (s) => { app.status = s; refreshStatus(); },
    columns: (c) => charts.setColumns(c),
    monitors: (rows) => charts.addRows(rows),
    frame: (f) => frames.add(f),
    extract: (e) => addExtract(e),
  }, (ok) => { app.connected = ok; refreshStatus(); });
}

main().catch((e) => {
  $('state').textContent = 'error';
  $('diagnostic').hidden = false;
  $('diagnostic').textContent = `The dashboard could not start: ${e.message}`;
});

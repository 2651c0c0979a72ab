// Monitors over simulated time (uPlot), one chart per group of columns the run has, updated as
// rows arrive.
import uPlot from 'uplot';
import 'uplot/dist/uPlot.min.css';
import { number } from './format.js';

const GROUPS = [
  { title: 'Energies (J)', match: (c) => /_energy$/.test(c) },
  { title: 'Saturations', match: (c) => /^saturation_/.test(c) },
  { title: 'Porosity', match: (c) => c === 'porosity' },
  { title: 'Pressures (Pa)', match: (c) => /^(capillary_pressure|pressure_liquid|pressure_gas)$/.test(c) },
  { title: 'Pressures (MPa, physical)', match: (c) => /_MPa$/.test(c) },
  { title: 'Seepage velocities (m/s)', match: (c) => /^velocity_(liquid|gas)_/.test(c) },
  { title: 'Percolation time (s)', match: (c) => c === 'percolation_time' },
  { title: 'Damage', match: (c) => /damage/.test(c) || c === 'ghost_particles' },
  { title: 'Time step (s)', match: (c) => c === 'dt' },
];
const COLOURS = ['#1f77b4', '#d62728', '#2ca02c', '#ff7f0e', '#9467bd', '#8c564b'];

export class Charts {
  constructor(container) {
    this.container = container;
    this.columns = [];
    this.rows = [];
    this.charts = [];
  }

  setColumns(columns) {
    this.columns = columns;
    this.container.replaceChildren();
    this.charts = [];
    const t = columns.indexOf('time');
    for (const g of GROUPS) {
      const idx = columns.map((c, i) => (g.match(c) ? i : -1)).filter((i) => i >= 0);
      if (idx.length === 0 || t < 0) continue;
      const div = document.createElement('div');
      div.className = 'chart';
      div.dataset.group = g.title;
      this.container.appendChild(div);
      const opts = {
        title: g.title,
        width: 420,
        height: 220,
        scales: { x: { time: false } },
        axes: [
          { label: 'simulated time (s)', values: (u, vals) => vals.map((v) => number(v, 3)) },
          { size: 70, values: (u, vals) => vals.map((v) => number(v, 3)) },
        ],
        series: [{ label: 't' }, ...idx.map((i, k) => ({ label: columns[i], stroke: COLOURS[k % COLOURS.length], width: 1.5 }))],
      };
      this.charts.push({ columns: [t, ...idx], plot: new uPlot(opts, this.data([t, ...idx]), div) });
    }
  }

  data(cols) {
    return cols.map((c) => this.rows.map((r) => r[c]));
  }

  addRows(rows) {
    for (const r of rows) this.rows.push(r);
    for (const ch of this.charts) ch.plot.setData(this.data(ch.columns));
  }
}

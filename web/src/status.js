// The run's status panel: case, state (with a failure's diagnostic and the run's warnings), progress and speed.
import { number, seconds } from './format.js';

const $ = (id) => document.getElementById(id);

export function showStatus(s, connected) {
  if (!s) return;
  $('case-name').textContent = s.case;
  const state = s.state;
  $('state').textContent = state + (connected || !['running', 'paused', 'starting'].includes(state) ? '' : ' (no connection)');
  $('state').className = `state ${state}`;
  $('device').textContent = `${s.backend} · ${s.device} · ${s.precision} · ${s.dimension}D`;
  $('diagnostic').hidden = !s.diagnostic;
  $('diagnostic').textContent = s.diagnostic ? `${state}: ${s.diagnostic}` : '';
  const warnings = s.warnings || [];
  $('warnings').hidden = warnings.length === 0;
  $('warnings').textContent = warnings.map((w) => `warning: ${w}`).join('\n');
  $('step').textContent = String(s.step);
  $('time').textContent = `${number(s.time)} / ${number(s.end_time)} s`;
  $('dt').textContent = `${number(s.dt, 3)} s`;
  $('sps').textContent = s.state === 'running' ? number(s.steps_per_second, 3) : '–';
  $('elapsed').textContent = seconds(s.elapsed);
  $('left').textContent = s.state === 'running' ? seconds(s.time_left) : '–';
  $('particles').textContent = s.particles.toLocaleString('en');
  $('progress-bar').style.width = `${Math.min(100, (100 * s.time) / (s.end_time || 1))}%`;
  document.title = `${s.case} · ${state} · poresph`;
}

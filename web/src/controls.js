// Pause, resume, stop and output cadence, with the run's token (from ?token=, kept for the tab).
import { control } from './api.js';

const $ = (id) => document.getElementById(id);

export function setupControls() {
  const url = new URL(window.location.href);
  const fromUrl = url.searchParams.get('token');
  if (fromUrl) {
    sessionStorage.setItem('poresph-token', fromUrl);
    url.searchParams.delete('token');  // out of the address bar and the history
    window.history.replaceState(null, '', url.toString());
  }
  $('token').value = sessionStorage.getItem('poresph-token') || '';
  $('token').addEventListener('change', () => sessionStorage.setItem('poresph-token', $('token').value.trim()));

  const send = async (body, what) => {
    const token = $('token').value.trim();
    const r = await control(token, body);
    $('control-message').textContent = r.status === 202 ? `${what}: requested` : `${what}: refused (${r.status}: ${r.error || ''})`;
  };
  $('pause').addEventListener('click', () => send({ action: 'pause' }, 'pause'));
  $('resume').addEventListener('click', () => send({ action: 'resume' }, 'resume'));
  $('stop').addEventListener('click', () => {
    if (window.confirm('Stop the run (with a final checkpoint)?')) send({ action: 'stop' }, 'stop');
  });
  $('cadence').addEventListener('click', () => {
    const body = { action: 'cadence' };
    for (const [id, key] of [['cad-monitor', 'monitor_interval'], ['cad-extract', 'extract_interval'], ['cad-frames', 'visualisation_interval']]) {
      const v = Number($(id).value);
      if ($(id).value !== '' && v > 0) body[key] = v;
    }
    send(body, 'cadence');
  });
}

// Buttons that make sense in this state; the cadence fields show the run's intervals.
export function updateControls(status, canControl) {
  const live = status && ['starting', 'running', 'paused'].includes(status.state);
  $('controls').hidden = !canControl;
  $('pause').disabled = !live || status.state === 'paused';
  $('resume').disabled = !live || status.state !== 'paused';
  $('stop').disabled = !live;
  $('cadence').disabled = !live;
  if (!status) return;
  for (const [id, v] of [['cad-monitor', status.monitor_interval], ['cad-extract', status.extract_interval], ['cad-frames', status.visualisation_interval]]) {
    if (document.activeElement !== $(id)) $(id).placeholder = String(v);
  }
}

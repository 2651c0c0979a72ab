// The solver's dashboard API (solver/dashboard/dashboard_server.hpp).
export async function fetchState() {
  const r = await fetch('api/state', { cache: 'no-store' });
  if (!r.ok) throw new Error(`api/state: HTTP ${r.status}`);
  return r.json();
}

// Server-sent events after event number `since`; the browser reconnects by itself, resuming
// after the last event it saw (Last-Event-ID). A stream the server refuses (503: it has as many
// open as it allows) the browser gives up: asked again after 5 s.
export function subscribe(since, handlers, onStateChange) {
  let last = since;
  const es = new EventSource(`api/events?since=${since}`);
  for (const [type, fn] of Object.entries(handlers)) {
    es.addEventListener(type, (e) => { last = Number(e.lastEventId) || last; fn(JSON.parse(e.data)); });
  }
  es.onopen = () => onStateChange(true);
  es.onerror = () => {
    onStateChange(false);
    if (es.readyState === EventSource.CLOSED) setTimeout(() => subscribe(last, handlers, onStateChange), 5000);
  };
  return es;
}

export async function control(token, body) {
  const r = await fetch('api/control', {
    method: 'POST',
    headers: { 'Content-Type': 'application/json', 'X-Poresph-Token': token },
    body: JSON.stringify(body),
  });
  const j = await r.json().catch(() => ({}));
  return { status: r.status, ...j };
}

// Material names in the solver's order (alphabetical), from the run's resolved case.
export async function materialNames() {
  const r = await fetch('run/case.resolved.toml');
  if (!r.ok) return [];
  const text = await r.text();
  const names = new Set();
  for (const m of text.matchAll(/^\s*\[\s*materials\.([A-Za-z0-9_-]+)\s*\]/gm)) names.add(m[1]);
  return [...names].sort();
}

// The page's HTTP: the server's JSON/binary API (docs/viewer-api.md). The server runs the
// graph one request at a time, so every sender keeps at most one request in flight and
// sends only the latest value.
import { setBusy, showRequestError } from './ui.js';

const TOKEN = new URLSearchParams(location.search).get('token') || '';

// The cookie set on GET /?token=T authenticates same-origin requests; the header is sent too
// so the page still works when cookies are blocked.
export function api(path, body) {
  const opts = { credentials: 'same-origin', headers: {} };
  if (TOKEN) opts.headers['X-SSG-Token'] = TOKEN;
  if (body !== undefined) {
    opts.method = 'POST';
    opts.headers['Content-Type'] = 'text/plain';
    opts.body = body;
  }
  return fetch(path, opts);
}

// The error text of a failed response: the server's {"error": "..."} or the status line.
export async function errorText(resp) {
  try { const j = await resp.json(); if (j && j.error) return j.error; } catch (e) { /* */ }
  return `${resp.status} ${resp.statusText}`;
}

// A sender that keeps at most one request in flight per key and, when values arrive while
// one is in flight, sends only the latest when it returns (slider drags, camera drags).
export class LatestSender {
  constructor(path, onDone) { this.path = path; this.onDone = onDone; this.busy = false;
    this.pending = new Map(); }
  send(key, body) { this.pending.set(key, body); this.pump(); }
  get idle() { return !this.busy && this.pending.size === 0; }
  async pump() {
    if (this.busy || this.pending.size === 0) return;
    const [key, body] = this.pending.entries().next().value;
    this.pending.delete(key);
    this.busy = true;
    setBusy(true);
    try { await this.onDone(body, await api(this.path, body)); }
    catch (e) { showRequestError(`${this.path}: ${e}`); }
    this.busy = false;
    setBusy(false);
    this.pump();
  }
}

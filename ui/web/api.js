// The server's JSON, with the session's CSRF token on every POST.
let csrf = '';

export class NotLoggedIn extends Error {}

async function answer(r) {
  const body = await r.json().catch(() => ({ error: 'the server answered something unreadable' }));
  if (r.status === 401) throw new NotLoggedIn(body.error || 'log in first');
  if (!r.ok) throw new Error(body.error || `the server answered ${r.status}`);
  return body;
}

export async function get(path, params = {}) {
  const q = new URLSearchParams(params).toString();
  return answer(await fetch(q ? `${path}?${q}` : path, { credentials: 'same-origin' }));
}

export async function post(path, body) {
  const r = await fetch(path, {
    method: 'POST',
    credentials: 'same-origin',
    headers: { 'Content-Type': 'application/json', 'X-Rockface-CSRF': csrf },
    body: JSON.stringify(body),
  });
  return answer(r);
}

export function setCsrf(token) {
  csrf = token || '';
}

export function url(path, params) {
  return `${path}?${new URLSearchParams(params).toString()}`;
}

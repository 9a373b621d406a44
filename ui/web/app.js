// The office's pages: log-in, tunnels, a tunnel's drive, a visit, two
// visits side by side; a hash route (#/drive/NAME, #/visit/NAME/UUID,
// #/compare/NAME/UUID/UUID) so a link opens the same page.
import { get, post, setCsrf, NotLoggedIn } from './api.js';
import { el, table, section } from './dom.js';
import { showDrive, stopDrive } from './drive.js';
import { showVisit } from './visit.js';
import { showCompare } from './compare.js';

const page = document.getElementById('page');
const where = document.getElementById('where');

function setWhere(...links) {
  where.replaceChildren(...links.flatMap((l, i) => (i ? [' › ', l] : [l])));
}

function showLogin(message) {
  stopDrive();
  document.getElementById('logout').hidden = true;
  document.getElementById('who').textContent = '';
  setWhere();
  const role = el('input', { name: 'role', autocomplete: 'username', required: 'required', id: 'role' });
  const password = el('input', { name: 'password', type: 'password', autocomplete: 'current-password', required: 'required', id: 'password' });
  const status = el('p', { className: 'status', id: 'login-status', text: message || '' });
  const form = el('form', { id: 'login' },
    el('h1', { text: 'Log in' }),
    el('p', { text: 'Your role and password on the office database.' }),
    el('label', { for: 'role', text: 'Role' }), role,
    el('label', { for: 'password', text: 'Password' }), password,
    el('button', { type: 'submit', text: 'Log in' }), status);
  form.addEventListener('submit', async (e) => {
    e.preventDefault();
    status.textContent = 'logging in…';
    try {
      const s = await post('/api/login', { role: role.value, password: password.value });
      password.value = '';
      loggedIn(s);
      route();
    } catch (err) {
      password.value = '';
      status.textContent = err.message;
    }
  });
  page.replaceChildren(form);
}

function loggedIn(s) {
  setCsrf(s.csrf);
  document.getElementById('who').textContent = s.role;
  document.getElementById('logout').hidden = false;
}

async function showTunnels() {
  setWhere(el('a', { href: '#/tunnels', text: 'Tunnels' }));
  const tunnels = await get('/api/tunnels');
  const rows = tunnels.map((t) => [
    el('a', { href: `#/drive/${encodeURIComponent(t.name)}`, text: t.name, className: 'tunnel-link' }),
    String(t.visits), t.last_visit, t.drive_length]);
  page.replaceChildren(section('Tunnels', tunnels.length
    ? table(['Tunnel', 'Visits', 'Last visit', 'Drive mapped'], rows)
    : el('p', { text: 'This log-in may read no tunnel yet.' })));
}

async function route() {
  stopDrive();
  const parts = location.hash.replace(/^#\/?/, '').split('/').map(decodeURIComponent);
  try {
    if (parts[0] === 'drive' && parts[1]) {
      setWhere(el('a', { href: '#/tunnels', text: 'Tunnels' }), el('span', { text: parts[1] }));
      await showDrive(page, parts[1]);
    } else if (parts[0] === 'visit' && parts[1] && parts[2]) {
      setWhere(el('a', { href: '#/tunnels', text: 'Tunnels' }),
        el('a', { href: `#/drive/${encodeURIComponent(parts[1])}`, text: parts[1] }), el('span', { text: 'visit' }));
      await showVisit(page, parts[1], parts[2]);
    } else if (parts[0] === 'compare' && parts[1] && parts[2] && parts[3]) {
      setWhere(el('a', { href: '#/tunnels', text: 'Tunnels' }),
        el('a', { href: `#/drive/${encodeURIComponent(parts[1])}`, text: parts[1] }), el('span', { text: 'two visits' }));
      await showCompare(page, parts[1], parts[2], parts[3]);
    } else {
      await showTunnels();
    }
  } catch (err) {
    if (err instanceof NotLoggedIn) showLogin(err.message);
    else page.replaceChildren(el('p', { className: 'error', text: err.message }));
  }
}

document.getElementById('logout').addEventListener('click', async () => {
  try { await post('/api/logout', {}); } catch (err) { /* the session is gone either way */ }
  showLogin('Logged out.');
});
window.addEventListener('hashchange', route);
window.addEventListener('rockface-logged-out', (e) => showLogin(e.detail));

(async () => {
  try {
    loggedIn(await get('/api/session'));
    await route();
  } catch (err) {
    showLogin(err instanceof NotLoggedIn ? '' : err.message);
  }
})();

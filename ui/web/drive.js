// A tunnel's drive: a strip along the chainage with every visit, each
// set's dip and dip direction against chainage (new, turning and vanishing
// sets flagged), the visits' blocks, the rounds (RMR89 / Q, the support
// class proposed and decided, over- and underbreak: read after the rest,
// filled in as the server measures them); filters by date, heading and
// tablet; the page asks the server every few seconds whether a tablet
// synced and redraws when one did.
import { get } from './api.js';
import { el, svg, table, section, setColour } from './dom.js';

let poll = null;
const POLL_MS = 4000;
const ROUNDS_POLL_MS = 3000;

export function stopDrive() {
  if (poll) clearInterval(poll);
  poll = null;
}

function chart(title, unit, visits, tracks, value, lo, hi) {
  const w = 900, h = 170, left = 48, right = 12, top = 22, bottom = 28;
  const placed = visits.filter((v) => typeof v.chainage === 'number');
  const chs = placed.map((v) => v.chainage).concat(tracks.flatMap((t) => t.points.map((p) => p.chainage)));
  let c0 = Math.min(...chs), c1 = Math.max(...chs);
  if (!isFinite(c0)) { c0 = 0; c1 = 1; }
  if (c1 - c0 < 1) { c0 -= 0.5; c1 += 0.5; }
  const x = (c) => left + ((c - c0) / (c1 - c0)) * (w - left - right);
  const y = (v) => top + (1 - (v - lo) / (hi - lo)) * (h - top - bottom);
  const g = svg('svg', { viewBox: `0 0 ${w} ${h}`, class: 'chart', role: 'img', 'aria-label': title });
  g.append(svg('text', { x: 4, y: 14, class: 'chart-title', text: `${title} (${unit})` }));
  for (const v of [lo, (lo + hi) / 2, hi]) {
    g.append(svg('line', { x1: left, x2: w - right, y1: y(v), y2: y(v), class: 'grid' }));
    g.append(svg('text', { x: left - 4, y: y(v) + 4, class: 'axis', 'text-anchor': 'end', text: `${v}${unit}` }));
  }
  for (const [c, anchor] of [[c0, 'start'], [(c0 + c1) / 2, 'middle'], [c1, 'end']])
    g.append(svg('text', { x: x(c), y: h - 8, class: 'axis', 'text-anchor': anchor, text: `ch ${c.toFixed(1)} m` }));
  tracks.forEach((t, i) => {
    const pts = t.points.map((p) => `${x(p.chainage).toFixed(1)},${y(value(p)).toFixed(1)}`).join(' ');
    g.append(svg('polyline', { points: pts, class: 'track', stroke: setColour(i) }));
    for (const p of t.points) {
      const dot = svg('circle', { cx: x(p.chainage), cy: y(value(p)), r: p.turned ? 6 : 4, fill: setColour(i), class: p.turned ? 'turned' : '' });
      dot.append(svg('title', { text: `${t.name}, ${p.text}${p.turned ? ' — turned' : ''}` }));
      g.append(dot);
    }
  });
  return g;
}

// RMR89 of each round against chainage: the class boundaries (20, 40, 60,
// 80) as grid lines, a round's decided support class in its mark's title.
function rmrChart(rounds) {
  const w = 900, h = 150, left = 48, right = 12, top = 22, bottom = 28;
  const rated = rounds.filter((r) => typeof r.rmr === 'number');
  const g = svg('svg', { viewBox: `0 0 ${w} ${h}`, class: 'chart rmr', role: 'img', 'aria-label': 'RMR89 per round' });
  g.append(svg('text', { x: 4, y: 14, class: 'chart-title', text: 'RMR89 per round against chainage' }));
  let c0 = Math.min(...rounds.map((r) => r.chainage)), c1 = Math.max(...rounds.map((r) => r.chainage));
  if (!isFinite(c0)) { c0 = 0; c1 = 1; }
  if (c1 - c0 < 1) { c0 -= 0.5; c1 += 0.5; }
  const x = (c) => left + ((c - c0) / (c1 - c0)) * (w - left - right);
  const y = (v) => top + (1 - v / 100) * (h - top - bottom);
  for (const v of [0, 20, 40, 60, 80, 100]) {
    g.append(svg('line', { x1: left, x2: w - right, y1: y(v), y2: y(v), class: 'grid' }));
    g.append(svg('text', { x: left - 4, y: y(v) + 4, class: 'axis', 'text-anchor': 'end', text: String(v) }));
  }
  for (const [c, anchor] of [[c0, 'start'], [c1, 'end']])
    g.append(svg('text', { x: x(c), y: h - 8, class: 'axis', 'text-anchor': anchor, text: `ch ${c.toFixed(1)} m` }));
  for (const r of rated) {
    const dot = svg('circle', { cx: x(r.chainage), cy: y(r.rmr), r: 4, class: 'round' });
    dot.append(svg('title', { text: `ch ${r.chainage_text}: RMR89 ${r.rmr_text}, Q ${r.q_text}, support ${r.decided}` }));
    g.append(dot);
  }
  return g;
}

// The rounds come at once as far as the server has them: before the
// drive's copy is read, the placed visits only ("reading…"); a round whose
// over- and underbreak is still being measured on the server says so, and
// the table is asked again every few seconds until every round is in (no
// reload; it stops when the page is left or redrawn).
async function drawRounds(host, tunnel) {
  const title = () => el('h2', { text: 'Rounds: rock mass, support class, excavation' });
  try {
    const d = await get('/api/drive/rounds', { tunnel });
    if (!host.isConnected) return;
    const rows = d.rounds.map((r) => [
      r.visit ? el('a', { href: `#/visit/${encodeURIComponent(tunnel)}/${r.visit}`, text: r.chainage_text }) : r.chainage_text,
      r.rmr_text, r.q_text, r.proposed, `${r.decided}${r.decided_by ? ` (${r.decided_by})` : ''}`,
      r.measuring ? el('span', { className: 'measuring', text: r.excavation_text }) : r.excavation_text]);
    const waiting = d.measuring > 0 || d.reading;
    const status = el('p', { className: waiting ? 'muted' : 'muted rounds-done', id: 'rounds-status',
      text: waiting ? `${d.measuring} of ${d.rounds.length} rounds still being measured on the server; they fill in here as they are done.`
        : `${d.rounds.length} rounds` });
    host.replaceChildren(title(), status,
      d.rounds.length ? rmrChart(d.rounds) : el('p', { className: 'muted', text: 'no visit is placed in the tunnel yet' }),
      table(['Chainage', 'RMR89', 'Q', 'Support proposed', 'Support decided', 'Over- / underbreak'], rows, 'rounds'));
    if (waiting) setTimeout(() => { if (host.isConnected) drawRounds(host, tunnel); }, ROUNDS_POLL_MS);
  } catch (err) {
    if (!host.isConnected) return;
    host.replaceChildren(title(), el('p', { className: 'error', text: `the rounds could not be read: ${err.message}` }));
  }
}

function strip(visits) {
  const w = 900, h = 60, left = 48, right = 12;
  const placed = visits.filter((v) => typeof v.chainage === 'number');
  const g = svg('svg', { viewBox: `0 0 ${w} ${h}`, class: 'chart strip', role: 'img', 'aria-label': 'visits along the drive' });
  g.append(svg('text', { x: 4, y: 14, class: 'chart-title', text: 'Visits along the drive (chainage, m); red: blocks that move' }));
  if (!placed.length) return g;
  let c0 = Math.min(...placed.map((v) => v.chainage)), c1 = Math.max(...placed.map((v) => v.chainage));
  if (c1 - c0 < 1) { c0 -= 0.5; c1 += 0.5; }
  const x = (c) => left + ((c - c0) / (c1 - c0)) * (w - left - right);
  g.append(svg('line', { x1: left, x2: w - right, y1: 36, y2: 36, class: 'axis-line' }));
  for (const v of placed) {
    const a = svg('a', { href: `#/visit/${encodeURIComponent(v.tunnel)}/${v.id}` });
    const mark = svg('rect', { x: x(v.chainage) - 3, y: 26, width: 6, height: 20, class: v.moving > 0 ? 'visit moving' : 'visit' });
    // Date, tablet and geologist first (issue 46); a title's text is text, never markup.
    mark.append(svg('title', { text: `${v.date}, ${v.tablet}, geologist ${v.geologist}, ${v.heading === '—' ? '' : `${v.heading}, `}ch ${v.chainage_text}, ${v.blocks} blocks, ${v.moving} move` }));
    a.append(mark);
    g.append(a);
  }
  return g;
}

async function draw(host, tunnel, filter, stamp) {
  const d = await get('/api/drive', { tunnel, ...filter });
  stamp.value = d.stamp;
  for (const v of d.visits) v.tunnel = tunnel;
  const tablet = el('select', { id: 'filter-tablet' }, el('option', { value: '', text: 'every tablet' }),
    ...d.tablets.map((t) => el('option', { value: t, text: t })));
  tablet.value = filter.tablet || '';
  // The face each visit was taken at, for a tunnel driven from more than
  // one ("—": the visits without one).
  const heading = el('select', { id: 'filter-heading' }, el('option', { value: '', text: 'every heading' }),
    ...(d.headings || []).map((h) => el('option', { value: h, text: h === '—' ? '— (none named)' : h })));
  heading.value = filter.heading || '';
  const from = el('input', { type: 'date', id: 'filter-from', value: filter.from || '' });
  const to = el('input', { type: 'date', id: 'filter-to', value: filter.to || '' });
  const apply = () => {
    filter.from = from.value; filter.to = to.value; filter.tablet = tablet.value; filter.heading = heading.value;
    draw(host, tunnel, filter, stamp);
  };
  for (const f of [tablet, heading, from, to]) f.addEventListener('change', apply);
  const rounds = el('section', { id: 'rounds' }, el('h2', { text: 'Rounds: rock mass, support class, excavation' }),
    el('p', { className: 'muted', text: 'reading the rounds…' }));
  const filters = el('form', { className: 'filters' },
    el('label', { text: 'From ' }, from), el('label', { text: 'To ' }, to), el('label', { text: 'Tablet ' }, tablet),
    el('label', { text: 'Heading ' }, heading));
  const setRows = d.sets.map((t, i) => [el('span', { className: `set-dot set-${i % 8}`, text: t.name }),
    t.points.length ? t.points[t.points.length - 1].text : '–', t.flags || '–', (t.events || []).join('; ') || '–']);
  const visitRows = d.visits.map((v) => [
    el('a', { href: `#/visit/${encodeURIComponent(tunnel)}/${v.id}`, text: v.date, className: 'visit-link' }),
    v.chainage_text, v.heading, v.tablet, v.project, String(v.blocks), String(v.moving), v.largest_block, v.note || '',
    v.geologist]);
  host.replaceChildren(
    el('h1', { text: `Drive of ${tunnel}` }),
    filters,
    el('p', { className: 'muted', id: 'drive-count', text: `${d.visits.length} visits, ${d.tablets.length} tablets` }),
    strip(d.visits),
    d.sets.length ? chart('Dip of each set', '°', d.visits, d.sets, (p) => p.dip, 0, 90) : el('p', { text: d.sets_note }),
    d.sets.length ? chart('Dip direction of each set', '°', d.visits, d.sets, (p) => p.dipdir, 0, 360) : null,
    section('Sets along the drive', table(['Set', 'Last seen (dip / dip direction ± α95)', 'Flags', 'Events'], setRows)),
    // The rounds arrive later and grow: below the visits, so that the list
    // a person is about to tap does not move under the finger.
    section('Visits', table(['Date', 'Chainage', 'Heading', 'Tablet', 'Project', 'Blocks', 'Blocks that move', 'Largest removable block', 'Note', 'Geologist'], visitRows, 'visits')),
    rounds);
  // The server answers the rounds at once and measures the rest in the
  // background: asked for every drive, however long.
  drawRounds(rounds, tunnel);
}

export async function showDrive(host, tunnel) {
  const filter = { from: '', to: '', tablet: '', heading: '' };
  const stamp = { value: '' };
  await draw(host, tunnel, filter, stamp);
  poll = setInterval(async () => {
    try {
      const s = await get('/api/stamp', { tunnel });
      if (s.stamp !== stamp.value) await draw(host, tunnel, filter, stamp);
    } catch (err) {
      stopDrive();
      window.dispatchEvent(new CustomEvent('rockface-logged-out', { detail: err.message }));
    }
  }, POLL_MS);
}

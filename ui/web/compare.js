// Two visits side by side: the same face a round later. The sets matched
// by orientation (each set's mean then and now and its change in degrees;
// sets new and vanished), the blocks matched by position and volume (the
// verdicts that changed first); who mapped each visit.
import { get } from './api.js';
import { el, table, section } from './dom.js';

export async function showCompare(host, tunnel, a, b) {
  host.replaceChildren(el('p', { className: 'muted', text: 'comparing the visits…' }));
  const c = await get('/api/compare', { tunnel, a, b });
  const link = (v) => el('a', { href: `#/visit/${encodeURIComponent(tunnel)}/${v.id}`, text: `${v.started_at} (${v.project})` });
  // Who mapped each visit: a round later it may be someone else.
  const geologist = (v, which) => el('span', { id: `compare-geologist-${which}`, text: `geologist: ${v.geologist}` });
  const setRows = c.sets.map((s) => [s.earlier, s.later, s.change, s.planes]);
  const blocks = [...c.blocks].sort((x, y) => Number(y.verdict_changed) - Number(x.verdict_changed));
  const blockRows = blocks.map((k) => [k.state, k.earlier, k.later, k.moved]);
  const changed = c.blocks.filter((k) => k.verdict_changed).length;
  host.replaceChildren(
    el('h1', { text: 'Two visits side by side' }),
    el('p', {}, el('span', { text: 'Earlier: ' }), link(c.earlier), el('span', { text: ', ' }), geologist(c.earlier, 'earlier'),
      el('span', { text: ' — later: ' }), link(c.later), el('span', { text: ', ' }), geologist(c.later, 'later')),
    section('Joint sets', el('p', { className: 'muted', text: 'Matched by the angle between their poles (within 25°); the change is that angle.' }),
      table(['Earlier (dip / dip direction)', 'Later (dip / dip direction)', 'Change', 'Planes'], setRows, 'compare-sets')),
    section('Blocks', el('p', { className: 'muted', id: 'verdicts-changed', text: `${changed} verdicts changed; blocks matched by centroid (within 0.5 m) and volume (within a factor 2).` }),
      table(['', 'Earlier', 'Later', 'Moved'], blockRows, 'compare-blocks')));
}

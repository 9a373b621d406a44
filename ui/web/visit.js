// A visit: its photographs (a click zooms), its 3D face, joints and sets
// with the stereonet, blocks with verdict, margin, mode, FoS and motion
// after failure, the round in the tunnel, the wedges, the rock mass, the
// support, the field report as PDF and the exports as downloads.
import { get, url } from './api.js';
import { el, svg, table, section, lines, setColour, verdictColours } from './dom.js';
import { stereonet } from './stereonet.js';

// The 3D face's legend: each set's colour (the stereonet's), traces of no
// set, each verdict's colour, the range pole.
function faceLegend(v) {
  const item = (colour, text) => el('span', { className: 'legend-item' },
    svg('svg', { viewBox: '0 0 12 12', width: 12, height: 12, 'aria-hidden': 'true' }, svg('rect', { x: 0, y: 0, width: 12, height: 12, fill: colour })),
    el('span', { text }));
  return el('p', { className: 'legend muted', id: 'face-legend' },
    el('span', { text: 'Traces by set:' }),
    ...v.sets.map((s, i) => item(setColour(i), s.label)),
    item(setColour(-1), 'no set'),
    el('span', { text: 'Blocks by verdict:' }),
    ...['removable', 'keyed', 'infinite'].map((k) => item(verdictColours[k], k)),
    v.pole ? item('#ff8c00', `range pole (${v.pole.length})`) : null);
}

export async function showVisit(host, tunnel, visitId) {
  host.replaceChildren(el('p', { className: 'muted', text: 'reading the visit…' }));
  const v = await get('/api/visit', { tunnel, visit: visitId });
  const q = { tunnel, visit: visitId };

  const photos = el('div', { className: 'photos' }, ...v.photos.map((p) => {
    const img = el('img', { src: url('/api/visit/photo', { ...q, capture: p.capture, side: p.side }), alt: `photograph ${p.capture}, ${p.side}`, loading: 'lazy' });
    const figure = el('figure', {}, img, el('figcaption', { text: `pair ${p.capture}, ${p.side}` }));
    // The figure takes the whole row when zoomed: a flex item sized by its
    // content would hold the photograph at its own small width.
    img.addEventListener('click', () => { img.classList.toggle('zoomed'); figure.classList.toggle('zoomed'); });
    return figure;
  }));

  const faceHost = el('div', { id: 'face', className: 'face' });
  const faceStatus = el('p', { className: 'muted', id: 'face-status', text: v.has_face ? 'drawing the 3D face…' : 'This visit has no 3D image.' });
  const fullButton = el('button', { type: 'button', text: 'Full resolution' });

  const report = el('a', { href: url('/api/visit/report.pdf', q), target: '_blank', rel: 'noopener', id: 'report-link', text: 'Field report (PDF)' });
  const exportsList = el('ul', { className: 'lines', id: 'exports' });
  const exportsButton = el('button', { type: 'button', id: 'exports-button', text: 'Prepare the exports' });
  exportsButton.addEventListener('click', async () => {
    exportsButton.disabled = true;
    exportsList.replaceChildren(el('li', { text: 'exporting…' }));
    try {
      const e = await get('/api/visit/exports', q);
      exportsList.replaceChildren(...e.files.map((f) => el('li', {}, el('a', { href: url('/api/visit/export', { ...q, name: f.name }), download: f.name, text: f.name }), el('span', { text: ` (${f.size})` }))));
    } catch (err) {
      exportsList.replaceChildren(el('li', { className: 'error', text: err.message }));
    }
    exportsButton.disabled = false;
  });

  const figures = table(['Figure', 'Value'], v.figures.map((f) => [f.name, f.value]));
  const blocks = table(['Block', 'Verdict', 'Margin', 'Mode', 'FoS', 'Volume', 'Mass', 'Rotation', 'After failure'],
    v.blocks.map((b) => [b.label, b.verdict, b.margin, b.mode, b.fos, b.volume, b.mass, b.rotation, b.motion]), 'blocks');
  const sets = table(['Set', 'Dip / dip direction', 'Planes', 'Fisher K', 'α95'], v.sets.map((s) => [s.label, s.orientation, String(s.count), s.fisher_k, s.alpha95]));
  const joints = table(['Joint', 'Set', 'Dip / dip direction', 'Friction', 'Cohesion'], v.joints.map((j) => [j.label, j.set, j.orientation, j.friction, j.cohesion]));

  const parts = [
    el('h1', { text: `Visit of ${v.started_at}` }),
    el('p', { className: 'muted', text: `${v.project}; ${v.source}; camera ${v.camera || '–'}; preset ${v.preset || '–'}` }),
    // Who mapped the visit (issue 46): text, whatever the name holds.
    el('p', { id: 'visit-geologist', text: `Geologist: ${v.geologist || 'not recorded'}` }),
    el('p', { className: 'actions' }, report),
    section('3D face', faceHost, faceStatus, v.has_face ? fullButton : null, faceLegend(v)),
    section('Photographs', photos),
    section('Accuracy', figures, lines(v.warnings)),
    section('Joint sets', el('div', { className: 'side' }, stereonet(v.poles, v.sets), sets)),
    section('Joints', joints),
    section('Blocks', blocks),
  ];
  // The field report's pictures with the caption the PDF prints under them.
  const picture = (which, caption) => {
    const img = el('img', { src: url('/api/visit/picture', { ...q, which }), alt: caption, className: 'picture', id: `picture-${which}` });
    img.addEventListener('click', () => img.classList.toggle('zoomed'));
    return el('figure', { className: 'picture' }, img, el('figcaption', { id: `caption-${which}`, text: caption }));
  };
  if (v.tunnel && v.tunnel.name)
    parts.push(section('The round in the tunnel', el('p', { text: `${v.tunnel.name}, ${v.tunnel.profile}, chainage ${v.tunnel.chainage}` }), lines(v.tunnel.lines),
      v.tunnel.has_developed_view ? picture('developed', 'The round developed: overbreak red, underbreak blue, not seen hatched') : null));
  if (v.wedges && v.wedges.rows) parts.push(section('Wedges around the excavation', lines(v.wedges.lines),
    v.wedges.has_picture ? picture('wedges', 'The wedges along the drive, and the largest in perspective') : null,
    table(v.wedges.rows[0] ? v.wedges.rows[0].map((_, i) => (i ? '' : 'Wedge')) : [], v.wedges.rows), lines(v.wedges.notes)));
  parts.push(section('Rock mass', v.rockmass.rmr ? lines([v.rockmass.rmr, v.rockmass.q, ...v.rockmass.lines]) : el('p', { text: v.rockmass.note || 'not classified' })));
  if (v.support && v.support.proposals) parts.push(section('Support', lines(v.support.proposals), lines(v.support.decision)));
  // Another visit of the tunnel to set beside this one (the drive's list,
  // read from the server's shared copy).
  const other = el('select', { id: 'compare-with' }, el('option', { value: '', text: 'another visit…' }));
  other.addEventListener('change', () => {
    if (other.value) location.hash = `#/compare/${encodeURIComponent(tunnel)}/${visitId}/${other.value}`;
  });
  get('/api/drive', { tunnel }).then((d) => {
    for (const o of d.visits) if (o.id !== visitId) other.append(el('option', { value: o.id, text: `${o.date}, ${o.tablet}, ${o.chainage_text}` }));
  }).catch(() => {});
  parts.push(section('Compare', el('label', { text: 'Side by side with ' }, other)));
  parts.push(section('Exports', exportsButton, exportsList));
  host.replaceChildren(...parts);

  if (v.has_face) {
    const texture = v.texture ? url('/api/visit/photo', { ...q, capture: v.texture.capture, side: v.texture.side }) : null;
    const { showFace } = await import('./face3d.js');
    const draw = (full) => showFace(faceHost, faceStatus, url('/api/visit/mesh', { ...q, full: full ? '1' : '0' }), texture, v)
      .catch((err) => { faceStatus.textContent = `The 3D face cannot be drawn here: ${err.message}`; });
    fullButton.addEventListener('click', () => draw(true));
    await draw(false);
  }
}

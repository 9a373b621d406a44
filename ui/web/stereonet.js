// The stereonet of a visit's poles and set means: lower hemisphere, equal
// area (Schmidt), north up, as the field report draws it.
import { svg, setColour } from './dom.js';

export function stereonet(poles, sets) {
  const r = 120, c = 130;
  const g = svg('svg', { viewBox: '0 0 260 275', class: 'stereonet', role: 'img', 'aria-label': 'stereonet of the poles, lower hemisphere, equal area' });
  g.append(svg('circle', { cx: c, cy: c, r, class: 'net' }));
  g.append(svg('line', { x1: c - 5, x2: c + 5, y1: c, y2: c, class: 'net' }));
  g.append(svg('line', { x1: c, x2: c, y1: c - 5, y2: c + 5, class: 'net' }));
  g.append(svg('text', { x: c, y: c - r - 3, 'text-anchor': 'middle', class: 'axis', text: 'N' }));
  // The pole of a plane (dip d, dip direction a) plunges 90 - d towards a + 180.
  const place = (dip, dipdir) => {
    const trend = ((dipdir + 180) * Math.PI) / 180;
    const plunge = ((90 - dip) * Math.PI) / 180;
    const rho = r * Math.SQRT2 * Math.sin((Math.PI / 2 - plunge) / 2);
    return [c + rho * Math.sin(trend), c - rho * Math.cos(trend)];
  };
  for (const p of poles) {
    const [x, y] = place(p.dip, p.dipdir);
    g.append(svg('circle', { cx: x.toFixed(1), cy: y.toFixed(1), r: 3, fill: setColour(p.set), class: 'pole' }));
  }
  sets.forEach((s, i) => {
    const [x, y] = place(s.dip, s.dipdir);
    g.append(svg('rect', { x: (x - 5).toFixed(1), y: (y - 5).toFixed(1), width: 10, height: 10, fill: 'none', stroke: setColour(i), 'stroke-width': 2, 'data-set': s.label }));
    g.append(svg('text', { x: (x + 7).toFixed(1), y: (y - 6).toFixed(1), class: 'axis', text: s.label }));
  });
  g.append(svg('text', { x: 4, y: 270, class: 'axis', text: 'poles, lower hemisphere, equal area' }));
  return g;
}

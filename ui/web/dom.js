// Building the page from data: every text goes in through textContent (or
// an attribute set with setAttribute), never as HTML, so a note holding
// "<script>" is shown as those characters and nothing else.
export function el(tag, attrs = {}, ...children) {
  const node = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) {
    if (k === 'text') node.textContent = v;
    else if (k === 'className') node.className = v;
    else if (k.startsWith('on')) node.addEventListener(k.slice(2), v);
    else node.setAttribute(k, v);
  }
  for (const c of children) if (c !== null && c !== undefined) node.append(c);
  return node;
}

export function svg(tag, attrs = {}, ...children) {
  const node = document.createElementNS('http://www.w3.org/2000/svg', tag);
  for (const [k, v] of Object.entries(attrs)) {
    if (k === 'text') node.textContent = v;
    else node.setAttribute(k, String(v));
  }
  for (const c of children) if (c) node.append(c);
  return node;
}

// A table from column titles and rows of texts.
export function table(titles, rows, className = '') {
  const head = el('tr', {}, ...titles.map((t) => el('th', { text: t })));
  const body = rows.map((r) => el('tr', {}, ...r.map((c) => (c instanceof Node ? el('td', {}, c) : el('td', { text: String(c) })))));
  return el('div', { className: 'scroll' }, el('table', { className }, el('thead', {}, head), el('tbody', {}, ...body)));
}

export function section(title, ...children) {
  return el('section', {}, el('h2', { text: title }), ...children);
}

export function lines(list) {
  return el('ul', { className: 'lines' }, ...(list || []).map((l) => el('li', { text: l })));
}

// The colours of sets (traces, poles, the drive's charts) and verdicts.
export const setColours = ['#d62728', '#1f77b4', '#2ca02c', '#9467bd', '#ff7f0e', '#17becf', '#8c564b', '#e377c2'];
export function setColour(i) {
  return i < 0 ? '#777777' : setColours[i % setColours.length];
}
export const verdictColours = { removable: '#d62728', keyed: '#2ca02c', infinite: '#888888' };

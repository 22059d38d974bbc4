// SPDX-License-Identifier: Apache-2.0
// alphapocket's index.html of a batch run (molecule/batch_page.hpp): the
// structures and sites tables, sortable and filterable, drawn a screen at a
// time (only the rows in view exist, so 100,000 sites scroll as fast as 10),
// the failures, and histograms of the top site's probability and of the
// sites' volumes. Text from the inputs goes in as text only.
'use strict';

(function () {
  const started = performance.now();  // the page parsed up to this script
  const data = JSON.parse(document.getElementById('alphapocket-index').textContent);
  const parsed = performance.now();
  const pages = new Set(data.pages);

  function el(tag, attrs, ...children) {
    const e = document.createElement(tag);
    for (const [k, v] of Object.entries(attrs || {})) e.setAttribute(k, v);
    for (const c of children) e.append(c instanceof Node ? c : document.createTextNode(String(c)));
    return e;
  }
  const show = v => (v === null || v === undefined ? '' : typeof v === 'number' && !Number.isInteger(v) ? v.toFixed(3) : String(v));

  const kRowHeight = 22;

  // A table of `rows` (arrays) with `columns` ([{name, title, numeric}]):
  // sort by clicking a header, filter with `filters` (functions of a row),
  // rows drawn only while in view.
  function virtualTable(id, columns, rows, cell) {
    let order = rows.map((_, i) => i), view = order, sortColumn = -1, ascending = true;
    const head = el('div', { class: 'vhead' });
    columns.forEach((c, k) => {
      const h = el('div', { class: 'vcell' + (c.numeric ? ' num' : ''), style: `flex:${c.width || 1}`, 'data-column': c.name }, c.title);
      h.addEventListener('click', () => sortBy(k));
      head.append(h);
    });
    const body = el('div', { class: 'vbody', id: id + '-rows' });
    const spacer = el('div', { class: 'vspacer' });
    const count = el('p', { class: 'count' });
    body.append(spacer);
    const box = el('div', { class: 'vtable', id }, head, body);
    let filters = [];

    function draw() {
      spacer.style.height = view.length * kRowHeight + 'px';
      const first = Math.floor(body.scrollTop / kRowHeight), n = Math.ceil(body.clientHeight / kRowHeight) + 2;
      for (const r of Array.from(body.querySelectorAll('.vrow'))) r.remove();
      for (let i = first; i < Math.min(view.length, first + n); ++i) {
        const row = rows[view[i]];
        const r = el('div', { class: 'vrow', style: `top:${i * kRowHeight}px`, 'data-row': String(view[i]) });
        columns.forEach((c, k) => r.append(el('div', { class: 'vcell' + (c.numeric ? ' num' : ''), style: `flex:${c.width || 1}` }, cell(row, k))));
        body.append(r);
      }
      count.textContent = `${view.length} of ${rows.length} rows`;
    }
    function refilter() {
      view = filters.length ? order.filter(i => filters.every(f => f(rows[i]))) : order;
      body.scrollTop = 0;
      draw();
    }
    function sortBy(k) {
      ascending = sortColumn === k ? !ascending : !columns[k].numeric;
      sortColumn = k;
      const key = columns[k].index;
      order = rows.map((_, i) => i).sort((a, b) => {
        const [x, y] = [rows[a][key], rows[b][key]];
        if (x === y) return a - b;
        if (x === null) return 1;
        if (y === null) return -1;
        return (x < y ? -1 : 1) * (ascending ? 1 : -1);
      });
      head.querySelectorAll('.vcell').forEach((h, j) => h.classList.toggle('sorted', j === k));
      refilter();
    }
    body.addEventListener('scroll', () => requestAnimationFrame(draw));
    return { box, count, draw, setFilters(f) { filters = f; refilter(); }, sortBy, view: () => view, rows };
  }

  function columnsOf(table, names) {
    return names.map(([name, title, width]) => {
      const index = table.columns.indexOf(name);
      return { name, title, index, width, numeric: table.numeric.includes(name) };
    });
  }

  // A histogram of `values` in [lo, hi] as SVG bars.
  function histogram(id, title, values, lo, hi, bins) {
    const ns = 'http://www.w3.org/2000/svg', w = 320, h = 120;
    const counts = new Array(bins).fill(0);
    for (const v of values) if (v !== null) counts[Math.min(bins - 1, Math.max(0, Math.floor((v - lo) / (hi - lo) * bins)))]++;
    const max = Math.max(1, ...counts);
    const svg = document.createElementNS(ns, 'svg');
    svg.setAttribute('width', w);
    svg.setAttribute('height', h);
    svg.setAttribute('id', id);
    counts.forEach((c, i) => {
      const r = document.createElementNS(ns, 'rect');
      const bh = c / max * (h - 30);
      r.setAttribute('x', 4 + i * (w - 8) / bins);
      r.setAttribute('y', h - 16 - bh);
      r.setAttribute('width', (w - 8) / bins - 1);
      r.setAttribute('height', bh);
      const tip = document.createElementNS(ns, 'title');
      tip.textContent = `${(lo + i * (hi - lo) / bins).toFixed(2)}–${(lo + (i + 1) * (hi - lo) / bins).toFixed(2)}: ${c}`;
      r.append(tip);
      svg.append(r);
    });
    for (const [x, text, anchor] of [[4, lo.toFixed(1), 'start'], [w - 4, hi.toFixed(1), 'end']]) {
      const t = document.createElementNS(ns, 'text');
      t.setAttribute('x', x);
      t.setAttribute('y', h - 3);
      t.setAttribute('text-anchor', anchor);
      t.textContent = text;
      svg.append(t);
    }
    return el('figure', {}, svg, el('figcaption', {}, title));
  }

  const S = data.structures, T = data.sites;
  const col = (table, name) => table.columns.indexOf(name);
  const structureColumns = columnsOf(S, [['id', 'Structure', 2], ['status', 'Status'], ['atoms', 'Atoms'], ['sites', 'Sites'],
    ['top_probability', 'Top site probability'], ['sa_volume', 'SA vol Å³'], ['mean_plddt', 'pLDDT'], ['tunnels', 'Tunnels']]);
  const siteColumns = columnsOf(T, [['structure_id', 'Structure', 2], ['site_rank', 'Site'], ['kind', 'Kind'], ['probability', 'Probability'],
    ['sa_volume', 'SA vol Å³'], ['ms_volume', 'MS vol Å³'], ['depth', 'Depth Å'], ['mean_plddt', 'pLDDT'], ['residues', 'Lining residues', 4], ['ligands', 'Ligands', 2]]);

  function linkTo(id, text) {
    return pages.has(id) ? el('a', { href: encodeURIComponent(id) + '/report.html' }, text) : text;
  }
  const structures = virtualTable('structures', structureColumns, S.rows, (row, k) => {
    const v = show(row[structureColumns[k].index]);
    return k === 0 ? linkTo(row[col(S, 'id')], v) : v;
  });
  const sites = virtualTable('sites', siteColumns, T.rows, (row, k) => {
    const v = show(row[siteColumns[k].index]);
    if (k === 0) return linkTo(row[col(T, 'structure_id')], v);
    return k >= 8 ? el('span', { title: v }, v) : v;
  });

  // Filters: text (id, residue, ligand), least probability, volume, pLDDT; status.
  const inputs = {
    text: el('input', { type: 'search', id: 'filter-text', placeholder: 'structure, residue or ligand' }),
    probability: el('input', { type: 'number', id: 'filter-probability', min: '0', max: '1', step: '0.05', placeholder: '0' }),
    volume: el('input', { type: 'number', id: 'filter-volume', min: '0', step: '10', placeholder: '0' }),
    plddt: el('input', { type: 'number', id: 'filter-plddt', min: '0', max: '100', step: '5', placeholder: '0' }),
    status: el('select', { id: 'filter-status' }, el('option', { value: '' }, 'any'),
      ...[...new Set(S.rows.map(r => r[col(S, 'status')]))].sort().map(s => el('option', { value: s }, s))),
  };
  function applyFilters() {
    const text = inputs.text.value.trim().toLowerCase();
    const minP = Number(inputs.probability.value || 0), minV = Number(inputs.volume.value || 0), minL = Number(inputs.plddt.value || 0);
    const status = inputs.status.value;
    const atLeast = (v, min) => min <= 0 || (v !== null && v >= min);
    const siteFilters = [], structureFilters = [];
    if (text) {
      const textIn = [col(T, 'structure_id'), col(T, 'residues'), col(T, 'ligands')];
      siteFilters.push(r => textIn.some(k => r[k] !== null && String(r[k]).toLowerCase().includes(text)));
      structureFilters.push(r => String(r[col(S, 'id')]).toLowerCase().includes(text));
    }
    if (minP > 0) {
      siteFilters.push(r => atLeast(r[col(T, 'probability')], minP));
      structureFilters.push(r => atLeast(r[col(S, 'top_probability')], minP));
    }
    if (minV > 0) {
      siteFilters.push(r => atLeast(r[col(T, 'sa_volume')], minV));
      structureFilters.push(r => atLeast(r[col(S, 'sa_volume')], minV));
    }
    if (minL > 0) {
      siteFilters.push(r => atLeast(r[col(T, 'mean_plddt')], minL));
      structureFilters.push(r => atLeast(r[col(S, 'mean_plddt')], minL));
    }
    if (status) structureFilters.push(r => r[col(S, 'status')] === status);
    structures.setFilters(structureFilters);
    sites.setFilters(siteFilters);
  }
  for (const i of Object.values(inputs)) i.addEventListener('input', applyFilters);

  const failures = el('table', { id: 'failures' }, el('thead', {}, el('tr', {}, ...data.failures.columns.map(c => el('th', {}, c)))));
  const fbody = el('tbody');
  for (const f of data.failures.rows) fbody.append(el('tr', {}, ...f.map(v => el('td', {}, show(v)))));
  failures.append(fbody);

  const ok = S.rows.filter(r => r[col(S, 'status')] === 'ok').length;
  document.body.append(
    el('header', {}, el('h1', {}, 'alphapocket screening run'),
      el('p', { class: 'summary' }, `${S.rows.length} structures (${ok} ok, ${data.failures.rows.length} failed or skipped) · ${T.rows.length} sites · alphapocket ${data.alphapocket}`)),
    el('section', { class: 'plots' },
      histogram('plot-top-probability', 'Top site probability per structure', S.rows.map(r => r[col(S, 'top_probability')]), 0, 1, 20),
      histogram('plot-volume', 'Site SA volume, Å³ (log10)', T.rows.map(r => (r[col(T, 'sa_volume')] > 0 ? Math.log10(r[col(T, 'sa_volume')]) : null)), 0, 4, 24)),
    el('section', { class: 'filters' }, el('label', {}, 'Find ', inputs.text), el('label', {}, 'probability ≥ ', inputs.probability),
      el('label', {}, 'SA volume ≥ ', inputs.volume), el('label', {}, 'pLDDT ≥ ', inputs.plddt), el('label', {}, 'status ', inputs.status)),
    el('h2', {}, 'Structures'), structures.count, structures.box,
    el('h2', {}, 'Sites'), sites.count, sites.box,
    el('h2', {}, 'Failures'), data.failures.rows.length ? failures : el('p', {}, 'None.'));
  structures.draw();
  sites.draw();
  const drawn = performance.now();
  // Ready once the first screen is painted (a task after the next frame), with
  // the time since navigation began: what the browser test holds to 2 s.
  window.alphapocketIndex = { structures, sites, siteColumns: T.columns, ready: false };
  requestAnimationFrame(() => setTimeout(() => {
    window.alphapocketIndex.firstScreenMs = performance.now();
    window.alphapocketIndex.timings = { started, parsed, drawn };
    window.alphapocketIndex.ready = true;
  }, 0));
})();

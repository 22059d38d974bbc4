// SPDX-License-Identifier: Apache-2.0
// alphapocket's report.html: draws the page from its JSON block
// (molecule/report_page.hpp) and the scene with Mol* (molstar.js, loaded
// before this file). Input text is only ever put in as text (textContent),
// never as markup. Nothing is fetched: the structure comes from the JSON.
'use strict';

(function () {
  const data = JSON.parse(document.getElementById('alphapocket-data').textContent);

  function el(tag, attrs, ...children) {
    const e = document.createElement(tag);
    for (const [k, v] of Object.entries(attrs || {})) e.setAttribute(k, v);
    for (const c of children) e.append(c instanceof Node ? c : document.createTextNode(String(c)));
    return e;
  }
  const fixed = (x, digits) => (x === null || x === undefined ? '' : Number(x).toFixed(digits));

  // A table from column definitions [{title, value(row) -> text or Node, numeric}].
  function table(id, columns, rows) {
    const head = el('tr', {}, ...columns.map(c => el('th', c.numeric ? { class: 'num' } : {}, c.title)));
    const body = el('tbody');
    rows.forEach((row, i) => {
      const tr = el('tr', { 'data-index': String(i) });
      for (const c of columns) {
        const v = c.value(row);
        tr.append(el('td', c.numeric ? { class: 'num' } : {}, v instanceof Node ? v : String(v)));
      }
      body.append(tr);
    });
    return el('table', { id }, el('thead', {}, head), body);
  }

  // The residues as a short text, all of them in the cell's tooltip.
  function residueList(residues) {
    const shown = residues.slice(0, 3).join(' ') + (residues.length > 3 ? ` … (${residues.length})` : '');
    return el('span', { title: residues.join(' ') }, shown);
  }

  // Radius along the path (distance from its first point) as an SVG line.
  function profilePlot(profile) {
    const ns = 'http://www.w3.org/2000/svg';
    const svg = document.createElementNS(ns, 'svg');
    const w = 220, h = 50;
    svg.setAttribute('width', w);
    svg.setAttribute('height', h);
    svg.setAttribute('class', 'profile');
    if (profile.length < 2) return svg;
    const s = [0];
    for (let i = 1; i < profile.length; ++i) {
      const [a, b] = [profile[i - 1], profile[i]];
      s.push(s[i - 1] + Math.hypot(b[0] - a[0], b[1] - a[1], b[2] - a[2]));
    }
    const maxS = s[s.length - 1] || 1, maxR = Math.max(...profile.map(p => p[3]), 1e-9);
    const points = profile.map((p, i) => `${(s[i] / maxS * (w - 4) + 2).toFixed(1)},${(h - 2 - p[3] / maxR * (h - 14)).toFixed(1)}`);
    const line = document.createElementNS(ns, 'polyline');
    line.setAttribute('points', points.join(' '));
    svg.append(line);
    const label = document.createElementNS(ns, 'text');
    label.setAttribute('x', 2);
    label.setAttribute('y', 10);
    label.textContent = `r max ${maxR.toFixed(2)} Å, length ${maxS.toFixed(1)} Å`;
    svg.append(label);
    return svg;
  }

  // ---- the page
  document.title = 'alphapocket: ' + data.file;
  const mol = data.molecule, input = data.input || {};
  const header = el('header', {},
    el('h1', {}, 'Sites of ', el('span', { id: 'structure-name' }, data.file)),
    el('p', { class: 'summary' },
      `${mol.atoms} atoms · ${data.sites.length} sites · ${data.tunnels.length} tunnels` +
      (input.predicted ? ` · predicted model, mean pLDDT ${fixed(mol.mean_plddt, 1)}` : '') +
      ` · alphapocket ${data.alphapocket}`));
  const viewer = el('div', { id: 'viewer' });
  const siteColumns = [
    { title: 'Site', value: s => s.rank, numeric: true },
    { title: 'Kind', value: s => `${s.kind} ${s.cavity_rank}` },
    { title: 'Probability', value: s => fixed(s.probability, 3), numeric: true },
    { title: 'SA vol Å³', value: s => fixed(s.sa_volume, 1), numeric: true },
    { title: 'MS vol Å³', value: s => fixed(s.ms_volume, 1), numeric: true },
    { title: 'Depth Å', value: s => fixed(s.depth, 1), numeric: true },
    { title: 'Mouths', value: s => s.mouths, numeric: true },
    { title: 'Lining residues', value: s => residueList(s.residues) },
    { title: 'Ligands', value: s => s.ligands.join(' ') },
  ];
  if (input.predicted) siteColumns.splice(7, 0, { title: 'pLDDT', value: s => fixed(s.mean_plddt, 1), numeric: true });
  const sites = table('sites', siteColumns, data.sites);
  sites.querySelectorAll('tbody tr').forEach(tr => {
    const site = data.sites[Number(tr.dataset.index)];
    tr.prepend(el('td', { class: 'swatch' }, el('span', { style: 'background:' + siteColor(site.rank) })));
  });
  sites.querySelector('thead tr').prepend(el('th', {}, ''));
  const tunnels = table('tunnels', [
    { title: 'Tunnel', value: t => t.rank, numeric: true },
    { title: 'Kind', value: t => t.kind },
    { title: 'Bottleneck Å', value: t => fixed(t.bottleneck_radius, 2), numeric: true },
    { title: 'Length Å', value: t => fixed(t.length, 1), numeric: true },
    { title: 'Radius profile', value: t => (t.profile.length >= 2 ? profilePlot(t.profile) : '') },
    { title: 'Lining residues', value: t => residueList(t.residues) },
  ], data.tunnels);
  const params = el('dl', { id: 'parameters' });
  for (const [k, v] of Object.entries(data.parameters)) params.append(el('dt', {}, k), el('dd', {}, JSON.stringify(v)));
  const files = el('ul', { id: 'files' });
  for (const f of data.files) files.append(el('li', {}, el('a', { href: f }, f)));
  const ligands = el('ul', { id: 'ligands' });
  for (const l of data.ligands)
    ligands.append(el('li', {}, l.id + (l.kept ? ' (kept in the structure)' : '') +
      (l.site ? ` in site ${l.site}` : l.nearest_site ? `: nearest site ${l.nearest_site}, ${fixed(l.distance, 1)} Å` : '')));
  const side = el('section', { id: 'tables' },
    el('h2', {}, 'Sites'), el('p', { class: 'hint' }, 'Click a row to focus the view on its site (the others fade), again to see all; click in the view to find the site.'), sites,
    el('h2', {}, 'Tunnels'), data.tunnels.length ? tunnels : el('p', {}, 'No tunnels.'),
    el('h2', {}, 'Ligands and other hetero groups'), data.ligands.length ? ligands : el('p', {}, 'None.'),
    el('h2', {}, 'Parameters'), params,
    el('h2', {}, 'Files'), files);
  document.body.append(header, el('main', {}, viewer, side));

  // The site colours of the scene: its primitives groups' tooltips name the site.
  function siteColor(rank) {
    for (const n of data.mvs.root.children || [])
      if (n.kind === 'primitives' && n.params && n.params.tooltip && n.params.tooltip.startsWith(`site ${rank} (`))
        return n.params.color;
    return '#ccc';
  }

  // Each site's extent for focusing and picking: its centre and the sphere
  // around its space (from the scene's spheres, or its centre alone).
  const extents = data.sites.map(s => {
    const c = s.center;
    let radius = 4;
    for (const n of data.mvs.root.children || []) {
      if (n.kind !== 'primitives' || !n.params.tooltip || !n.params.tooltip.startsWith(`site ${s.rank} (`)) continue;
      for (const p of n.children || []) {
        if (p.params.kind === 'ellipsoid')
          radius = Math.max(radius, Math.hypot(p.params.center[0] - c[0], p.params.center[1] - c[1], p.params.center[2] - c[2]) + p.params.radius);
        else if (p.params.kind === 'mesh')
          for (let i = 0; i + 2 < p.params.vertices.length; i += 3)
            radius = Math.max(radius, Math.hypot(p.params.vertices[i] - c[0], p.params.vertices[i + 1] - c[1], p.params.vertices[i + 2] - c[2]));
      }
    }
    return { center: c, radius };
  });

  function selectRow(index) {
    sites.querySelectorAll('tbody tr').forEach(tr => tr.classList.toggle('selected', Number(tr.dataset.index) === index));
    const row = sites.querySelector(`tbody tr[data-index="${index}"]`);
    if (row) row.scrollIntoView({ block: 'nearest' });
  }

  // The structure for the scene: its download node's URL made a data URL of the embedded text.
  // (The fragment names the format for Mol*'s check of file extensions.)
  const mvs = JSON.parse(JSON.stringify(data.mvs));
  for (const n of mvs.root.children)
    if (n.kind === 'download') n.params.url = 'data:text/plain;charset=utf-8,' + encodeURIComponent(data.structure) + '#structure.cif';

  window.alphapocket = { data, ready: false, focused: null };
  molstar.Viewer.create('viewer', {
    layoutIsExpanded: false, layoutShowControls: false, layoutShowRemoteState: false, layoutShowSequence: false,
    layoutShowLog: false, layoutShowLeftPanel: false, viewportShowExpand: false, viewportShowSelectionMode: false,
    viewportShowAnimation: false, viewportShowScreenshotControls: false, volumeStreamingDisabled: true,
    collapseLeftPanel: true, pixelScale: 1,
  }).then(async v => {
    await v.loadMvsData(JSON.stringify(mvs), 'mvsj');
    // Mol* keeps the scene as a list of one state snapshot and draws a
    // snapshot switcher and title over the view while the list is not empty;
    // the scene stays applied when the list is emptied.
    v.plugin.managers.snapshot.clear();
    const camera = v.plugin.canvas3d.camera;
    window.alphapocket.viewer = v;
    // The sites' and tunnels' drawn parts: the representations under the
    // scene's nodes site-N (a space), site-N-lining (its residues) and
    // path-N (a tunnel; rank 0), Mol* tagging a node's state cell with its ref.
    const state = v.plugin.state.data;
    const siteParts = [];
    state.cells.forEach(cell => {
      if (!cell.obj || !cell.obj.data || !cell.obj.data.repr) return;
      for (let t = cell.transform; ;) {
        const m = (t.tags || []).map(tag => /^mvs-ref:(?:site-(\d+)(-lining)?|path-\d+)$/.exec(tag)).find(Boolean);
        if (m) {
          siteParts.push({ rank: Number(m[1] || 0), lining: Boolean(m[2]), ref: cell.transform.ref, repr: cell.obj.data.repr });
          break;
        }
        const up = state.tree.transforms.get(t.parent);
        if (!up || up === t) break;
        t = up;
      }
    });
    // While a site is focused the other sites fade (their spaces
    // see-through, their residues hidden) and the tunnels are hidden (their
    // cyan spheres would cover a site they start from). rank null: all as
    // the scene has it.
    const showOnly = rank => {
      for (const p of siteParts) {
        const other = rank !== null && p.rank !== rank;
        if (p.lining || p.rank === 0) state.updateCellState(p.ref, { isHidden: other });
        else p.repr.setState({ alphaFactor: other ? 0.15 : 1 });
      }
      v.plugin.canvas3d.requestDraw();
    };
    window.alphapocket.unfocus = () => {
      showOnly(null);
      v.plugin.managers.camera.reset();
      window.alphapocket.focused = null;
      selectRow(-1);
    };
    window.alphapocket.focus = index => {
      const e = extents[index];
      // The site and its surroundings, seen from outside the molecule along
      // the line from the scene's centre through the site (sites sit near
      // the surface: the others are then seldom in front of it).
      const middle = v.plugin.canvas3d.boundingSphere.center;
      let out = [0, 1, 2].map(k => e.center[k] - middle[k]);
      if (Math.hypot(...out) < 1e-3) out = [0, 1, 2].map(k => camera.state.position[k] - camera.state.target[k]);
      const from = { target: e.center, position: [0, 1, 2].map(k => e.center[k] + out[k]) };
      camera.setState(camera.getFocus(e.center, Math.max(12, e.radius + 6), undefined, undefined, from), 0);
      showOnly(data.sites[index].rank);
      window.alphapocket.focused = index;
      selectRow(index);
    };
    // A click on a row focuses its site; on the focused row, shows all again.
    sites.querySelectorAll('tbody tr').forEach(tr => tr.addEventListener('click', () => {
      const index = Number(tr.dataset.index);
      if (window.alphapocket.focused === index) window.alphapocket.unfocus();
      else window.alphapocket.focus(index);
    }));
    // A click in the view: the site whose space holds the point (or is
    // nearest its centre, within 8 Å).
    v.plugin.behaviors.interaction.click.subscribe(ev => {
      const p = ev.position;
      if (!p) return;
      let best = -1, bestD = Infinity;
      extents.forEach((e, i) => {
        const d = Math.hypot(p[0] - e.center[0], p[1] - e.center[1], p[2] - e.center[2]);
        const score = d <= e.radius ? d / e.radius : d <= 8 ? 1 + d : Infinity;
        if (score < bestD) [best, bestD] = [i, score];
      });
      if (best >= 0) selectRow(best);
    });
    window.alphapocket.ready = true;
  }).catch(err => {
    console.error('alphapocket: the 3D view failed:', err);
    viewer.append(el('p', { class: 'error' }, 'The 3D view failed: ' + err));
  });
})();

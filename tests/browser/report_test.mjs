// SPDX-License-Identifier: Apache-2.0
// report.html of `alphapocket pockets` in a real browser: Debian's chromium,
// headless, driven by puppeteer-core (report_assets/node_modules, `npm ci`),
// started by this script. One case per CTest test:
//
//   node report_test.mjs ALPHAPOCKET REPO_ROOT CASE [SCREENSHOT]
//
//   page_1a26A  the page opened from file:// after OUTDIR was moved, every
//               request that is not file: or data: refused (and counted):
//               no console error, no page error, no such request; the
//               viewer's canvas shows the structure (non-white pixels); the
//               sites table has one row per site of report.json; clicking
//               row 2 points the camera at site 2's centre (and site 2's
//               colour covers 2% or more of the middle of the view);
//               clicking the middle of the view then highlights the row
//               of the site there.
//   casts_3stdA the same with meshes (--mesh ply): the casts are drawn.
//   predicted   an AlphaFold model: the same checks but site 2's colour (the
//               pLDDT cartoon has the sites' hues), pLDDT colours in the scene.
//   injection   a file name and a chain name holding <script> and markup:
//               they stay text (the page shows them verbatim, no script of
//               theirs runs, no element of theirs exists).
// SCREENSHOT: where to keep the view after clicking row 2 (a PNG).
import { createRequire } from 'node:module';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';

const [exe, root, caseName, screenshot] = process.argv.slice(2);
const require = createRequire(path.join(root, 'report_assets', 'package.json'));
const puppeteer = require('puppeteer-core');

function fail(message) {
  console.error(`FAIL [${caseName}]: ${message}`);
  process.exit(1);
}

const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'report_test.'));
process.on('exit', () => fs.rmSync(tmp, { recursive: true, force: true }));

function pockets(input, outdir, ...args) {
  execFileSync(exe, ['-q', 'pockets', input, '-o', outdir, ...args], { stdio: ['ignore', 'ignore', 'inherit'] });
}

// The case's output directory, moved after writing: the page must not depend on where it was made.
function outputs() {
  const data = path.join(root, 'tests', 'data');
  let input, args = [];
  if (caseName === 'page_1a26A') input = path.join(root, 'examples', 'data', '1a26A.pdb');
  else if (caseName === 'casts_3stdA') [input, args] = [path.join(data, '3stdA.pdb'), ['--mesh', 'ply']];
  else if (caseName === 'predicted') input = path.join(data, 'AF-X6R8D5-F1-model_v1.pdb.gz');
  else if (caseName === 'injection') {
    // 1fkgA with its chain renamed to markup, in a file whose name is markup too.
    input = path.join(tmp, '<img src=x onerror=alert(1)><script>alert(2).pdb');
    const chain = 'X';
    const lines = fs.readFileSync(path.join(data, '1fkgA.pdb'), 'latin1').split('\n')
      .map(l => (/^(ATOM|HETATM)/.test(l) ? l.slice(0, 21) + chain + l.slice(22) : l));
    fs.writeFileSync(input, lines.join('\n'));
    // A CIF can name a chain with more than one character.
    const cif = path.join(tmp, 'markup.cif');
    execFileSync('/usr/bin/python3', ['-c', `
import gemmi, sys
st = gemmi.read_structure(sys.argv[1])
for ch in st[0]: ch.name = '<script>alert(3)</script>'
st.setup_entities()
doc = st.make_mmcif_document()
doc.write_file(sys.argv[2])`, input, cif]);
    fs.renameSync(cif, input.replace(/\.pdb$/, '.cif'));
    fs.rmSync(input);
    input = input.replace(/\.pdb$/, '.cif');
  } else fail('unknown case');
  const made = path.join(tmp, 'made');
  pockets(input, made, ...args);
  const moved = path.join(tmp, 'moved', 'out');
  fs.mkdirSync(path.dirname(moved));
  fs.renameSync(made, moved);
  return { dir: moved, input };
}

function hex(color) {
  return [1, 3, 5].map(i => parseInt(color.slice(i, i + 2), 16));
}

const { dir, input } = outputs();
const report = JSON.parse(fs.readFileSync(path.join(dir, 'report.json'), 'utf8'));
const mvs = JSON.parse(fs.readFileSync(path.join(dir, 'scene.mvsj'), 'utf8'));

const browser = await puppeteer.launch({
  executablePath: '/usr/bin/chromium',
  headless: true,
  args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--window-size=1400,800'],
  defaultViewport: { width: 1400, height: 800 },
});
try {
  const page = await browser.newPage();
  const problems = [], remote = [];
  page.on('console', async m => {
    if (m.type() !== 'error') return;
    const args = await Promise.all(m.args().map(a => a.evaluate(v => (v instanceof Error ? v.stack : String(v))).catch(() => '?')));
    problems.push('console error: ' + m.text() + ' ' + args.join(' '));
  });
  page.on('pageerror', e => problems.push('page error: ' + e.message));
  page.on('dialog', d => { problems.push('a dialog opened: ' + d.message()); d.dismiss(); });
  await page.setRequestInterception(true);
  page.on('request', r => {
    if (/^(file|data|blob):/.test(r.url())) r.continue();
    else { remote.push(r.url()); r.abort(); }
  });
  const t0 = Date.now();
  await page.goto('file://' + path.join(dir, 'report.html'), { waitUntil: 'load', timeout: 240000 });
  console.log(`loaded in ${Date.now() - t0} ms`);
  await page.waitForFunction('window.alphapocket && (window.alphapocket.ready || document.querySelector(".error"))',
                             { timeout: 240000 });
  console.log(`ready in ${Date.now() - t0} ms`);
  await new Promise(r => setTimeout(r, 1500));  // the first frames
  if (remote.length) fail('requests left the machine: ' + remote.join(' '));
  if (problems.length) fail(problems.join('; '));
  if (!(await page.evaluate('window.alphapocket.ready'))) fail('the viewer did not load');

  const rows = await page.$$eval('#sites tbody tr', trs => trs.length);
  if (rows !== report.sites.length) fail(`${rows} rows in the sites table, report.json has ${report.sites.length} sites`);

  // Pixels of the viewer: decoded in the page from a PNG screenshot.
  async function viewPixels() {
    const box = await (await page.$('#viewer')).boundingBox();
    const png = await page.screenshot({ clip: box, encoding: 'base64' });
    return page.evaluate(async (png) => {
      const img = new Image();
      img.src = 'data:image/png;base64,' + png;
      await img.decode();
      const c = document.createElement('canvas');
      [c.width, c.height] = [img.width, img.height];
      const g = c.getContext('2d');
      g.drawImage(img, 0, 0);
      return { width: c.width, height: c.height, data: Array.from(g.getImageData(0, 0, c.width, c.height).data) };
    }, png);
  }
  // The structure drawn: 5% of the view not white, within a minute (a
  // loaded machine draws the first frames late).
  let coloured = 0, total = 1;
  for (const t0 = Date.now(); Date.now() - t0 < 60000; await new Promise(r => setTimeout(r, 1000))) {
    const before = await viewPixels();
    coloured = 0;
    total = before.width * before.height;
    for (let i = 0; i < before.data.length; i += 4) if (before.data[i] + before.data[i + 1] + before.data[i + 2] < 720) ++coloured;
    if (coloured >= total * 0.05) break;
  }
  if (coloured < total * 0.05) fail(`the view is blank: ${coloured} of ${total} pixels not white`);

  // What the page says beside the view: version, parameters, files, ligands, tunnels.
  const summary = await page.$eval('header .summary', e => e.textContent);
  if (!summary.includes('alphapocket ' + report.alphapocket)) fail('the version is not shown: ' + summary);
  const shownParameters = await page.$$eval('#parameters dt', ds => ds.map(d => d.textContent));
  if (shownParameters.join() !== Object.keys(report.parameters).join()) fail('parameters shown: ' + shownParameters);
  const links = await page.$$eval('#files a', as => as.map(a => a.getAttribute('href')));
  for (const f of ['report.json', 'sites.csv', 'structure.cif', 'scene.mvsj'])
    if (!links.includes(f)) fail(`no link to ${f}: ${links}`);
  for (const f of links) if (!fs.existsSync(path.join(dir, f))) fail(`a link to ${f}, which is not in the directory`);
  const ligandItems = await page.$$eval('#ligands li', ls => ls.map(l => l.textContent));
  if (ligandItems.length !== report.ligands.length) fail(`${ligandItems.length} ligands listed, report.json has ${report.ligands.length}`);
  const labels = mvs.root.children.filter(n => n.kind === 'primitives').flatMap(n => n.children || [])
    .filter(p => p.params.kind === 'label').map(p => p.params.text);
  for (const l of report.ligands) if (!labels.some(t => l.id.startsWith(t))) fail(`ligand ${l.id} is not named in the view: ${labels}`);
  const plots = await page.$$eval('#tunnels svg.profile polyline', ps => ps.length);
  const profiled = report.tunnels.filter(t => t.profile.length >= 2).length;
  if (plots !== profiled) fail(`${plots} radius profiles plotted, ${profiled} tunnels have one`);
  const tunnelGroups = mvs.root.children.filter(n => n.kind === 'primitives' && /^(tunnel|pore)/.test(n.params.tooltip || ''));
  if (report.tunnels.length && !(tunnelGroups.length >= 1 && tunnelGroups.length <= report.tunnels.length))
    fail(`${tunnelGroups.length} tunnels drawn, report.json has ${report.tunnels.length}`);
  // Casts when meshes were written, else spheres; pLDDT colours for a predicted model.
  const siteShapes = mvs.root.children.filter(n => n.kind === 'primitives' && /^site /.test(n.params.tooltip || ''))
    .flatMap(n => n.children.map(p => p.params.kind));
  const wanted = caseName === 'casts_3stdA' ? 'mesh' : 'ellipsoid';
  if (!siteShapes.length || siteShapes.some(k => k !== wanted)) fail(`the sites are drawn as ${[...new Set(siteShapes)]}, not ${wanted}`);
  const cartoonColors = JSON.stringify(mvs).match(/"type":"cartoon"[^\]]*/)[0].match(/#[0-9A-F]{6}/g);
  const bands = ['#0053D6', '#65CBF3', '#FFDB13', '#FF7D45'];
  if (report.input.predicted !== (caseName === 'predicted')) fail('report.json: predicted is ' + report.input.predicted);
  if ((caseName === 'predicted') !== cartoonColors.some(c => bands.includes(c))) fail('pLDDT colours: ' + cartoonColors);
  if (caseName === 'predicted' && !(await page.$$eval('#sites th', ths => ths.some(t => t.textContent === 'pLDDT'))))
    fail('no pLDDT column in the sites table');

  if (caseName === 'injection') {
    const shown = await page.$eval('#structure-name', e => e.textContent);
    if (shown !== input) fail(`the file name is shown as ${JSON.stringify(shown)}, not verbatim`);
    const foreign = await page.evaluate(() =>
      document.querySelectorAll('img, script:not([src]):not([type="application/json"])').length);
    if (foreign) fail(`${foreign} elements made from the input's names`);
    const residues = await page.$eval('#sites tbody tr td:nth-child(9) span', e => e.title);
    if (!residues.includes('<script>alert(3)</script>:')) fail('the chain name is not shown as text: ' + residues);
  }

  if (report.sites.length >= 2) {
    // Row 2 -> the camera on site 2.
    await page.click('#sites tbody tr:nth-child(2)');
    await new Promise(r => setTimeout(r, 1000));
    const target = await page.evaluate('Array.from(window.alphapocket.viewer.plugin.canvas3d.camera.state.target)');
    const center = report.sites[1].center;
    const off = Math.hypot(target[0] - center[0], target[1] - center[1], target[2] - center[2]);
    if (off > 0.01) fail(`after clicking row 2 the camera looks at ${target}, site 2's centre is ${center}`);
    const selected = await page.$$eval('#sites tbody tr.selected', trs => trs.map(t => t.dataset.index));
    if (selected.join() !== '1') fail('row 2 is not highlighted after clicking it: ' + selected);
    // ... and site 2's colour covers 2% or more of the middle of the view
    // (polled: a loaded machine draws the new frame late).
    // Pixels by hue (the see-through surface greys colours, keeping their
    // hue): each coloured pixel goes to the scene colour nearest in hue
    // (sites, tunnels, ligands), within 8 degrees.
    const hue = ([r, g, b]) => {
      const max = Math.max(r, g, b), min = Math.min(r, g, b), d = max - min;
      if (d === 0) return null;
      const h = max === r ? ((g - b) / d) % 6 : max === g ? (b - r) / d + 2 : (r - g) / d + 4;
      return { h: (h * 60 + 360) % 360, s: d / max };
    };
    const colors = mvs.root.children.filter(n => n.kind === 'primitives' && n.params.color)
      .map(n => ({ rank: /^site \d+ /.test(n.params.tooltip || '') ? Number(n.params.tooltip.split(' ')[1]) : 0,
                   h: hue(hex(n.params.color)).h }));
    colors.push({ rank: 0, h: hue([255, 255, 0]).h });  // the ligands
    let ranked = [], middle = 1;
    const siteTwoShown = () => ranked.some(([rank, n]) => rank === 2 && n >= 0.02 * middle);
    for (const t0 = Date.now(); caseName !== 'predicted' && Date.now() - t0 < 30000 && !siteTwoShown(); await new Promise(r => setTimeout(r, 1000))) {
      const shot = await viewPixels();
      const counts = new Map();
      const [w, h] = [shot.width, shot.height];
      for (let y = Math.floor(h * 0.35); y < h * 0.65; ++y)
        for (let x = Math.floor(w * 0.35); x < w * 0.65; ++x) {
          const i = 4 * (y * w + x), p = hue(shot.data.slice(i, i + 3));
          if (!p || p.s < 0.2) continue;
          let best = null, bestD = 8;
          for (const c of colors) {
            const d = Math.min(Math.abs(p.h - c.h), 360 - Math.abs(p.h - c.h));
            if (d < bestD) [best, bestD] = [c.rank, d];
          }
          if (best) counts.set(best, (counts.get(best) || 0) + 1);
        }
      ranked = [...counts.entries()].sort((a, b) => b[1] - a[1]);
      middle = (Math.floor(h * 0.65) - Math.floor(h * 0.35)) * (Math.floor(w * 0.65) - Math.floor(w * 0.35));
    }
    // (Not for the predicted model: its pLDDT-coloured cartoon has the
    // sites' hues, orange and blue, so hue cannot tell them apart.)
    if (caseName !== 'predicted' && !siteTwoShown())
      fail('site 2 covers less than 2% of the middle of the view after focusing it: ' + JSON.stringify(ranked));
    if (screenshot) {
      const box = await (await page.$('main')).boundingBox();
      await page.screenshot({ path: screenshot, clip: box });
    }
    console.log(`site colours in the middle after focusing site 2 (rank, pixels of ${middle}): ${JSON.stringify(ranked)}`);
    // A click on the middle of the view highlights the row of the site there
    // (1a26A: site 2's space is there).
    if (caseName === 'page_1a26A') {
      await page.$$eval('#sites tbody tr', trs => trs.forEach(t => t.classList.remove('selected')));
      const box = await (await page.$('#viewer canvas')).boundingBox();
      await page.mouse.click(box.x + box.width / 2, box.y + box.height / 2);
      for (const t0 = Date.now(); Date.now() - t0 < 20000; await new Promise(r => setTimeout(r, 500)))
        if (await page.$('#sites tbody tr.selected')) break;
      const picked = await page.$$eval('#sites tbody tr.selected', trs => trs.map(t => t.dataset.index));
      if (picked.length !== 1) fail('clicking a site in the view highlights rows ' + JSON.stringify(picked));
    }
  }
  if (problems.length) fail(problems.join('; '));
  if (remote.length) fail('requests left the machine: ' + remote.join(' '));
  console.log(`ok [${caseName}]: ${rows} sites`);
} finally {
  await browser.close();
}

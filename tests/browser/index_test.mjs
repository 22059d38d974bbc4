// SPDX-License-Identifier: Apache-2.0
// index.html of `alphapocket batch` and `merge` in a real browser (Debian's
// chromium, headless, puppeteer-core; started here), opened from file://
// with every request that is not file: or data: refused:
//
//   node index_test.mjs ALPHAPOCKET REPO_ROOT CASE
//
//   batch      a batch run of three chains and a broken file, --outputs
//              report,html: no console or page error, no request out; one
//              structure row per input and one site row per row of
//              sites.csv (the rows in view drawn, the count shown); the
//              failure listed; sorting by probability puts the largest
//              first (and again the smallest); filtering by a ligand and
//              by a least probability leaves exactly the sites.csv rows
//              that match; a structure's link opens its report.html,
//              which loads with its viewer from OUTDIR/viewer.
//   synthetic  `merge` of a synthetic records file of 10,000 structures
//              and 100,000 sites: the first screen is drawn, only a screen
//              of rows exists in the page, and after sorting 100,000 sites
//              filtering leaves exactly the matching ones. The times
//              (first screen, sort, filter) are printed, not asserted:
//              bench/index_page.sh takes their medians.
import { createRequire } from 'node:module';
import { execFileSync, spawnSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';

const [exe, root, caseName] = process.argv.slice(2);
const require = createRequire(path.join(root, 'report_assets', 'package.json'));
const puppeteer = require('puppeteer-core');

function fail(message) {
  console.error(`FAIL [${caseName}]: ${message}`);
  process.exit(1);
}
const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'index_test.'));
process.on('exit', () => fs.rmSync(tmp, { recursive: true, force: true }));

// A CSV file's rows as objects (fields quoted with "" where needed).
function readCsv(file) {
  const text = fs.readFileSync(file, 'utf8');
  const rows = [];
  let row = [], field = '', quoted = false;
  for (let i = 0; i < text.length; ++i) {
    const c = text[i];
    if (quoted) {
      if (c === '"' && text[i + 1] === '"') { field += '"'; ++i; } else if (c === '"') quoted = false; else field += c;
    } else if (c === '"') quoted = true;
    else if (c === ',') { row.push(field); field = ''; } else if (c === '\n') { row.push(field); rows.push(row); row = []; field = ''; } else field += c;
  }
  const [head, ...body] = rows;
  return body.map(r => Object.fromEntries(head.map((h, k) => [h, r[k]])));
}

function syntheticRun(dir, structures, sitesEach) {
  fs.mkdirSync(dir);
  const lines = [];
  for (let i = 0; i < structures; ++i) {
    const id = 'S' + String(i).padStart(5, '0');
    const sites = [];
    for (let k = 1; k <= sitesEach; ++k) {
      const p = ((i * 7919 + k * 104729) % 1000) / 1000;
      sites.push([k, 'pocket', k, p * 2, p, 50 + (i * k) % 900, 80 + (i * k) % 1200, 100, 150, 5 + k % 9, 1 + k % 3, 20, 0.5, 40,
                  2.5, i % 100, k, 0, 70 + k % 30, 12, `A:TYR:${k} A:LEU:${k + 3}`, k === 1 && i % 10 === 0 ? `A:ATP:${900 + i % 7}` : '']);
    }
    sites.sort((a, b) => b[4] - a[4]).forEach((s, k) => { s[0] = k + 1; });
    lines.push(JSON.stringify({ id, path: `/data/${id}.pdb`, checksum: 'x', key: 'k', status: 'ok', category: '', message: '',
      seconds: 1, rows: { structure: ['pdb', 0, 2000 + i % 3000, sitesEach, 0, sitesEach, 0, 9000, 20000, null], sites, tunnels: [] } }));
  }
  fs.writeFileSync(path.join(dir, 'records.jsonl'), lines.join('\n') + '\n');
}

const browser = await puppeteer.launch({
  executablePath: '/usr/bin/chromium', headless: true,
  args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader'],
  defaultViewport: { width: 1400, height: 900 },
});
const problems = [], remote = [];
async function open(url) {
  const page = await browser.newPage();
  page.on('console', m => { if (m.type() === 'error') problems.push('console error: ' + m.text()); });
  page.on('pageerror', e => problems.push('page error: ' + e.message));
  await page.setRequestInterception(true);
  page.on('request', r => { if (/^(file|data|blob):/.test(r.url())) r.continue(); else { remote.push(r.url()); r.abort(); } });
  await page.goto(url, { waitUntil: 'load', timeout: 240000 });
  await page.waitForFunction('window.alphapocketIndex && window.alphapocketIndex.ready', { timeout: 240000 });
  return { page };
}
const checkClean = () => {
  if (problems.length) fail(problems.join('; '));
  if (remote.length) fail('requests left the machine: ' + remote.join(' '));
};
const shownRows = (page, table) => page.$$eval(`#${table}-rows .vrow`, rs => rs.map(r => r.dataset.row));
const count = (page, table) => page.evaluate(t => window.alphapocketIndex[t].view().length, table);
async function setInput(page, id, value) {
  await page.$eval('#' + id, (e, v) => { e.value = v; e.dispatchEvent(new Event('input')); }, value);
}

try {
  if (caseName === 'batch') {
    const data = path.join(root, 'tests', 'data');
    const broken = path.join(tmp, 'broken.pdb');
    fs.writeFileSync(broken, 'ATOM  garbage\n');
    const out = path.join(tmp, 'run');
    const run = spawnSync(exe, ['-q', 'batch', path.join(data, '1fkgA.pdb'), path.join(data, '1ytjA.pdb'), path.join(data, '1grm_single.pdb'),
      broken, '-o', out, '--outputs', 'report,html'], { encoding: 'utf8' });
    if (!fs.existsSync(path.join(out, 'index.html'))) fail('no index.html: ' + run.stderr);
    const sitesCsv = readCsv(path.join(out, 'sites.csv'));
    const { page } = await open('file://' + path.join(out, 'index.html'));
    checkClean();
    if (await count(page, 'structures') !== 4) fail(`${await count(page, 'structures')} structure rows, 4 inputs`);
    if (await count(page, 'sites') !== sitesCsv.length) fail(`${await count(page, 'sites')} site rows, sites.csv has ${sitesCsv.length}`);
    const failures = await page.$$eval('#failures tbody tr', rs => rs.map(r => r.textContent));
    if (failures.length !== 1 || !failures[0].includes('broken')) fail('failures listed: ' + JSON.stringify(failures));
    // Sort by probability: largest first, then smallest first.
    const probabilities = sitesCsv.map(s => Number(s.probability)).sort((a, b) => a - b);
    const header = '#sites .vhead [data-column="probability"]';
    const firstProbability = () => page.evaluate(() => {
      const t = window.alphapocketIndex.sites, k = window.alphapocketIndex.siteColumns.indexOf('probability');
      return t.rows[t.view()[0]][k];
    });
    await page.click(header);
    if (Math.abs(await firstProbability() - probabilities[probabilities.length - 1]) > 1e-3) fail('sorting by probability does not put the largest first');
    await page.click(header);
    if (Math.abs(await firstProbability() - probabilities[0]) > 1e-3) fail('sorting again does not put the smallest first');
    // Filters against sites.csv.
    const ligand = sitesCsv.find(s => s.ligands)?.ligands.split(' ')[0];
    if (!ligand) fail('no site holds a ligand in this run');
    await setInput(page, 'filter-text', ligand);
    const expected = sitesCsv.filter(s => [s.structure_id, s.residues, s.ligands].some(v => v.toLowerCase().includes(ligand.toLowerCase()))).length;
    if (await count(page, 'sites') !== expected) fail(`filtering by ${ligand} leaves ${await count(page, 'sites')} sites, sites.csv ${expected}`);
    await setInput(page, 'filter-text', '');
    await setInput(page, 'filter-probability', '0.5');
    const likely = sitesCsv.filter(s => Number(s.probability) >= 0.5).length;
    if (await count(page, 'sites') !== likely) fail(`probability >= 0.5 leaves ${await count(page, 'sites')} sites, sites.csv ${likely}`);
    // A structure's link opens its page, whose viewer is OUTDIR/viewer.
    const link = await page.$eval('#structures-rows a', a => a.href);
    const report = await browser.newPage();
    report.on('pageerror', e => problems.push('report page error: ' + e.message));
    report.on('console', m => { if (m.type() === 'error') problems.push('report console error: ' + m.text()); });
    await report.setRequestInterception(true);
    report.on('request', r => { if (/^(file|data|blob):/.test(r.url())) r.continue(); else { remote.push(r.url()); r.abort(); } });
    await report.goto(link, { waitUntil: 'load', timeout: 240000 });
    await report.waitForFunction('window.alphapocket && window.alphapocket.ready', { timeout: 240000 });
    checkClean();
    console.log(`ok [batch]: 4 structures, ${sitesCsv.length} sites`);
  } else if (caseName === 'synthetic') {
    const chunk = path.join(tmp, 'chunk');
    syntheticRun(chunk, 10000, 10);
    const out = path.join(tmp, 'merged');
    execFileSync(exe, ['-q', 'merge', chunk, '-o', out], { stdio: ['ignore', 'ignore', 'inherit'] });
    const size = fs.statSync(path.join(out, 'index.html')).size;
    const { page } = await open('file://' + path.join(out, 'index.html'));
    checkClean();
    // From navigation start to the first screen painted, as the page measured it.
    const ms = Math.round(await page.evaluate('window.alphapocketIndex.firstScreenMs'));
    const timings = JSON.stringify(await page.evaluate('window.alphapocketIndex.timings'));
    if (!(ms > 0)) fail(`no first screen measured (${timings})`);
    if (await count(page, 'sites') !== 100000) fail(`${await count(page, 'sites')} site rows, 100,000 made`);
    const drawn = (await shownRows(page, 'sites')).length;
    if (drawn === 0 || drawn > 200) fail(`${drawn} site rows in the page (a screen expected)`);
    let t = Date.now();
    await page.click('#sites .vhead [data-column="sa_volume"]');
    const sortMs = Date.now() - t;
    t = Date.now();
    await setInput(page, 'filter-text', 'ATP');
    const filterMs = Date.now() - t;
    if (await count(page, 'sites') !== 1000) fail(`filtering by ATP leaves ${await count(page, 'sites')} sites, 1,000 made`);
    checkClean();
    console.log(`ok [synthetic]: index.html ${(size / 1e6).toFixed(1)} MB, first screen ${ms} ms (${timings}), sort ${sortMs} ms, filter ${filterMs} ms`);
  } else fail('unknown case');
} finally {
  await browser.close();
}

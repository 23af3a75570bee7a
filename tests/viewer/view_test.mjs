// Browser test of view.html (docs/viewer.md): headless Chromium (Debian's /usr/bin/chromium,
// driven by puppeteer-core from viewer/node_modules; never a downloaded browser) opens each
// folder's view.html from file:// and checks: no console error, page error or failed request;
// the canvas is not blank; moving the time slider to t turns the body to the trajectory's R(t)
// (window.attiguardView.state(), compared with DIR/trajectory.csv); a screenshot is saved.
//
// Usage: node view_test.mjs VIEWER_DIR SCREENSHOT_DIR DIR...
import { createRequire } from 'node:module';
import fs from 'node:fs';
import path from 'node:path';
import { pathToFileURL } from 'node:url';

const [viewerDir, shotDir, ...dirs] = process.argv.slice(2);
const require = createRequire(path.join(path.resolve(viewerDir), 'package.json'));
const puppeteer = require('puppeteer-core');
fs.mkdirSync(shotDir, { recursive: true });

function readCsv(file) {
  const lines = fs.readFileSync(file, 'utf8').trim().split('\n');
  const cols = lines[0].split(',');
  return { cols, rows: lines.slice(1).map((l) => l.split(',').map(Number)) };
}

/** Rotation angle [rad] between two scalar-first unit quaternions. */
function angleBetween(a, b) {
  const na = Math.hypot(...a);
  const nb = Math.hypot(...b);
  const dot = Math.abs(a.reduce((s, v, k) => s + v * b[k], 0) / (na * nb));
  return 2 * Math.acos(Math.min(1, dot));
}

let failures = 0;
function check(ok, what) {
  console.log(`${ok ? 'ok  ' : 'FAIL'} ${what}`);
  if (!ok) failures++;
}

const browser = await puppeteer.launch({
  executablePath: '/usr/bin/chromium',
  headless: true,
  args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--disable-dev-shm-usage'],
});
try {
  for (const dir of dirs) {
    const page = await browser.newPage();
    await page.setViewport({ width: 1300, height: 1300 });
    const problems = [];
    page.on('console', (m) => {
      if (m.type() === 'error') problems.push(`console error: ${m.text()}`);
    });
    page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
    page.on('requestfailed', (r) => problems.push(`failed request: ${r.url()}`));
    page.on('request', (r) => {
      if (!r.url().startsWith('file:') && !r.url().startsWith('data:') && !r.url().startsWith('blob:')) {
        problems.push(`network request: ${r.url()}`);
      }
    });
    const file = path.resolve(dir, 'view.html');
    await page.goto(pathToFileURL(file).href, { waitUntil: 'load' });
    await page.waitForFunction(() => window.attiguardView && (window.attiguardView.ready || window.attiguardView.failed), { timeout: 60000 });
    const kind = await page.evaluate(() => window.attiguardView.kind);
    const name = await page.evaluate(() => window.attiguardView.name);
    const tag = `${path.basename(dir)} (${kind})`;
    check(!(await page.evaluate(() => window.attiguardView.failed)), `${tag}: page built`);
    const stats = await page.evaluate(() => window.attiguardView.canvasStats());
    check(stats.nonBackground > 0.02 && stats.colours > 20,
      `${tag}: canvas not blank (${(100 * stats.nonBackground).toFixed(1)} % of pixels drawn, ${stats.colours} colours)`);

    if (kind !== 'campaign') {
      // The page's trajectory: trajectory.csv of a run, plan.csv of a plan (docs/viewer.md).
      const csv = readCsv(path.join(dir, kind === 'plan' ? 'plan.csv' : 'trajectory.csv'));
      const iq = csv.cols.indexOf('q_w');
      const it = csv.cols.indexOf('t');
      const tEnd = csv.rows[csv.rows.length - 1][it];
      const s0 = await page.evaluate(() => window.attiguardView.state());
      let moved = 0;
      for (const frac of [0.37, 0.81]) {
        // Move the slider as a user would: set its value and fire its input event.
        await page.evaluate((v) => {
          const s = document.getElementById('time-slider');
          s.value = String(v);
          s.dispatchEvent(new Event('input', { bubbles: true }));
        }, frac * tEnd);
        const st = await page.evaluate(() => window.attiguardView.state());
        // The page's numbers have 9 significant digits (app/view_page.hpp): a relative 1e-8.
        const row = csv.rows.find((r) => Math.abs(r[it] - st.t) <= 1e-8 * Math.max(1, Math.abs(st.t)));
        check(row !== undefined && Math.abs(st.t - frac * tEnd) <= tEnd / Math.max(1, st.rows_shown - 1),
          `${tag}: slider to t = ${(frac * tEnd).toFixed(3)} s shows the trajectory row t = ${st.t}`);
        if (row) {
          const q = row.slice(iq, iq + 4);
          const err = angleBetween(st.body_q, q);
          check(err < 1e-6, `${tag}: body attitude = R(t) of trajectory.csv (angle ${err.toExponential(2)} rad)`);
          moved = Math.max(moved, angleBetween(st.body_q, s0.body_q));
        }
      }
      check(moved > 1e-3, `${tag}: the body turned as the slider moved (${moved.toFixed(3)} rad)`);
    } else {
      // A click on a run's point shows its row.
      const clicked = await page.evaluate(() => {
        const c = document.getElementById('campaign-canvas');
        const r = c.getBoundingClientRect();
        for (let y = 0; y < c.height; y += 2) {
          for (let x = 0; x < c.width; x += 2) {
            const d = c.getContext('2d').getImageData(x, y, 1, 1).data;
            if (d[2] > 150 && d[0] < 80) {
              c.dispatchEvent(new MouseEvent('click', { clientX: r.left + (x * r.width) / c.width, clientY: r.top + (y * r.height) / c.height }));
              return window.attiguardView.selectedRun;
            }
          }
        }
        return undefined;
      });
      check(clicked !== undefined, `${tag}: a click on a run selects it (run ${clicked})`);
    }
    if (kind === 'pet_erg' && JSON.parse(fs.readFileSync(path.join(dir, 'summary.json'), 'utf8')).governor === 'planned') {
      // A planned slew (docs/pet-erg.md 16.2): the plan in place of the governor's reference,
      // the clock's strip (σ, ṡ) and ‖τ‖ against torque_bound in place of V and Γ.
      const legend = await page.evaluate(() => document.getElementById('legend').textContent);
      check(legend.includes('R_p(σ) a_b (plan at the governed clock') && !legend.includes('governor reference'),
        `${tag}: the qg trace is labelled as the plan R_p(σ)`);
      const titles = await page.evaluate(() => [...document.querySelectorAll('.strip')].map((b) => b.dataset.title));
      check(titles.some((x) => x.startsWith('plan clock σ')) && titles.some((x) => x.includes('torque_bound'))
        && !titles.some((x) => x.includes('threshold Γ')), `${tag}: strips ${titles.map((x) => x.split(' ').slice(0, 3).join(' ')).join(' | ')}`);
    }
    const shot = path.join(shotDir, `view_${kind}_${path.basename(dir)}.png`);
    await page.screenshot({ path: shot, fullPage: true });
    console.log(`     screenshot ${shot} (${name})`);
    check(problems.length === 0, `${tag}: no console error, failed or network request${problems.length ? ': ' + problems.join('; ') : ''}`);
    await page.close();
  }
} finally {
  await browser.close();
}
if (failures) {
  console.log(`${failures} check(s) failed`);
  process.exit(1);
}
console.log('all browser checks passed');

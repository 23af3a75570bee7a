// The campaign view (docs/viewer.md): a scatter of any figure of runs.csv against any other
// (default: the first margin against the first dispersed value), worst runs highlighted; a
// click on a run shows its row and how to replay it (a link to run_K/view.html when replayed
// with --view); the percentile envelopes of retained time series when the campaign kept them.

import { makeStrip } from './strips.js';

const FIXED = new Set(['run', 'seed', 'attempts', 'status', 'reason', 'outcome', 'outcome_reason']);

export function campaignView(root, data, series) {
  const runs = series('runs');
  const box = document.createElement('div');
  box.className = 'campaign';
  root.appendChild(box);
  const cols = runs ? runs.columns.filter((c) => !FIXED.has(c) && runs.col(c).some((v) => typeof v === 'number')) : [];
  const varying = cols.filter((c) => {
    const v = runs.col(c).filter((x) => typeof x === 'number');
    return v.length && Math.max(...v) > Math.min(...v);
  });
  const dispersed = varying.filter((c) => c.includes('.') || c.includes('['));
  const margin = varying.find((c) => c.includes('margin')) || varying.find((c) => !dispersed.includes(c)) || varying[0];
  const controls = document.createElement('div');
  controls.className = 'controls';
  const selX = document.createElement('select');
  const selY = document.createElement('select');
  selX.id = 'campaign-x';
  selY.id = 'campaign-y';
  for (const c of varying) {
    selX.add(new Option(c, c));
    selY.add(new Option(c, c));
  }
  selX.value = dispersed[0] || varying[0];
  selY.value = margin;
  controls.append('x: ', selX, '  y: ', selY, `  (${runs ? runs.n : 0} runs; columns that vary: ${varying.length})`);
  box.appendChild(controls);
  const canvas = document.createElement('canvas');
  canvas.width = 900;
  canvas.height = 420;
  canvas.id = 'campaign-canvas';
  box.appendChild(canvas);
  const detail = document.createElement('pre');
  detail.className = 'detail';
  detail.textContent = 'Click a run to see its row and how to replay it.';
  box.appendChild(detail);
  const ctx = canvas.getContext('2d');
  let points = [];

  function draw() {
    ctx.fillStyle = '#ffffff';
    ctx.fillRect(0, 0, canvas.width, canvas.height);
    if (!runs || !varying.length) {
      ctx.fillStyle = '#333';
      ctx.fillText('no column varies over the runs', 20, 30);
      return;
    }
    const xs = runs.col(selX.value);
    const ys = runs.col(selY.value);
    const ok = [];
    for (let i = 0; i < runs.n; i++) if (typeof xs[i] === 'number' && typeof ys[i] === 'number') ok.push(i);
    const xv = ok.map((i) => xs[i]);
    const yv = ok.map((i) => ys[i]);
    const [x0, x1] = [Math.min(...xv), Math.max(...xv)];
    const [y0, y1] = [Math.min(...yv), Math.max(...yv)];
    const L = 80;
    const T = 20;
    const W = canvas.width - L - 20;
    const H = canvas.height - T - 40;
    const X = (v) => L + (x1 > x0 ? (v - x0) / (x1 - x0) : 0.5) * W;
    const Y = (v) => T + (1 - (y1 > y0 ? (v - y0) / (y1 - y0) : 0.5)) * H;
    ctx.strokeStyle = '#ccc';
    ctx.strokeRect(L, T, W, H);
    ctx.fillStyle = '#333';
    ctx.font = '12px sans-serif';
    ctx.fillText(selY.value, 4, 14);
    ctx.fillText(selX.value, L + W / 2 - 40, canvas.height - 8);
    ctx.fillText(y1.toPrecision(4), 4, T + 10);
    ctx.fillText(y0.toPrecision(4), 4, T + H);
    ctx.fillText(x0.toPrecision(4), L, T + H + 14);
    ctx.fillText(x1.toPrecision(4), L + W - 50, T + H + 14);
    // The worst 1 % (at least 1) of the y column highlighted (lowest for margins).
    const order = ok.slice().sort((a, b) => ys[a] - ys[b]);
    const worst = new Set(order.slice(0, Math.max(1, Math.ceil(ok.length / 100))));
    points = [];
    const status = runs.col('status');
    for (const i of ok) {
      const px = X(xs[i]);
      const py = Y(ys[i]);
      ctx.fillStyle = worst.has(i) ? '#d62728' : status && status[i] !== 'ok' ? '#ff7f0e' : '#1f77b4';
      ctx.beginPath();
      ctx.arc(px, py, worst.has(i) ? 4 : 2.5, 0, 2 * Math.PI);
      ctx.fill();
      points.push({ i, px, py });
    }
    ctx.fillStyle = '#d62728';
    ctx.fillText(`red: the worst ${worst.size} run(s) by ${selY.value} (lowest)`, L + 8, T + 14);
  }

  canvas.addEventListener('click', (ev) => {
    const rect = canvas.getBoundingClientRect();
    const x = ((ev.clientX - rect.left) * canvas.width) / rect.width;
    const y = ((ev.clientY - rect.top) * canvas.height) / rect.height;
    let best = null;
    for (const p of points) {
      const d = Math.hypot(p.px - x, p.py - y);
      if (d < 10 && (!best || d < best.d)) best = { ...p, d };
    }
    if (best) showRun(runs.col('run')[best.i]);
  });

  function showRun(k) {
    const i = runs.col('run').indexOf(k);
    if (i < 0) return;
    const lines = runs.columns.map((c) => `${c} = ${runs.col(c)[i]}`);
    const replayed = (data.replayed || []).find((r) => r.dir === `run_${k}`);
    detail.textContent = `run ${k}\n${lines.join('\n')}\n\nReplay it: attiguard campaign SCENARIO --seed S --out ${data.source_dir} --replay ${k} --view\n`;
    if (replayed && replayed.has_view) {
      const a = document.createElement('a');
      a.href = `run_${k}/view.html`;
      a.textContent = `open run_${k}/view.html`;
      detail.appendChild(a);
    }
    window.attiguardView.selectedRun = k;
  }

  // Envelopes of the retained time series (DIR/retained.h5): min, 1 %, 50 %, 99 %, max over
  // the runs at each t, the worst runs in red; a button per worst run shows its row.
  if (data.envelopes) {
    const env = data.envelopes;
    const head = document.createElement('h3');
    head.textContent = `Retained time series (retained.h5): percentile envelopes over ${env.runs} runs`;
    box.appendChild(head);
    for (const c of env.columns) {
      const counts = c.count.filter((x) => x !== null);
      const lines = [
        { label: 'min', values: c.min, color: '#7f7f7f' },
        { label: 'p1', values: c.p1, color: '#1f77b4' },
        { label: 'p50', values: c.p50, color: '#000000' },
        { label: 'p99', values: c.p99, color: '#1f77b4' },
        { label: 'max', values: c.max, color: '#7f7f7f' },
        ...c.worst.map((w, k) => ({ label: `run ${w.run}`, values: w.values, color: ['#d62728', '#e377c2', '#ff7f0e'][k % 3] })),
      ];
      const title = `${c.column}: envelopes over ${Math.min(...counts)}–${Math.max(...counts)} runs per t; red: worst runs (${c.column.includes('margin') ? 'lowest minimum' : 'highest maximum'})`;
      const strip = makeStrip(box, env.t, title, lines, { height: 170 });
      strip.draw(NaN);
      const buttons = document.createElement('div');
      buttons.className = 'controls';
      for (const w of c.worst) {
        const b = document.createElement('button');
        b.textContent = `run ${w.run}`;
        b.onclick = () => showRun(w.run);
        buttons.appendChild(b);
      }
      box.appendChild(buttons);
    }
  }

  selX.onchange = draw;
  selY.onchange = draw;
  draw();
  return { canvas, draw, showRun };
}

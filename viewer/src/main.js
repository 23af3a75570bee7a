// attiguard viewer (docs/viewer.md): one page per result folder, opened from file:// with no
// network. Reads the JSON of <script id="attiguard-data">, builds the scene of the folder's
// kind, the time slider with play / pause / speed and the strips, and exposes its state as
// window.attiguardView for the browser test (tests/viewer/view_test.mjs).
import { loadData, series as seriesOf, decimationNote, indexAt } from './data.js';
import { makeRenderer, BACKGROUND, THREE } from './scene.js';
import { attitudeScene, insetScene, quaternions } from './attitude.js';
import { pathScene } from './path.js';
import { reachScene } from './reach.js';
import { campaignView } from './campaign.js';
import { makeStrip } from './strips.js';

const STYLE = `
body { font-family: sans-serif; margin: 0; background: #eef1f6; color: #222; }
header { padding: 8px 14px; background: #24324a; color: #fff; }
header h1 { font-size: 18px; margin: 0 0 2px 0; }
header .sub { font-size: 13px; opacity: 0.85; }
#wrap { display: flex; gap: 10px; padding: 10px; }
#scene { position: relative; }
#legend { font-size: 12px; max-width: 330px; line-height: 1.4; }
#legend li { margin-bottom: 4px; }
.controls { padding: 4px 10px; font-size: 13px; display: flex; align-items: center; gap: 8px; }
#time-slider { width: 600px; }
.strip canvas { display: block; margin: 4px 10px; border: 1px solid #ccd; width: 900px; }
.campaign { padding: 10px; }
.campaign canvas { border: 1px solid #ccd; background: #fff; }
.detail { font-size: 12px; background: #fff; padding: 6px; max-height: 260px; overflow: auto; }
.note { font-size: 12px; color: #555; padding: 0 10px; }
`;

const SCENE_W = 900;
const SCENE_H = 560;
const INSET_W = 260;
const INSET_H = 200;
/** The inset's rectangle in canvas pixels (top-left origin). */
const INSET_RECT = { x: SCENE_W - INSET_W - 6, y: SCENE_H - INSET_H - 6, w: INSET_W, h: INSET_H };

function el(tag, attrs = {}, text = '') {
  const e = document.createElement(tag);
  Object.assign(e, attrs);
  if (text) e.textContent = text;
  return e;
}

function headline(data) {
  const s = data.summary || {};
  const parts = [`kind ${data.kind}`];
  if (s.outcome) parts.push(`outcome: ${s.outcome}${s.outcome_reason ? ' (' + s.outcome_reason + ')' : ''}`);
  if (data.kind === 'reach') {
    parts.push(`verdict: ${s.verdict}`);
    parts.push(`first unprovable time: ${s.first_failure_time === null || s.first_failure_time === undefined ? 'none (proved over the horizon ' + s.horizon + ' s)' : s.first_failure_time + ' s'}`);
  }
  if (s.constraints_satisfied !== undefined) parts.push(`constraints satisfied: ${s.constraints_satisfied}`);
  if (s.min_pointing_margin !== undefined) parts.push(`min pointing margin ${(+s.min_pointing_margin).toPrecision(4)}`);
  if (data.kind === 'plan' && s.duration !== undefined) {
    const ratio = s.ratio_to_bang_bang !== null && s.ratio_to_bang_bang !== undefined ? ` = ${(+s.ratio_to_bang_bang).toPrecision(4)}× the eigenaxis bang-bang` : '';
    parts.push(`duration ${(+s.duration).toPrecision(5)} s${ratio}`);
    if (s.smallest_cone_margin_deg !== null && s.smallest_cone_margin_deg !== undefined) parts.push(`smallest cone margin ${(+s.smallest_cone_margin_deg).toPrecision(4)}°`);
    if (s.largest_torque_ratio !== undefined) parts.push(`max ‖τ‖/τ_max ${(+s.largest_torque_ratio).toPrecision(4)}`);
  }
  if (data.kind === 'pet_erg' && s.governor === 'planned' && s.planned && s.planned.plan) {
    const p = s.planned;
    const fig = (v, digits) => (v === null || v === undefined ? '–' : (+v).toPrecision(digits));
    parts.push(`planned: plan T_p ${fig(p.plan.duration, 5)} s = ${fig(p.plan.ratio, 4)}× the eigenaxis bang-bang, converged at ${fig(p.convergence_time_over_plan, 4)}× T_p, clock held ${fig(p.time_held, 4)} s, min ṡ ${fig(p.min_rate, 4)}`);
  }
  if (data.kind === 'campaign') parts.push(`runs ${s.runs_completed} / ${s.runs_requested}, ok ${s.ok}, violations ${s.violations}`);
  return parts.join(' · ');
}

/**
 * The strips of a planned slew (pet_erg, governor "planned", docs/pet-erg.md 16.2) in place of
 * the PET-ERG's V and Γ: the tracking law's V, the plan's clock σ (as σ/T_p) with its rate ṡ,
 * and ‖τ‖ against the governor's torque bound and τ_max (whichever columns exist).
 */
function plannedStrips(parent, s, t, summary, add, strips) {
  add('Lyapunov function V of the tracking law (to the plan R_p(σ)) [J]', ['V']);
  const planned = summary.planned || {};
  const tp = planned.plan && Number.isFinite(planned.plan.duration) && planned.plan.duration > 0 ? planned.plan.duration : null;
  const clock = [];
  if (s.has('s')) {
    if (tp) clock.push({ label: `σ/T_p (T_p = ${tp.toPrecision(4)} s)`, values: s.col('s').map((v) => (v === null ? null : v / tp)) });
    else clock.push({ label: 'σ [s]', values: s.col('s') });
  }
  if (s.has('s_dot')) clock.push({ label: 'ṡ', values: s.col('s_dot') });
  if (clock.length) strips.push(makeStrip(parent, t, 'plan clock σ and its rate ṡ (ṡ < 1: the progress slowed; 0: held) [–]', clock, { zero: true }));
  const torque = [];
  if (s.has('tau_norm')) torque.push({ label: '‖τ‖', values: s.col('tau_norm'), color: '#222222' });
  if (s.has('torque_bound')) torque.push({ label: 'torque_bound', values: s.col('torque_bound'), color: '#9467bd' });
  const tauMax = Number.isFinite(summary.tau_max) ? summary.tau_max : Number.isFinite(planned.tau_max) ? planned.tau_max : null;
  if (torque.length && tauMax !== null) torque.push({ label: 'τ_max', values: t.map(() => tauMax), color: '#d62728', width: 1 });
  if (torque.length) strips.push(makeStrip(parent, t, 'torque ‖τ‖, torque_bound (the governor\'s bound on ‖τ‖ at the last choice of ṡ), τ_max [N m]', torque, { zero: true }));
  return torque.length > 0;
}

/** The strips of a flight trajectory: V vs Γ, margins, torques (whichever columns exist). */
function flightStrips(parent, s, t, summary = {}) {
  const strips = [];
  const add = (title, names, opts) => {
    const lines = names.filter((n) => s.has(n)).map((n) => ({ label: n, values: s.col(n) }));
    if (lines.length) strips.push(makeStrip(parent, t, title, lines, opts));
  };
  const planned = summary.kind === 'pet_erg' && summary.governor === 'planned';
  let torqueShown = false;
  if (planned) torqueShown = plannedStrips(parent, s, t, summary, add, strips);
  else if (s.has('gamma')) add('Lyapunov function V and threshold Γ (PET-ERG paper (5)) [J]', ['V', 'gamma']);
  else add('Lyapunov function V of the control law [J]', ['V']);
  const margins = s.columns.filter((c) => /^margin_\d+$/.test(c) || c === 'min_margin');
  add('pointing margins a_cᵀ R a_b − cos θ_c (≥ 0: satisfied) [–]', margins, { zero: true });
  if (!torqueShown) {  // a planned run's ‖τ‖ is in its strips above, with its bounds
    if (s.has('tau_norm')) add('torque ‖τ‖ [N m]', ['tau_norm']);
    else add('body torque τ_b [N m]', ['tau_x', 'tau_y', 'tau_z']);
  }
  add('main-engine thrust [N]', ['thrust']);
  add('RCT thrusters [N]', ['rct_1', 'rct_2', 'rct_3', 'rct_4', 'rct_5', 'rct_6']);
  return strips;
}

function reachStrips(parent, series) {
  const strips = [];
  const tube = series('tube');
  if (tube) {
    const t = tube.col('t0');
    const k = ['x', 'y', 'z'];
    const lines = [];
    // Sampled trajectories' ω_b (samples.csv, the first 5 samples) under the bounds, thin grey.
    const samples = series('samples');
    if (samples) {
      const id = samples.col('sample');
      const st = samples.col('t');
      for (const s of [...new Set(id)].slice(0, 5)) {
        const rows = [];
        for (let i = 0; i < samples.n; i++) if (id[i] === s) rows.push(i);
        k.forEach((a) => lines.push({
          label: '', color: '#9a9a9a', width: 0.8,
          t: rows.map((i) => st[i]), values: rows.map((i) => samples.col(`omega_${a}`)[i]),
        }));
      }
    }
    const colours = { x: '#d62728', y: '#2ca02c', z: '#1f77b4' };
    k.forEach((a) => {
      lines.push({ label: `ω_${a} bounds`, values: tube.col(`omega_lo_${a}`), color: colours[a] });
      lines.push({ label: '', values: tube.col(`omega_hi_${a}`), color: colours[a] });
    });
    strips.push(makeStrip(parent, t, 'ω tube: bounds of ω_b (tube.csv); grey: 5 sampled ω_b [rad/s]', lines, { height: 190 }));
    const steps = series('steps');
    if (steps) strips.push(makeStrip(parent, steps.col('t'), 'attitude radius of the ball (steps.csv) [rad]', [{ label: 'attitude_radius', values: steps.col('attitude_radius') }], { zero: true }));
  }
  return strips;
}

/** Title, style and the header line of the page. */
function pageHeader(data) {
  document.title = `attiguard view: ${data.name} (${data.kind})`;
  const style = document.createElement('style');
  style.textContent = STYLE;
  document.head.appendChild(style);
  const header = el('header');
  header.append(el('h1', {}, `${data.name}`), el('div', { className: 'sub' }, headline(data)));
  document.body.appendChild(header);
}

/** The 3-D scene of the kind (main view and inset), in a box beside its legend. */
function sceneView(data, series, traj) {
  const wrap = el('div', { id: 'wrap' });
  const sceneBox = el('div', { id: 'scene' });
  const legendBox = el('ul', { id: 'legend' });
  wrap.append(sceneBox, legendBox);
  document.body.appendChild(wrap);
  const renderer = makeRenderer(sceneBox, SCENE_W, SCENE_H);
  renderer.domElement.id = 'scene-canvas';

  const q = quaternions(traj, 'q_w', 'q_x', 'q_y', 'q_z');
  let main = null;
  let inset = null;
  if (data.kind === 'waypoint' || data.kind === 'mission') {
    main = pathScene(renderer, traj, data.summary, q);
    inset = insetScene(renderer, q, data.kind === 'mission' ? data.summary : null);
  } else if (data.kind === 'reach') {
    main = reachScene(renderer, data, series, q);
    inset = insetScene(renderer, q, null, false);
  } else {
    main = attitudeScene(renderer, traj, data.summary);
  }
  const legend = [...main.legend];
  if (inset) legend.push(`inset (lower right): the body attitude R(t) with its axes${data.kind === 'reach' ? '' : '; orange: main-engine axis x_b'}`);
  legend.push(decimationNote(traj));
  for (const n of ['boundary', 'samples', 'tube']) if (series(n)) legend.push(decimationNote(series(n)));
  legend.push('units: SI (s, m, rad, N m); drag to turn, wheel to zoom');
  for (const l of legend) legendBox.appendChild(el('li', { innerHTML: l }));
  return { renderer, main, inset };
}

/** Draws the main view and, in its lower right corner, the inset. */
function renderScenes({ renderer, main, inset }) {
  renderer.setViewport(0, 0, SCENE_W, SCENE_H);
  renderer.setScissorTest(false);
  renderer.clear();
  main.camera.aspect = SCENE_W / SCENE_H;
  main.camera.updateProjectionMatrix();
  renderer.render(main.scene, main.camera);
  if (inset) {
    const w = INSET_W;
    const h = INSET_H;
    renderer.setScissorTest(true);
    renderer.setScissor(SCENE_W - w - 6, 6, w, h);
    renderer.setViewport(SCENE_W - w - 6, 6, w, h);
    renderer.setClearColor(0xe4e9f1, 1);
    renderer.clear();
    renderer.setClearColor(BACKGROUND, 1);
    inset.camera.aspect = w / h;
    inset.camera.updateProjectionMatrix();
    renderer.render(inset.scene, inset.camera);
    renderer.setScissorTest(false);
  }
}

/** Controls: slider over the displayed samples' times, play / pause, speed. */
function timeControls(t) {
  const controls = el('div', { className: 'controls' });
  const play = el('button', { id: 'play' }, 'play');
  const speed = el('select', { id: 'speed' });
  for (const f of [0.25, 1, 4, 16]) speed.add(new Option(`speed ${f}× (the run in ${(20 / f).toFixed(0)} s)`, String(f)));
  speed.value = '1';
  const slider = el('input', { id: 'time-slider', type: 'range', min: String(t[0]), max: String(t[t.length - 1]), step: 'any', value: String(t[0]) });
  const timeLabel = el('span', { id: 'time-label' });
  controls.append(play, speed, slider, timeLabel);
  document.body.appendChild(controls);
  return { play, speed, slider, timeLabel };
}

/** The time cursor over samples t: setTime moves scenes, strips and controls; play/pause animates it. */
function player(t, view, strips, ui) {
  const { main, inset } = view;
  const duration = t[t.length - 1] - t[0];
  const state = { index: 0, time: t[0] };
  function setTime(value) {
    state.index = indexAt(t, value);
    state.time = t[state.index];
    main.update(state.index, state.time);
    if (inset) inset.update(state.index, state.time);
    ui.slider.value = String(state.time);
    ui.timeLabel.textContent = `t = ${state.time.toFixed(3)} s of ${t[t.length - 1]} s (sample ${state.index + 1}/${t.length})`;
    for (const s of strips) s.draw(state.time);
    renderScenes(view);
  }
  ui.slider.addEventListener('input', () => setTime(parseFloat(ui.slider.value)));
  main.controls.addEventListener('change', () => renderScenes(view));
  if (inset) inset.controls.enabled = false;

  let playing = false;
  let last = 0;
  function frame(ts) {
    if (!playing) return;
    const dt = last ? (ts - last) / 1000 : 0;
    last = ts;
    let next = state.time + dt * parseFloat(ui.speed.value) * duration * 0.05;
    if (next >= t[t.length - 1]) {
      next = t[t.length - 1];
      playing = false;
      ui.play.textContent = 'play';
    }
    setTime(next);
    if (playing) requestAnimationFrame(frame);
  }
  ui.play.addEventListener('click', () => {
    playing = !playing;
    ui.play.textContent = playing ? 'pause' : 'play';
    last = 0;
    if (playing) {
      if (state.time >= t[t.length - 1]) setTime(t[0]);
      requestAnimationFrame(frame);
    }
  });
  return { setTime, state };
}

function main() {
  const data = loadData();
  const series = (name) => seriesOf(data, name);
  pageHeader(data);
  const api = { ready: false, kind: data.kind, name: data.name, errors: [] };
  window.attiguardView = api;

  if (data.kind === 'campaign') {
    const view = campaignView(document.body, data, series);
    api.canvas = view.canvas;
    api.canvasStats = () => canvasStats(view.canvas, [255, 255, 255]);
    api.ready = true;
    return;
  }

  const traj = series('trajectory');
  const view = sceneView(data, series, traj);
  const t = traj.col('t');
  const ui = timeControls(t);
  const stripsBox = el('div', { id: 'strips' });
  document.body.appendChild(stripsBox);
  const strips = data.kind === 'reach' ? reachStrips(stripsBox, series) : flightStrips(stripsBox, traj, t, data.summary || {});
  const { setTime, state } = player(t, view, strips, ui);

  setTime(t[0]);
  Object.assign(api, {
    setTime,
    canvas: view.renderer.domElement,
    state: () => {
      const b = (view.main.bodyObject || view.inset.bodyObject).quaternion;
      return { t: state.time, index: state.index, body_q: [b.w, b.x, b.y, b.z], rows_shown: t.length };
    },
    canvasStats: () => canvasStats(view.renderer.domElement, [0xf4, 0xf6, 0xfa], view.inset ? INSET_RECT : null),
    ready: true,
  });
}

/** Fraction of pixels of a canvas (outside `exclude`, the inset) that differ from the background, and the colours seen. */
function canvasStats(canvas, bg, exclude = null) {
  const c = document.createElement('canvas');
  c.width = canvas.width;
  c.height = canvas.height;
  const ctx = c.getContext('2d');
  ctx.drawImage(canvas, 0, 0);
  const px = ctx.getImageData(0, 0, c.width, c.height).data;
  let differ = 0;
  const colours = new Set();
  let counted = 0;
  for (let i = 0; i < px.length; i += 4) {
    const x = (i / 4) % c.width;
    const y = Math.floor(i / 4 / c.width);
    if (exclude && x >= exclude.x && x < exclude.x + exclude.w && y >= exclude.y && y < exclude.y + exclude.h) continue;
    counted++;
    const d = Math.abs(px[i] - bg[0]) + Math.abs(px[i + 1] - bg[1]) + Math.abs(px[i + 2] - bg[2]);
    if (d > 30) differ++;
    if (colours.size < 5000) colours.add((px[i] << 16) | (px[i + 1] << 8) | px[i + 2]);
  }
  return { nonBackground: differ / counted, colours: colours.size };
}

try {
  main();
} catch (e) {
  console.error('attiguard viewer: ' + (e && e.stack ? e.stack : e));
  const api = window.attiguardView || {};
  api.failed = String(e);
  window.attiguardView = api;
}
export { THREE };

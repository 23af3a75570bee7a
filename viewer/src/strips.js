// Time strips under the scene (docs/viewer.md): 2-D canvas line plots of named series against t
// with a cursor at the current time.

const COLORS = ['#1f77b4', '#d62728', '#2ca02c', '#ff7f0e', '#9467bd', '#8c564b', '#e377c2', '#17becf'];

/**
 * A strip: `lines` = [{label, values, t?, color?}] over `t` (or the line's own `t`); a line with
 * an empty label is left out of the legend; `title` names the quantity and its unit.
 * Returns {draw(time)}.
 */
export function makeStrip(parent, t, title, lines, options = {}) {
  const box = document.createElement('div');
  box.className = 'strip';
  box.dataset.title = title;  // what the strip shows, for the browser test
  const canvas = document.createElement('canvas');
  canvas.width = 900;
  canvas.height = options.height || 130;
  box.appendChild(canvas);
  parent.appendChild(box);
  const ctx = canvas.getContext('2d');
  let ymin = Infinity;
  let ymax = -Infinity;
  for (const l of lines) {
    for (const v of l.values) {
      if (v === null || !Number.isFinite(v)) continue;
      ymin = Math.min(ymin, v);
      ymax = Math.max(ymax, v);
    }
  }
  if (options.zero) {
    ymin = Math.min(ymin, 0);
    ymax = Math.max(ymax, 0);
  }
  if (!(ymax > ymin)) {
    ymax = (Number.isFinite(ymax) ? ymax : 0) + 1;
    ymin = ymax - 2;
  }
  const pad = (ymax - ymin) * 0.06;
  ymin -= pad;
  ymax += pad;
  const L = 70;
  const R = 10;
  const T = 18;
  const B = 20;
  const W = canvas.width - L - R;
  const H = canvas.height - T - B;
  const t0 = t[0];
  const t1 = t[t.length - 1] > t0 ? t[t.length - 1] : t0 + 1;
  const X = (v) => L + ((v - t0) / (t1 - t0)) * W;
  const Y = (v) => T + (1 - (v - ymin) / (ymax - ymin)) * H;
  const fmt = (v) => (Math.abs(v) >= 1e4 || (Math.abs(v) < 1e-2 && v !== 0) ? v.toExponential(1) : v.toPrecision(3));

  function draw(time) {
    ctx.fillStyle = '#ffffff';
    ctx.fillRect(0, 0, canvas.width, canvas.height);
    ctx.strokeStyle = '#cccccc';
    ctx.strokeRect(L, T, W, H);
    ctx.fillStyle = '#333333';
    ctx.font = '12px sans-serif';
    ctx.fillText(title, L, 13);
    ctx.fillText(fmt(ymax), 4, T + 10);
    ctx.fillText(fmt(ymin), 4, T + H);
    ctx.fillText(`${fmt(t0)}`, L, canvas.height - 5);
    ctx.fillText(`t [s] ${fmt(t1)}`, L + W - 70, canvas.height - 5);
    if (ymin < 0 && ymax > 0) {
      ctx.strokeStyle = '#999999';
      ctx.setLineDash([3, 3]);
      ctx.beginPath();
      ctx.moveTo(L, Y(0));
      ctx.lineTo(L + W, Y(0));
      ctx.stroke();
      ctx.setLineDash([]);
    }
    lines.forEach((l, k) => {
      ctx.strokeStyle = l.color || COLORS[k % COLORS.length];
      ctx.beginPath();
      let pen = false;
      const tt = l.t || t;
      ctx.lineWidth = l.width || 1.5;
      for (let i = 0; i < tt.length; i++) {
        const v = l.values[i];
        if (v === null || !Number.isFinite(v)) {
          pen = false;
          continue;
        }
        if (pen) ctx.lineTo(X(tt[i]), Y(v));
        else ctx.moveTo(X(tt[i]), Y(v));
        pen = true;
      }
      ctx.stroke();
    });
    let x = L + W;
    for (let k = lines.length - 1; k >= 0; k--) {
      if (!lines[k].label) continue;
      x -= ctx.measureText(lines[k].label).width + 14;
      ctx.fillStyle = lines[k].color || COLORS[k % COLORS.length];
      ctx.fillText(lines[k].label, x, 13);
    }
    ctx.strokeStyle = '#000000';
    ctx.lineWidth = 1;
    ctx.beginPath();
    ctx.moveTo(X(time), T);
    ctx.lineTo(X(time), T + H);
    ctx.stroke();
  }
  return { draw, canvas };
}

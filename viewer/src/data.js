// The page's data (docs/viewer.md): the JSON that `attiguard view` writes into view.html.

/** The parsed <script id="attiguard-data"> element. */
export function loadData() {
  const el = document.getElementById('attiguard-data');
  return JSON.parse(el.textContent);
}

/** A series (one CSV file) of the page, with column access; null when absent. */
export function series(data, name) {
  const s = data.series ? data.series[name] : undefined;
  if (!s) return null;
  return {
    ...s,
    has: (c) => Object.prototype.hasOwnProperty.call(s.data, c),
    col: (c) => s.data[c] || null,
    n: s.rows_shown,
  };
}

/** A one-line note on decimation ("every 4th of 6001 rows"), or '' when every row is shown. */
export function decimationNote(s) {
  if (!s) return '';
  if (s.stride <= 1 && s.rows_selected === s.rows_total) return `${s.file}: all ${s.rows_total} rows`;
  const sel = s.rows_selected !== s.rows_total ? ` (${s.rows_selected} selected)` : '';
  return `${s.file}: ${s.rows_shown} of ${s.rows_total} rows${sel} shown, every k-th row with k = ${s.stride} (decimated for display, never truncated: the last row is kept)`;
}

/** Index of the last sample with t[i] <= time (binary search; 0 before the first). */
export function indexAt(t, time) {
  let lo = 0;
  let hi = t.length - 1;
  if (time <= t[0]) return 0;
  if (time >= t[hi]) return hi;
  while (hi - lo > 1) {
    const mid = (lo + hi) >> 1;
    if (t[mid] <= time) lo = mid;
    else hi = mid;
  }
  return time - t[lo] < t[hi] - time ? lo : hi;
}

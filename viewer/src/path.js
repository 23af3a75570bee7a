// The path scene of kinds waypoint and mission (docs/viewer.md): the 3-D path coloured by
// guidance mode, the waypoints, the spacecraft with its thrust direction (main engine along
// +x_b, the nominal axis) at the current time.
import { THREE, axes, frame, label, makeView, vectorArrow } from './scene.js';

const MODE_COLORS = [0x1f77b4, 0xd62728, 0x2ca02c, 0xff7f0e, 0x9467bd, 0x8c564b, 0x7f7f7f, 0xe377c2];

export function pathScene(renderer, s, summary, q) {
  const px = s.col('p_x');
  const py = s.col('p_y');
  const pz = s.col('p_z');
  let extent = 1;
  for (let i = 0; i < s.n; i++) extent = Math.max(extent, Math.abs(px[i]), Math.abs(py[i]), Math.abs(pz[i]));
  const scale = 4 / extent; // scene units per metre
  const P = (i) => new THREE.Vector3(px[i] * scale, py[i] * scale, pz[i] * scale);
  const view = makeView(renderer, 12);
  const { scene } = view;
  const legend = [];
  scene.add(axes(1.2, 'i', 0.6));
  legend.push(`positions in the inertial frame i, scale: 1 unit = ${(1 / scale).toPrecision(3)} m`);

  const mode = s.col('mode');
  const names = summary.mode_names || ['align', 'accelerate', 'coast', 'flip', 'decelerate', 'fine', 'done', 'brake'];
  const pos = [];
  const col = [];
  const c = new THREE.Color();
  for (let i = 0; i < s.n; i++) {
    const p = P(i);
    pos.push(p.x, p.y, p.z);
    c.setHex(MODE_COLORS[(mode ? mode[i] : 0) % MODE_COLORS.length]);
    col.push(c.r, c.g, c.b);
  }
  const geom = new THREE.BufferGeometry();
  geom.setAttribute('position', new THREE.Float32BufferAttribute(pos, 3));
  geom.setAttribute('color', new THREE.Float32BufferAttribute(col, 3));
  scene.add(new THREE.Line(geom, new THREE.LineBasicMaterial({ vertexColors: true })));
  const used = new Set(mode || [0]);
  legend.push('path colour = guidance mode: ' + names.map((n, k) => (used.has(k) ? `<span style="color:#${MODE_COLORS[k % MODE_COLORS.length].toString(16).padStart(6, '0')}">■ ${n}</span>` : '')).filter(Boolean).join(' '));

  // Waypoints: the legs' positions, else the position at each waypoint's arrival time.
  const t = s.col('t');
  const wps = [];
  if (summary.legs && summary.legs.every((l) => Array.isArray(l.position))) {
    summary.legs.forEach((l) => wps.push(new THREE.Vector3(...l.position).multiplyScalar(scale)));
    legend.push('spheres: waypoints (scenario positions)');
  } else if (summary.waypoints) {
    summary.waypoints.forEach((w) => {
      let k = 0;
      while (k < s.n - 1 && t[k] < w.arrival_time) k++;
      wps.push(P(k));
    });
    legend.push('spheres: waypoints (the position at each arrival time)');
  }
  const start = new THREE.Mesh(new THREE.SphereGeometry(0.08, 16, 10), new THREE.MeshStandardMaterial({ color: 0x333333 }));
  start.position.copy(P(0));
  scene.add(start);
  wps.forEach((w, k) => {
    const m = new THREE.Mesh(new THREE.SphereGeometry(0.16, 20, 12), new THREE.MeshStandardMaterial({ color: 0x2ca02c }));
    m.position.copy(w);
    scene.add(m);
    const l = label(`waypoint ${k}`, '#1b6e1b', 0.25);
    l.position.copy(w).add(new THREE.Vector3(0, 0, 0.35));
    scene.add(l);
  });

  // A faint grid in the x-y plane of the path (10 × 10 cells) for depth.
  const grid = new THREE.GridHelper(8, 16, 0xb8c0cc, 0xd6dbe3);
  grid.rotation.x = Math.PI / 2;
  grid.position.z = Math.min(...pz) * scale;
  scene.add(grid);
  legend.push(`grid: 1 cell = ${(0.5 / scale).toPrecision(3)} m, in the plane z_i = ${Math.min(...pz).toPrecision(3)} m`);
  const pathPoints = [];
  for (let i = 0; i < s.n; i += Math.max(1, Math.floor(s.n / 200))) pathPoints.push(P(i));
  wps.forEach((w) => pathPoints.push(w));
  frame(view, pathPoints, 1.0);

  const craft = new THREE.Group();
  craft.add(new THREE.Mesh(new THREE.BoxGeometry(0.36, 0.24, 0.18), new THREE.MeshStandardMaterial({ color: 0x555e6e })));
  craft.add(axes(0.6, 'b'));
  scene.add(craft);
  const thrust = vectorArrow(0xff7f0e, 0.15);
  scene.add(thrust.object);
  const th = s.col('thrust');
  let thMax = 0;
  if (th) for (let i = 0; i < s.n; i++) thMax = Math.max(thMax, th[i]);
  legend.push('orange arrow: main-engine thrust direction R x_b (length ∝ thrust), drawn from the spacecraft');

  function update(i) {
    craft.position.copy(P(i));
    craft.quaternion.copy(q[i]);
    thrust.object.position.copy(P(i));
    const f = th ? th[i] : 0;
    thrust.set(new THREE.Vector3(1, 0, 0).applyQuaternion(q[i]), thMax > 0 && f > 0 ? (0.9 * f) / thMax : 0);
  }
  return { ...view, update, bodyObject: craft, legend };
}

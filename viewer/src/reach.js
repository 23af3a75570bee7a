// The reach scene (docs/viewer.md): in the exponential chart r = log(R) [rad] (chart of
// reach.json), the boundaries of the metric balls (boundary.csv, one point cloud per step,
// coloured by time, the current step highlighted), the nominal trajectory and the sampled
// trajectories (samples.csv).
import { THREE, axes, frame, makeView, polyline } from './scene.js';

const SCALE = 8; // scene units per radian

/** Rotation vector log(q) of a THREE.Quaternion (|angle| ≤ π). */
export function logQuaternion(q) {
  let { x, y, z, w } = q;
  if (w < 0) {
    x = -x; y = -y; z = -z; w = -w;
  }
  const s = Math.hypot(x, y, z);
  if (s < 1e-12) return new THREE.Vector3(2 * x, 2 * y, 2 * z);
  const angle = 2 * Math.atan2(s, w);
  return new THREE.Vector3(x, y, z).multiplyScalar(angle / s);
}

export function reachScene(renderer, data, series, q) {
  const view = makeView(renderer, 8);
  const { scene } = view;
  const legend = [];
  scene.add(axes(1.5, 'r', 0.6));
  legend.push(`exponential chart: r = log(R) (rotation vector, 1 unit = ${(1 / SCALE).toFixed(3)} rad)`);
  const b = series('boundary');
  const steps = [];
  if (b) {
    const t = b.col('t');
    const rx = b.col('r_x');
    const ry = b.col('r_y');
    const rz = b.col('r_z');
    const tmax = Math.max(...t);
    const byT = new Map();
    for (let i = 0; i < b.n; i++) {
      if (!byT.has(t[i])) byT.set(t[i], []);
      byT.get(t[i]).push(new THREE.Vector3(rx[i], ry[i], rz[i]).multiplyScalar(SCALE));
    }
    const c = new THREE.Color();
    for (const [time, pts] of byT) {
      const geom = new THREE.BufferGeometry().setFromPoints(pts);
      c.setHSL(0.66 - 0.66 * (tmax > 0 ? time / tmax : 0), 0.8, 0.5);
      const mat = new THREE.PointsMaterial({ color: c.clone(), size: 0.05, transparent: true, opacity: 0.5 });
      const cloud = new THREE.Points(geom, mat);
      scene.add(cloud);
      steps.push({ time, cloud });
    }
    legend.push(`ball boundaries (boundary.csv, ${byT.size} steps; colour blue → red with t; the current step opaque and larger)`);
  }
  const samples = series('samples');
  if (samples) {
    const id = samples.col('sample');
    const rx = samples.col('r_x');
    const ry = samples.col('r_y');
    const rz = samples.col('r_z');
    const lines = new Map();
    for (let i = 0; i < samples.n; i++) {
      if (!lines.has(id[i])) lines.set(id[i], []);
      lines.get(id[i]).push(new THREE.Vector3(rx[i], ry[i], rz[i]).multiplyScalar(SCALE));
    }
    for (const pts of lines.values()) scene.add(polyline(pts, 0x7f7f7f, { opacity: 0.6 }));
    legend.push(`grey: ${lines.size} sampled trajectories (of ${data.summary.soundness ? data.summary.soundness.samples : '?'} checked)`);
  }
  if (q) {
    scene.add(polyline(q.map((x) => logQuaternion(x).multiplyScalar(SCALE)), 0x000000));
    legend.push('black: nominal trajectory log(R(t)); black dot: now');
  }
  if (q) frame(view, q.map((x) => logQuaternion(x).multiplyScalar(SCALE)), 1.3);
  const now = new THREE.Mesh(new THREE.SphereGeometry(0.06, 12, 8), new THREE.MeshBasicMaterial({ color: 0x000000 }));
  scene.add(now);

  function update(i, time) {
    if (q) now.position.copy(logQuaternion(q[i]).multiplyScalar(SCALE));
    let best = null;
    for (const s of steps) if (s.time <= time + 1e-12 && (!best || s.time > best.time)) best = s;
    for (const s of steps) {
      s.cloud.material.opacity = s === best ? 1.0 : 0.3;
      s.cloud.material.size = s === best ? 0.11 : 0.045;
    }
  }
  return { ...view, update, legend };
}

// The attitude scene (kinds pet_erg, rigid_body, mission; the nominal of reach): the body with
// its axes and constrained body axes, the celestial sphere with every cone, the boresight
// traces of R, R_g and R_d and the torque vector (docs/viewer.md).
import { THREE, AXIS_COLORS, axes, body, celestialSphere, cones, distinctAxes, makeView, trace, vectorArrow, vec, polyline, label } from './scene.js';

const SPHERE = 2.0;

/** Quaternions (THREE, x y z w order) of columns PREFIX_w … PREFIX_z, or null. */
export function quaternions(s, w, x, y, z) {
  if (!s || !s.has(w)) return null;
  const cw = s.col(w);
  const cx = s.col(x);
  const cy = s.col(y);
  const cz = s.col(z);
  const out = [];
  for (let i = 0; i < s.n; i++) out.push(new THREE.Quaternion(cx[i], cy[i], cz[i], cw[i]).normalize());
  return out;
}

/**
 * Builds the scene for trajectory series `s` with the summary's cones. Returns
 * {scene, camera, controls, update(i), bodyObject, legend}.
 */
export function attitudeScene(renderer, s, summary) {
  const view = makeView(renderer, 5.6);
  const { scene } = view;
  const legend = [];
  scene.add(axes(SPHERE * 1.2, 'i', 0.55));
  legend.push('inertial axes x_i, y_i, z_i (faint); body axes x_b, y_b, z_b on the body; R = R_ib maps b to i');
  scene.add(celestialSphere(SPHERE));
  const coneList = summary.cones || [];
  scene.add(cones(coneList, SPHERE));
  if (coneList.length) legend.push('cones on the unit sphere (drawn at radius 2): shaded = forbidden directions of a_b, circle = boundary; each cone, its body axis a_b (arrow on the body) in one colour');

  const q = quaternions(s, 'q_w', 'q_x', 'q_y', 'q_z');
  const qg = quaternions(s, 'qg_w', 'qg_x', 'qg_y', 'qg_z');
  const qd = quaternions(s, 'qd_w', 'qd_x', 'qd_y', 'qd_z');
  const bodyObject = body(0.5);
  scene.add(bodyObject);
  const boresights = [];
  const axesB = coneList.length ? distinctAxes(coneList) : [[1, 0, 0]];
  axesB.forEach((a, k) => {
    const color = coneList.length ? AXIS_COLORS[k % AXIS_COLORS.length] : 0xe6a000;
    const arrow = new THREE.ArrowHelper(vec(a), new THREE.Vector3(), SPHERE, color, 0.15, 0.08);
    bodyObject.add(arrow);
    const l = label(`a_b = [${a.map((v) => +v.toFixed(2)).join(', ')}]`, `#${color.toString(16).padStart(6, '0')}`, 0.14);
    l.position.copy(vec(a).multiplyScalar(SPHERE * 1.05));
    bodyObject.add(l);
    scene.add(trace(q, a, SPHERE, 0x222222));
    if (qg) scene.add(trace(qg, a, SPHERE, 0x17becf, { dashed: true }));
    if (qd) {
      const dot = new THREE.Mesh(new THREE.SphereGeometry(0.05, 12, 8), new THREE.MeshBasicMaterial({ color: 0x9467bd }));
      dot.position.copy(vec(a).applyQuaternion(qd[qd.length - 1]).multiplyScalar(SPHERE));
      scene.add(dot);
      scene.add(trace(qd, a, SPHERE, 0x9467bd, { opacity: 0.8 }));
    }
    const marker = new THREE.Mesh(new THREE.SphereGeometry(0.045, 12, 8), new THREE.MeshBasicMaterial({ color: 0x000000 }));
    scene.add(marker);
    boresights.push({ a: vec(a), marker });
  });
  // A planned slew (governor "planned", docs/pet-erg.md 16.2) writes the plan's attitude R_p(σ)
  // at the governed clock σ in qg_*, where the PET-ERG writes its governor's reference R_g.
  const planned = summary.governor === 'planned';
  const reference = planned ? 'R_p(σ) a_b (plan at the governed clock; cyan, dashed)' : 'R_g a_b (cyan, dashed: governor reference)';
  legend.push(['trace of R a_b (black; dot: now)', qg ? reference : '',
    qd ? 'R_d a_b (violet: desired; dot = final)' : ''].filter(Boolean).join(', ')
    + (coneList.length ? '' : '; a_b = x_b (no cone in this scenario)'));

  const torque = vectorArrow(0xff7f0e, 0.15);
  scene.add(torque.object);
  const tx = s.col('tau_x');
  let tauMax = 0;
  if (tx) {
    const ty = s.col('tau_y');
    const tz = s.col('tau_z');
    for (let i = 0; i < s.n; i++) tauMax = Math.max(tauMax, Math.hypot(tx[i], ty[i], tz[i]));
    legend.push(`torque τ (orange, inertial direction R τ_b, length ∝ ‖τ‖, max ${tauMax.toPrecision(3)} N m)`);
  }

  function update(i) {
    bodyObject.quaternion.copy(q[i]);
    for (const b of boresights) b.marker.position.copy(b.a.clone().applyQuaternion(q[i]).multiplyScalar(SPHERE * 1.003));
    if (tx) {
      const tb = new THREE.Vector3(tx[i], s.col('tau_y')[i], s.col('tau_z')[i]);
      const n = tb.length();
      torque.set(tb.applyQuaternion(q[i]), tauMax > 0 ? (1.6 * n) / tauMax : 0);
    }
  }
  return { ...view, update, bodyObject, legend, quaternions: q };
}

/** A small attitude-only scene (inset of waypoint / reach): the body and the inertial axes. */
export function insetScene(renderer, q, summary, withThrust = true) {
  const view = makeView(renderer, 4.2);
  view.scene.add(axes(1.6, 'i', 0.5));
  if (summary && summary.cones) {
    view.scene.add(celestialSphere(SPHERE));
    view.scene.add(cones(summary.cones, SPHERE));
  }
  const b = body(0.5);
  view.scene.add(b);
  const thrust = new THREE.ArrowHelper(new THREE.Vector3(1, 0, 0), new THREE.Vector3(), 1.4, 0xff7f0e, 0.2, 0.1);
  if (withThrust) b.add(thrust);
  return { ...view, update: (i) => b.quaternion.copy(q[i]), bodyObject: b, thrust };
}

export { polyline };

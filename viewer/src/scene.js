// three.js building blocks of the viewer (docs/viewer.md): renderer, labelled axes, the body,
// the celestial sphere with its cones, traces on the sphere and arrows. Frames: the scene's
// world frame is the inertial frame i; a body object's quaternion is q_ib (R_ib maps body to
// inertial, docs/conventions.md), three.js's Object3D convention exactly.
import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';

export const BACKGROUND = 0xf4f6fa;

/** Renderer (the drawing buffer is kept so that the test and screenshots can read it). */
export function makeRenderer(container, width, height) {
  const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(1);
  renderer.setSize(width, height);
  renderer.setClearColor(BACKGROUND, 1);
  renderer.autoClear = false;
  container.appendChild(renderer.domElement);
  return renderer;
}

/** A scene with soft lights, and a camera with orbit controls looking at the origin. */
export function makeView(renderer, distance, up = [0, 0, 1]) {
  const scene = new THREE.Scene();
  scene.add(new THREE.AmbientLight(0xffffff, 1.6));
  const sun = new THREE.DirectionalLight(0xffffff, 1.8);
  sun.position.set(3, -2, 4);
  scene.add(sun);
  const camera = new THREE.PerspectiveCamera(40, 1, distance / 100, distance * 100);
  camera.up.set(...up);
  camera.position.set(distance * 0.8, -distance * 1.0, distance * 0.6);
  camera.lookAt(0, 0, 0);
  const controls = new OrbitControls(camera, renderer.domElement);
  return { scene, camera, controls };
}

/** Points the view's camera at the box of `points` (Vector3[]) from a fixed direction. */
export function frame(view, points, margin = 1.6) {
  const box = new THREE.Box3().setFromPoints(points);
  const center = box.getCenter(new THREE.Vector3());
  const radius = Math.max(box.getSize(new THREE.Vector3()).length() / 2, 0.5);
  const dir = new THREE.Vector3(0.8, -1.0, 0.6).normalize();
  const dist = (radius * margin) / Math.sin((view.camera.fov * Math.PI) / 360);
  view.camera.position.copy(center.clone().add(dir.multiplyScalar(dist)));
  view.camera.near = dist / 100;
  view.camera.far = dist * 100;
  view.controls.target.copy(center);
  view.camera.lookAt(center);
  view.controls.update();
}

/** A text label as a sprite (canvas texture, no network). */
export function label(text, color = '#222222', size = 0.18) {
  const c = document.createElement('canvas');
  const ctx = c.getContext('2d');
  ctx.font = '36px sans-serif';
  const w = Math.ceil(ctx.measureText(text).width) + 8;
  c.width = w;
  c.height = 44;
  ctx.font = '36px sans-serif';
  ctx.fillStyle = color;
  ctx.fillText(text, 4, 34);
  const tex = new THREE.CanvasTexture(c);
  tex.colorSpace = THREE.SRGBColorSpace;
  const sprite = new THREE.Sprite(new THREE.SpriteMaterial({ map: tex, depthTest: false, transparent: true }));
  sprite.scale.set((size * w) / 44, size, 1);
  sprite.renderOrder = 10;
  return sprite;
}

/** Three arrows x, y, z (red, green, blue) of `length`, labelled NAME_x … (e.g. "x_i"). */
export function axes(length, suffix, opacity = 1) {
  const g = new THREE.Group();
  const dirs = [new THREE.Vector3(1, 0, 0), new THREE.Vector3(0, 1, 0), new THREE.Vector3(0, 0, 1)];
  const colors = [0xd62728, 0x2ca02c, 0x1f77b4];
  ['x', 'y', 'z'].forEach((n, k) => {
    const a = new THREE.ArrowHelper(dirs[k], new THREE.Vector3(), length, colors[k], length * 0.12, length * 0.06);
    if (opacity < 1) {
      a.line.material.transparent = true;
      a.line.material.opacity = opacity;
      a.cone.material.transparent = true;
      a.cone.material.opacity = opacity;
    }
    g.add(a);
    const l = label(`${n}_${suffix}`, ['#d62728', '#2ca02c', '#1f77b4'][k], length * 0.14);
    l.position.copy(dirs[k]).multiplyScalar(length * 1.1);
    g.add(l);
  });
  return g;
}

/** The spacecraft body: a box with its axes (body frame b). */
export function body(size = 0.5) {
  const g = new THREE.Group();
  const box = new THREE.Mesh(
    new THREE.BoxGeometry(size * 1.2, size * 0.8, size * 0.6),
    new THREE.MeshStandardMaterial({ color: 0xb0b7c3, metalness: 0.3, roughness: 0.6 }),
  );
  g.add(box);
  const panel = new THREE.Mesh(
    new THREE.BoxGeometry(size * 0.05, size * 2.4, size * 0.5),
    new THREE.MeshStandardMaterial({ color: 0x2a4d8f, metalness: 0.2, roughness: 0.5 }),
  );
  g.add(panel);
  g.add(axes(size * 2.0, 'b'));
  return g;
}

/** Unit vector of an array. */
export function vec(a) {
  return new THREE.Vector3(a[0], a[1], a[2]).normalize();
}

/** A unit vector orthogonal to u. */
function orthogonal(u) {
  const a = Math.abs(u.x) < 0.9 ? new THREE.Vector3(1, 0, 0) : new THREE.Vector3(0, 1, 0);
  return a.sub(u.clone().multiplyScalar(a.dot(u))).normalize();
}

/** Points of the circle at angle `theta` [rad] from the unit vector `u` on the sphere of radius r. */
export function circle(u, theta, r, n = 128) {
  const e1 = orthogonal(u);
  const e2 = new THREE.Vector3().crossVectors(u, e1);
  const pts = [];
  for (let k = 0; k <= n; k++) {
    const phi = (2 * Math.PI * k) / n;
    const p = u.clone().multiplyScalar(Math.cos(theta))
      .add(e1.clone().multiplyScalar(Math.sin(theta) * Math.cos(phi)))
      .add(e2.clone().multiplyScalar(Math.sin(theta) * Math.sin(phi)));
    pts.push(p.multiplyScalar(r));
  }
  return pts;
}

/** A polyline through points (Vector3[]). */
export function polyline(points, color, opts = {}) {
  const geom = new THREE.BufferGeometry().setFromPoints(points);
  const mat = opts.dashed
    ? new THREE.LineDashedMaterial({ color, dashSize: opts.dash || 0.06, gapSize: opts.dash || 0.04, transparent: true, opacity: opts.opacity ?? 1 })
    : new THREE.LineBasicMaterial({ color, transparent: (opts.opacity ?? 1) < 1, opacity: opts.opacity ?? 1 });
  const line = new THREE.Line(geom, mat);
  if (opts.dashed) line.computeLineDistances();
  return line;
}

/**
 * A spherical cap of half-angle `theta` [rad] around unit vector `u` on the sphere of radius r:
 * translucent, drawn without depth writes so that what lies behind stays visible.
 */
export function cap(u, theta, r, color, opacity) {
  const geom = new THREE.SphereGeometry(r * 0.995, 64, 24, 0, 2 * Math.PI, 0, theta);
  const mesh = new THREE.Mesh(
    geom,
    new THREE.MeshBasicMaterial({ color, transparent: true, opacity, side: THREE.DoubleSide, depthWrite: false }),
  );
  // SphereGeometry's cap is around +y: turn +y onto u.
  mesh.quaternion.setFromUnitVectors(new THREE.Vector3(0, 1, 0), u);
  return mesh;
}

/** The celestial sphere of radius r: a faint shell with meridians and parallels. */
export function celestialSphere(r) {
  const g = new THREE.Group();
  g.add(new THREE.Mesh(
    new THREE.SphereGeometry(r, 48, 24),
    new THREE.MeshBasicMaterial({ color: 0xffffff, transparent: true, opacity: 0.25, depthWrite: false }),
  ));
  const z = new THREE.Vector3(0, 0, 1);
  for (let k = 1; k < 6; k++) g.add(polyline(circle(z, (k * Math.PI) / 6, r), 0x9aa5b8, { opacity: 0.5 }));
  for (let k = 0; k < 6; k++) {
    const phi = (k * Math.PI) / 6;
    const n = new THREE.Vector3(Math.cos(phi), Math.sin(phi), 0);
    g.add(polyline(circle(new THREE.Vector3().crossVectors(z, n).normalize(), Math.PI / 2, r), 0x9aa5b8, { opacity: 0.5 }));
  }
  return g;
}

/**
 * Every cone of a summary's "cones" (PET-ERG paper, constraint (2b): a_cᵀ R a_b ≥ cos θ_c, with
 * keep-out cones stored as the keep-in cone of π − α around −a): the boundary circle, the
 * forbidden region shaded red, a narrow keep-in region's allowed cap shaded faint green (under
 * the forbidden shading, never hiding it), and a label.
 */
/** Colours of the constrained body axes (cone k is drawn in the colour of its a_b). */
export const AXIS_COLORS = [0xd62728, 0x9467bd, 0x8c564b, 0xe377c2];

/** The distinct body axes a_b of a cone list, in order of first appearance. */
export function distinctAxes(list) {
  const out = [];
  for (const c of list || []) {
    if (!out.some((a) => a.every((v, i) => Math.abs(v - c.axis_b[i]) < 1e-12))) out.push(c.axis_b);
  }
  return out;
}

export function cones(list, r) {
  const g = new THREE.Group();
  const axesB = distinctAxes(list);
  (list || []).forEach((c, k) => {
    const d = vec(c.direction_i);
    const theta = (c.theta_c_deg * Math.PI) / 180;
    const j = axesB.findIndex((a) => a.every((v, i) => Math.abs(v - c.axis_b[i]) < 1e-12));
    const color = AXIS_COLORS[j % AXIS_COLORS.length];
    g.add(polyline(circle(d, theta, r * 1.001), color));
    // Forbidden set: angle from d larger than θ_c, the cap of π − θ_c around −d.
    const forbidden = cap(d.clone().negate(), Math.PI - theta, r, color, 0.35);
    forbidden.renderOrder = 2;
    g.add(forbidden);
    if (theta < Math.PI / 2) {
      const allowed = cap(d, theta, r * 0.99, 0x2ca02c, 0.08);
      allowed.renderOrder = 1;
      g.add(allowed);
    }
    const where = theta > Math.PI / 2 ? d.clone().negate() : d.clone();
    const css = `#${color.toString(16).padStart(6, '0')}`;
    const l = label(`cone ${k}: a_b = [${c.axis_b.map((v) => +v.toFixed(3)).join(', ')}]`, css, r * 0.07);
    l.position.copy(where.multiplyScalar(r * 1.12));
    g.add(l);
  });
  return g;
}

/** A line on the sphere through R(t) a_b for the quaternions of rows `qs` (THREE.Quaternion[]). */
export function trace(qs, axisB, r, color, opts = {}) {
  const a = vec(axisB);
  const pts = qs.map((q) => a.clone().applyQuaternion(q).multiplyScalar(r * 1.003));
  return polyline(pts, color, opts);
}

/** An arrow from the origin that set(v) points along v (hidden when v is zero). */
export function vectorArrow(color, headScale = 0.12) {
  const a = new THREE.ArrowHelper(new THREE.Vector3(1, 0, 0), new THREE.Vector3(), 1, color);
  return {
    object: a,
    set(v, length) {
      if (!(length > 1e-9)) {
        a.visible = false;
        return;
      }
      a.visible = true;
      a.setDirection(v.clone().normalize());
      a.setLength(length, Math.min(length * 0.4, headScale), Math.min(length * 0.2, headScale * 0.5));
    },
  };
}

export { THREE };

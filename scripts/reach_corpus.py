#!/usr/bin/env python3
"""Corpus of 40 ConReach loops for issue 46, and its runner.

  reach_corpus.py generate --out DIR [--seed S] [--legacy-steps]
  reach_corpus.py run --dir DIR --bin PATH [--timeout 300] [--out RESULTS.json] [--table RESULTS.md]

`generate` writes 40 deterministic `kind = "reach"` scenarios, loop_NN_<model>.toml: 28 PD loops
(J 1..2000 kg m^2 log-uniform with products of inertia up to ~10 % of the diagonal, k_p = w_n^2 J,
k_d = 2 zeta w_n J with zeta in [0.3, 2], reference offsets 90..170 deg for most and a few small
ones), 6 free rigid bodies (CubeSat to station, spins and tumbles) and 6 linear omega-dynamics
(stable and neutral matrices).  About half carry a pointing cone placed near the nominal
trajectory (integrated here with SciPy, conventions of docs/reach.md: R maps body to inertial,
J w' = -w x Jw + k_p sk(R^T R_g)^v - k_d w, R' = R w^); the others an omega-norm bound 10..50 %
above the largest |w| of sampled trajectories.  Without --legacy-steps the [reach] table has
only the horizon (the tool chooses steps itself, issue 46); with it, steps = 20, substeps = 10
and an integrator_step that today's binary accepts.

`run` runs `BIN reach FILE --out TMPDIR` on each file, one at a time, and summarises the
outcomes (exit code, verdict, wall time, soundness and the adversarial check).
"""

import argparse
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
import time

import numpy as np
from scipy.integrate import solve_ivp
from scipy.spatial.transform import Rotation

N_PD, N_FREE, N_LIN = 28, 6, 6
N_SAMPLES = 48  # boundary samples per loop for the "true" extremes of the safety quantities


# ----------------------------------------------------------------------------- dynamics

def hat(w):
    return np.array([[0.0, -w[2], w[1]], [w[2], 0.0, -w[0]], [-w[1], w[0], 0.0]])


def vee_skew(m):
    s = 0.5 * (m - m.T)
    return np.array([s[2, 1], s[0, 2], s[1, 0]])


def expm_so3(v):
    return Rotation.from_rotvec(v).as_matrix()


def make_rhs(loop):
    model = loop["model"]
    if model == "linear_omega":
        m = loop["matrix"]

        def f(t, x):
            r = x[:9].reshape(3, 3)
            w = x[9:]
            return np.concatenate([(r @ hat(w)).ravel(), m @ w])
        return f
    j = loop["J"]
    jinv = np.linalg.inv(j)
    kp = loop.get("kp", 0.0)
    kd = loop.get("kd", 0.0)
    rg = loop.get("Rg")

    def f(t, x):
        r = x[:9].reshape(3, 3)
        w = x[9:]
        tau = -np.cross(w, j @ w)
        if model == "pd":
            tau = tau + kp * vee_skew(r.T @ rg) - kd * w
        return np.concatenate([(r @ hat(w)).ravel(), jinv @ tau])
    return f


def simulate(loop, r0, w0, n_eval=1500):
    f = make_rhs(loop)
    t_end = loop["horizon"]
    ts = np.linspace(0.0, t_end, n_eval)
    sol = solve_ivp(f, (0.0, t_end), np.concatenate([r0.ravel(), w0]), method="DOP853",
                    t_eval=ts, rtol=1e-9, atol=1e-11)
    rs = sol.y[:9].T.reshape(-1, 3, 3)
    ws = sol.y[9:].T
    return sol.t, rs, ws


def boundary_samples(loop, rng, n):
    """States on the boundary of the initial set: R0 exp(a u^), w0 + b v (u, v unit)."""
    out = []
    for _ in range(n):
        u = rng.normal(size=3)
        v = rng.normal(size=3)
        u /= np.linalg.norm(u)
        v /= np.linalg.norm(v)
        out.append((loop["R0"] @ expm_so3(loop["a"] * u), loop["w0"] + loop["b"] * v))
    return out


def angles(rs, axis_b, dir_i):
    p = rs @ axis_b
    c = np.clip(p @ dir_i, -1.0, 1.0)
    return np.degrees(np.arccos(c))


def unit(v):
    v = np.asarray(v, dtype=float)
    return v / np.linalg.norm(v)


def perp(v, rng):
    x = rng.normal(size=3)
    x -= (x @ v) * v
    return unit(x)


# ----------------------------------------------------------------------------- loops

def random_inertia(rng, scale):
    """Diagonal log-spread within a factor ~2.5, products <= ~10 % of the diagonal; principal
    moments kept positive and within the triangle inequality (with 2 % to spare)."""
    digits = 6 - int(math.floor(math.log10(scale)))
    while True:
        d = scale * np.exp(rng.uniform(-0.45, 0.45, size=3))
        j = np.diag(d)
        frac = rng.uniform(0.0, 0.1, size=3) * rng.choice([-1.0, 1.0], size=3)
        for (k, (p, q)) in enumerate([(0, 1), (0, 2), (1, 2)]):
            j[p, q] = j[q, p] = frac[k] * math.sqrt(d[p] * d[q])
        j = np.round(j, digits)
        ev = np.linalg.eigvalsh(j)
        if ev[0] > 0 and ev[0] + ev[1] >= 1.02 * ev[2]:
            return j


def settling_tau(zeta, wn):
    """Slowest time constant of s^2 + 2 zeta wn s + wn^2."""
    if zeta < 1.0:
        return 1.0 / (zeta * wn)
    return 1.0 / (wn * (zeta - math.sqrt(zeta * zeta - 1.0)))


def stratified(rng, n, lo, hi, log=False):
    """n values, one per stratum of [lo, hi] (log scale if asked), in random order."""
    u = (np.arange(n) + rng.uniform(0.0, 1.0, size=n)) / n
    rng.shuffle(u)
    if log:
        return np.exp(np.log(lo) + u * (np.log(hi) - np.log(lo)))
    return lo + u * (hi - lo)


def pd_loops(rng):
    n = N_PD
    scales = stratified(rng, n, 1.0, 2000.0, log=True)
    zetas = stratified(rng, n, 0.3, 2.0)
    # natural frequency: fast for small craft, slow for large ones (a user's choice),
    # with a spread of a factor ~3 either way
    wn_base = 0.8 * scales ** -0.25
    wns = np.clip(wn_base * np.exp(stratified(rng, n, -1.0, 1.0)), 0.03, 2.0)
    n_small = 6
    offsets = np.concatenate([stratified(rng, n - n_small, 90.0, 170.0),
                              stratified(rng, n_small, 10.0, 60.0)])
    rng.shuffle(offsets)
    att = stratified(rng, n, 0.05, 0.3, log=True)
    horizon_mult = stratified(rng, n, 0.5, 4.0, log=True)
    loops = []
    for i in range(n):
        j = random_inertia(rng, scales[i])
        js = float(np.trace(j) / 3.0)
        zeta, wn = float(zetas[i]), float(wns[i])
        kp = wn * wn * js
        kd = 2.0 * zeta * wn * js
        tau = settling_tau(zeta, wn)
        horizon = float(np.clip(round(horizon_mult[i] * tau, 1), 2.0, 60.0))
        # omega set: the loop's own rate scale (wn times the offset), kept in 0.02..0.2 rad/s
        b = float(np.clip(round(rng.uniform(0.05, 0.25) * wn * max(1.0, math.radians(offsets[i])), 3),
                          0.02, 0.2))
        a = float(round(att[i], 3))
        r0 = Rotation.random(random_state=rng.integers(1 << 31)).as_matrix()
        axis = unit(rng.normal(size=3))
        rg = r0 @ expm_so3(math.radians(offsets[i]) * axis)
        if rng.uniform() < 0.5:
            w0 = np.zeros(3)
        else:
            w0 = unit(rng.normal(size=3)) * rng.uniform(0.1, 0.5) * wn
        why = []
        why.append("slow large craft" if scales[i] > 300 else
                   "small craft" if scales[i] < 10 else "mid-size craft")
        why.append("underdamped" if zeta < 0.7 else "near critical" if zeta < 1.2 else "overdamped")
        why.append("large slew" if offsets[i] >= 90 else "small offset")
        why.append("horizon %.2f x the slowest time constant" % (horizon / tau))
        loops.append(dict(model="pd", J=j, kp=kp, kd=kd, Rg=rg, R0=r0, w0=w0, a=a, b=b,
                          horizon=horizon, zeta=zeta, wn=wn, offset=float(offsets[i]),
                          tau=tau, why="; ".join(why)))
    return loops


def free_loops(rng):
    # (scale kg m^2, kind, |w| rad/s, horizon s)
    specs = [
        (0.03, "spin about the major axis (stable)", 0.5, 20.0),
        (0.2, "spin about the minor axis (stable)", 0.3, 30.0),
        (8.0, "near the intermediate axis (tumble, Dzhanibekov)", 0.2, 30.0),
        (150.0, "general tumble", 0.1, 40.0),
        (5e4, "slow spin of a large platform, mixed axes", 0.03, 60.0),
        (1e7, "station-scale slow tumble", 0.01, 60.0),
    ]
    loops = []
    for scale, kind, wmag, horizon in specs:
        j = random_inertia(rng, scale)
        ev, evec = np.linalg.eigh(j)  # ascending: minor (smallest J) first
        if "major" in kind:
            d = evec[:, 2]
        elif "minor" in kind:
            d = evec[:, 0]
        elif "intermediate" in kind:
            d = unit(evec[:, 1] + 0.05 * evec[:, 0])
        else:
            d = unit(rng.normal(size=3))
        w0 = wmag * d
        r0 = Rotation.random(random_state=rng.integers(1 << 31)).as_matrix()
        a = float(round(rng.uniform(0.05, 0.2), 3))
        b = float(round(float(np.clip(rng.uniform(0.1, 0.3) * wmag, 0.002, 0.05)), 4))
        loops.append(dict(model="free", J=j, R0=r0, w0=w0, a=a, b=b, horizon=horizon,
                          why="free body, J scale %.3g kg m^2: %s, |w0| = %.3g rad/s"
                              % (scale, kind, wmag)))
    return loops


def linear_loops(rng):
    def rot_part(wz):
        return np.array([[0.0, -wz, 0.0], [wz, 0.0, 0.0], [0.0, 0.0, 0.0]])
    specs = [
        ("stable diagonal", np.diag([-0.5, -1.5, -3.0]), 4.0),
        ("stable, lightly damped oscillation", np.diag([-0.1, -0.1, -0.8]) + rot_part(1.2), 10.0),
        ("stable non-normal (transient growth)", np.array([[-0.5, 2.0, 0.0], [0.0, -0.7, 1.0],
                                                          [0.0, 0.0, -1.0]]), 8.0),
        ("neutral: skew (rotation of w)", rot_part(0.8), 6.0),
        ("neutral: one zero eigenvalue, two stable", np.diag([0.0, -0.4, -1.0]), 10.0),
        ("stable, slow", np.array([[-0.05, 0.02, 0.0], [-0.02, -0.08, 0.01],
                                   [0.0, -0.01, -0.1]]), 40.0),
    ]
    loops = []
    for kind, m, horizon in specs:
        q = Rotation.random(random_state=rng.integers(1 << 31)).as_matrix()
        m = np.round(q @ m @ q.T, 6)
        r0 = Rotation.random(random_state=rng.integers(1 << 31)).as_matrix()
        wmag = rng.uniform(0.2, 0.8)
        w0 = unit(rng.normal(size=3)) * wmag
        a = float(round(rng.uniform(0.05, 0.3), 3))
        b = float(round(rng.uniform(0.02, 0.2), 3))
        loops.append(dict(model="linear_omega", matrix=m, R0=r0, w0=w0, a=a, b=b,
                          horizon=horizon, why="linear w-dynamics, %s; |w0| = %.2f rad/s"
                                               % (kind, wmag)))
    return loops


def add_safety(loop, rng, want_cone, violate):
    t, rs, ws = simulate(loop, loop["R0"], loop["w0"])
    samples = boundary_samples(loop, rng, N_SAMPLES)
    w0n = float(np.linalg.norm(loop["w0"]))
    if w0n > 0.0:  # the state of largest |w| at t = 0
        samples.append((loop["R0"], loop["w0"] * (1.0 + loop["b"] / w0n)))
    sims = [(rs, ws)] + [simulate(loop, r, w)[1:] for (r, w) in samples]
    # the initial set's own extremes (|w0| + b; the nominal's angle at t = 0 moved by a) bound
    # the sampled ones from below
    wmax = max([float(np.max(np.linalg.norm(w, axis=1))) for (_, w) in sims] + [w0n + loop["b"]])
    a_deg = math.degrees(loop["a"])
    loop["nominal_wmax"] = float(np.max(np.linalg.norm(ws, axis=1)))
    loop["sampled_wmax"] = wmax
    if not want_cone:
        f = rng.uniform(1.1, 1.5)
        loop["omega_norm_max"] = float(f"{f * wmax:.4g}")
        loop["safety_note"] = ("omega_norm_max %.0f %% above the largest |w| of the nominal, %d boundary "
                               "samples and |w0| + b (%.4g rad/s)" % (100 * (f - 1), N_SAMPLES, wmax))
        return
    axis_b = unit(rng.normal(size=3)) if rng.uniform() < 0.5 else np.eye(3)[rng.integers(3)]
    keep_in = rng.uniform() < 0.5
    m = rng.uniform(0.1, 0.4)
    if keep_in:
        # centre on the mean pointing of the body axis, half-angle just above the spread
        mean_dir = unit(np.mean(rs @ axis_b, axis=0))
        dirn = unit(mean_dir + 0.1 * perp(mean_dir, rng))
        worst = max([float(np.max(angles(r, axis_b, dirn))) for (r, _) in sims]
                    + [float(angles(rs[:1], axis_b, dirn)[0]) + a_deg])
        nom = float(np.max(angles(rs, axis_b, dirn)))
        if violate:
            half = 0.85 * nom
            note = "keep_in, half-angle 15 %% below the nominal's largest angle (%.1f deg): violated" % nom
        else:
            half = worst / (1.0 - m)
            note = ("keep_in, margin %.0f %% of the half-angle beyond the largest sampled angle "
                    "(%.1f deg)" % (100 * m, worst))
        typ = "keep_in"
        if half > 150.0:  # the axis sweeps too wide for a meaningful keep-in cone
            keep_in = False
    if not keep_in:
        # avoided direction next to the path: a point of the path at a random time, moved
        # 10..40 deg off it; of a few such candidates keep the one whose closest approach of
        # the sampled trajectories is nearest the intended 10..40 deg
        best = None
        for _ in range(12):
            k = rng.integers(len(t) // 5, len(t))
            p = rs[k] @ axis_b
            beta = rng.uniform(10.0, 40.0)
            d = unit(math.cos(math.radians(beta)) * p + math.sin(math.radians(beta)) * perp(p, rng))
            cl = min([float(np.min(angles(r, axis_b, d))) for (r, _) in sims]
                     + [float(angles(rs[:1], axis_b, d)[0]) - a_deg])
            score = abs(cl - beta) if cl >= 5.0 else 1e3 - cl
            if best is None or score < best[0]:
                best = (score, d, cl)
        _, dirn, closest = best
        nom = float(np.min(angles(rs, axis_b, dirn)))
        if violate:
            half = 1.15 * nom
            note = "keep_out, half-angle 15 %% beyond the nominal's closest approach (%.1f deg): violated" % nom
        else:
            half = closest / (1.0 + m)
            note = ("keep_out, margin %.0f %% of the half-angle inside the closest sampled approach "
                    "(%.1f deg)" % (100 * m, closest))
        typ = "keep_out"
    loop["cone"] = dict(type=typ, axis_b=axis_b, direction_i=dirn, half=float(f"{half:.4g}"))
    loop["safety_note"] = note


# ----------------------------------------------------------------------------- TOML

def fnum(x):
    x = float(x)
    if x == 0.0:
        return "0.0"
    s = repr(x)
    return s if ("." in s or "e" in s or "inf" in s or "nan" in s) else s + ".0"


def fvec(v):
    return "[" + ", ".join(fnum(x) for x in v) + "]"


def fmat(m):
    return "[" + ", ".join(fvec(r) for r in m) + "]"


def rot_table(r):
    rv = Rotation.from_matrix(r).as_rotvec()
    ang = float(np.linalg.norm(rv))
    if ang < 1e-12:
        return "{ axis = [1.0, 0.0, 0.0], angle_deg = 0.0 }"
    ax = rv / ang
    return "{ axis = %s, angle_deg = %s }" % (fvec(np.round(ax, 12)), fnum(round(math.degrees(ang), 10)))


def to_toml(idx, loop, legacy):
    name = "loop_%02d_%s" % (idx, loop["model"])
    L = []
    L.append("# Issue 46 corpus (scripts/reach_corpus.py generate): %s" % name)
    L.append("# %s" % loop["why"])
    if loop["model"] == "pd":
        js = float(np.trace(loop["J"]) / 3.0)
        L.append("# J scale %.4g kg m^2 (mean diagonal), zeta = %.3f, w_n = %.4g rad/s "
                 "(kp = w_n^2 J, kd = 2 zeta w_n J), offset from R_g = %.1f deg," % (
                     js, loop["zeta"], loop["wn"], loop["offset"]))
        L.append("# slowest time constant %.3g s, horizon %.4g s." % (loop["tau"], loop["horizon"]))
    L.append("# Initial set: a = %.3f rad, b = %.3f rad/s; nominal max |w| = %.4g rad/s." % (
        loop["a"], loop["b"], loop["nominal_wmax"]))
    L.append("# Safety: %s." % loop["safety_note"])
    L.append('kind = "reach"')
    L.append('name = "%s"' % name)
    L.append('description = "issue 46 corpus: %s"' % loop["why"].split(";")[0])
    L.append("")
    L.append("[system]")
    L.append('model = "%s"' % loop["model"])
    if loop["model"] == "linear_omega":
        L.append("matrix = %s" % fmat(loop["matrix"]))
    else:
        L.append("inertia = %s" % fmat(loop["J"]))
    if loop["model"] == "pd":
        L.append("kp = %s" % fnum(float(f"{loop['kp']:.6g}")))
        L.append("kd = %s" % fnum(float(f"{loop['kd']:.6g}")))
        L.append("reference = %s" % rot_table(loop["Rg"]))
    L.append("")
    L.append("[initial]")
    L.append("attitude = %s" % rot_table(loop["R0"]))
    L.append("attitude_radius = %s" % fnum(loop["a"]))
    L.append("omega_b = %s" % fvec(np.round(loop["w0"], 8)))
    L.append("omega_radius = %s" % fnum(loop["b"]))
    L.append("")
    L.append("[reach]")
    L.append("horizon = %s" % fnum(loop["horizon"]))
    if legacy:
        steps, sub = 20, 10
        h = min(0.01, loop["horizon"] / (steps * sub))
        h = math.floor(h * 1e6) / 1e6
        L.append("steps = %d" % steps)
        L.append("substeps = %d" % sub)
        L.append("integrator_step = %s" % fnum(h))
    L.append("")
    L.append("[soundness]")
    L.append("samples = 200")
    L.append("seed = 1")
    L.append("")
    if "cone" in loop:
        c = loop["cone"]
        L.append("[[safety.cones]]")
        L.append('name = "%s"' % ("near_path_in" if c["type"] == "keep_in" else "near_path_out"))
        L.append('type = "%s"' % c["type"])
        L.append("axis_b = %s" % fvec(np.round(c["axis_b"], 10)))
        L.append("direction_i = %s" % fvec(np.round(c["direction_i"], 10)))
        L.append("half_angle_deg = %s" % fnum(c["half"]))
        L.append("")
    else:
        L.append("[safety]")
        L.append("omega_norm_max = %s" % fnum(loop["omega_norm_max"]))
        L.append("")
    return name, "\n".join(L)


def generate(args):
    rng = np.random.default_rng(args.seed)
    loops = pd_loops(rng) + free_loops(rng) + linear_loops(rng)
    # interleave models a little so the numbering is not by model only: keep pd first
    n = len(loops)
    cone_flags = np.array([k % 2 == 0 for k in range(n)])
    rng.shuffle(cone_flags)
    cone_idx = [k for k in range(n) if cone_flags[k]]
    violate = set(rng.choice(cone_idx, size=4, replace=False).tolist())
    os.makedirs(args.out, exist_ok=True)
    for k, loop in enumerate(loops):
        add_safety(loop, rng, bool(cone_flags[k]), k in violate)
        name, text = to_toml(k + 1, loop, args.legacy_steps)
        with open(os.path.join(args.out, name + ".toml"), "w") as f:
            f.write(text)
    print("wrote %d scenarios to %s" % (n, args.out))


# ----------------------------------------------------------------------------- run

def first_line(s):
    for line in s.splitlines():
        if line.strip():
            return line.strip()
    return ""


def run_one(path, binary, timeout):
    out = tempfile.mkdtemp(prefix="reach_corpus_")
    rec = dict(file=os.path.basename(path), name=os.path.splitext(os.path.basename(path))[0])
    rec["model"] = rec["name"].split("_", 2)[2] if rec["name"].count("_") >= 2 else ""
    t0 = time.monotonic()
    try:
        p = subprocess.Popen([binary, "reach", path, "--out", out], stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, text=True, start_new_session=True)
        try:
            _, err = p.communicate(timeout=timeout)
            rec["exit"] = p.returncode
        except subprocess.TimeoutExpired:
            os.killpg(p.pid, 9)
            _, err = p.communicate()
            rec["exit"] = None
            rec["timeout"] = True
        rec["stderr"] = first_line(err or "")
    finally:
        rec["wall_s"] = round(time.monotonic() - t0, 2)
    jp = os.path.join(out, "reach.json")
    if os.path.exists(jp) and not rec.get("timeout"):
        try:
            with open(jp) as f:
                r = json.load(f)
            adv = r.get("adversarial") or {}
            snd = r.get("soundness") or {}
            rec.update(verdict=r.get("verdict"), first_failure_time=r.get("first_failure_time"),
                       cells=r.get("cells"), n_steps=r.get("n_steps"),
                       sdp_solves=r.get("sdp_solves"), worst_ratio=adv.get("worst_ratio"),
                       attitude_tightness=adv.get("attitude_tightness"),
                       soundness_inside=snd.get("inside"), soundness_samples=snd.get("samples"))
        except (OSError, ValueError) as e:
            rec["json_error"] = str(e)
    shutil.rmtree(out, ignore_errors=True)
    return rec


def outcome(rec):
    if rec.get("timeout"):
        return "timeout"
    if rec["exit"] == 0 and rec.get("verdict") == "safe":
        return "safe"
    if rec["exit"] == 4 and rec.get("verdict") == "cannot_prove":
        return "cannot_prove"
    if rec["exit"] in (2, 3, 4):
        return "exit %d" % rec["exit"]
    return "exit %s" % rec["exit"]


def escape(rec):
    wr = rec.get("worst_ratio")
    si, ss = rec.get("soundness_inside"), rec.get("soundness_samples")
    return (wr is not None and wr > 1.0) or (si is not None and ss is not None and si < ss)


def fmt(x, nd=3):
    if x is None:
        return "–"
    if isinstance(x, float):
        return ("%." + str(nd) + "g") % x
    return str(x)


def run(args):
    files = sorted(f for f in os.listdir(args.dir) if f.endswith(".toml"))
    recs = []
    for f in files:
        rec = run_one(os.path.join(args.dir, f), args.bin, args.timeout)
        rec["outcome"] = outcome(rec)
        recs.append(rec)
        print("%-26s %-13s %7.1f s  %s" % (rec["name"], rec["outcome"], rec["wall_s"],
                                          rec["stderr"][:110]), flush=True)
        if args.out:  # write as we go, so a partial run leaves a usable file
            with open(args.out, "w") as fo:
                json.dump(dict(binary=args.bin, timeout=args.timeout, runs=recs), fo, indent=1)
    counts = {}
    for r in recs:
        counts[r["outcome"]] = counts.get(r["outcome"], 0) + 1
    n = len(recs)
    verdicts = counts.get("safe", 0) + counts.get("cannot_prove", 0)
    esc = [r["name"] for r in recs if escape(r)]
    summary = dict(total=n, counts=counts, verdict_share=verdicts / n if n else 0.0, escapes=esc)
    order = ["safe", "cannot_prove", "exit 3", "exit 2", "timeout"]
    order += sorted(k for k in counts if k not in order)
    print("\noutcomes: " + ", ".join("%s %d" % (k, counts.get(k, 0)) for k in order))
    print("verdict share: %d/%d = %.1f %%" % (verdicts, n, 100.0 * verdicts / n if n else 0.0))
    if esc:
        print("!!! ESCAPES (worst_ratio > 1 or soundness inside < samples): " + ", ".join(esc))
    else:
        print("escapes: none (among the runs that wrote reach.json)")
    if args.out:
        with open(args.out, "w") as fo:
            json.dump(dict(binary=args.bin, timeout=args.timeout, summary=summary, runs=recs),
                      fo, indent=1)
    if args.table:
        L = ["| loop | model | exit | verdict | first failure t | cells | steps | worst ratio "
             "| tightness | inside | wall s | stderr (first line) |",
             "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
        for r in recs:
            inside = ("%s/%s" % (r.get("soundness_inside"), r.get("soundness_samples"))
                      if r.get("soundness_samples") is not None else "–")
            L.append("| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %.1f | %s |" % (
                r["name"], r["model"], "timeout" if r.get("timeout") else r["exit"],
                fmt(r.get("verdict")), fmt(r.get("first_failure_time")), fmt(r.get("cells")),
                fmt(r.get("n_steps")), fmt(r.get("worst_ratio")),
                fmt(r.get("attitude_tightness")), inside, r["wall_s"],
                r["stderr"].replace("|", "\\|")[:140]))
        L.append("")
        L.append("Outcomes: " + ", ".join("%s %d" % (k, counts.get(k, 0)) for k in order)
                 + "; verdict share %d/%d; escapes: %s." % (verdicts, n, ", ".join(esc) or "none"))
        with open(args.table, "w") as fo:
            fo.write("\n".join(L) + "\n")
    return 1 if esc else 0


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    sub = ap.add_subparsers(dest="cmd", required=True)
    g = sub.add_parser("generate")
    g.add_argument("--out", required=True)
    g.add_argument("--seed", type=int, default=46)
    g.add_argument("--legacy-steps", action="store_true")
    r = sub.add_parser("run")
    r.add_argument("--dir", required=True)
    r.add_argument("--bin", required=True)
    r.add_argument("--timeout", type=float, default=300.0)
    r.add_argument("--out")
    r.add_argument("--table")
    args = ap.parse_args()
    if args.cmd == "generate":
        generate(args)
        return 0
    return run(args)


if __name__ == "__main__":
    sys.exit(main())

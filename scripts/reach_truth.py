#!/usr/bin/env python3
"""The truth of ConReach loops, measured without attiguard (issue 47, "proved where it is true").

  reach_truth.py measure --dir DIR --out TRUTH.json [--samples N] [--boundary N] [--starts K]
                         [--times N] [--seed S] [--only NAME ...]
  reach_truth.py join --truth TRUTH.json --results R.json --out TABLE.md

`measure` reads every `kind = "reach"` scenario DIR/*.toml (models `pd`, `free`,
`constant_torque`, `linear_omega`; conventions of docs/reach.md: R maps body to inertial,
R' = R w^, J w' = -w x Jw + tau with tau = k_p sk(R^T R_g)^v - k_d w for `pd`, tau = torque_b for
`constant_torque`, 0 for `free`; w' = M w for `linear_omega`; the initial set is
{R0 exp(eta^) : |eta| <= a} x {w : |w - w0| <= b}) and, for each safety functional g of the
loop, estimates  min over the initial set x [0, T] of g  where g is the signed margin:

  keep_out cone  angle(R axis_b, direction_i) - half_angle      [deg]
  keep_in cone   half_angle - angle(R axis_b, direction_i)      [deg]
  omega_norm_max bound - |w|                                    [rad/s]
  omega_abs_max  bound_k - |w_k|, one functional per k          [rad/s]

The estimate (the "truth") is the smallest margin found, an upper bound on the true minimum:
 (a) sampling: --samples initial states uniform in the set (eta and w - w0 uniform in their
     balls) plus --boundary states on its boundary (|eta| = a and |w - w0| = b) and the centre;
     each trajectory integrated by SciPy solve_ivp (DOP853, rtol 1e-10, atol 1e-12, dense
     output; trajectories batched by the hundred with a vectorised right-hand side that is
     checked against scripts/reach_corpus.py's make_rhs at start), g evaluated on --times
     (>= 400) equally spaced times including 0 and T, and each trajectory's minimum refined in
     time by a bounded scalar minimisation on the dense output around the grid's minimum;
 (b) multi-start local minimisation of the worst-over-time margin w.r.t. the initial state:
     eta = a tanh(|u|) u/|u|, w - w0 = b tanh(|v|) v/|v| with (u, v) in R^6 free, Nelder-Mead
     from the --starts worst distinct samples; every evaluation integrates one trajectory alone
     (reach_corpus.make_rhs, DOP853, rtol 1e-10, atol 1e-12, dense output) and refines its
     minimum in time as in (a). The reported worst state is re-integrated alone.

Per functional TRUTH.json records the worst margin, the bound (the half-angle for cones), the
margin as % of the bound, the sampling-only worst, the state (eta, w - w0, R as a rotation
vector, w) and time where it occurs. Per loop: its class, "violates" (some worst margin < 0),
"roomy" (every functional's margin >= 10 % of its bound) or "tight" (otherwise), and the smallest
margin %. The seed is fixed (--seed, 47), so the measurement is reproducible.

`join` reads TRUTH.json and the output of `scripts/reach_corpus.py run ... --out R.json`
(per loop: outcome, verdict, exit, adversarial attitude_tightness, first line of stderr) and
writes a markdown table (loop, class, worst margin %, verdict, tightness, why not) with summary
lines: roomy loops and how many are proved `safe`, violating loops and whether any is `safe`
(never allowed), tight loops, and the median / worst attitude tightness over the `safe` ones.
It prints the summary and exits 1 when a violating loop is `safe`.
"""

import argparse
import json
import math
import os
import sys
import time
import tomllib

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import minimize, minimize_scalar
from scipy.spatial.transform import Rotation

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import reach_corpus as rc  # noqa: E402  (dynamics: make_rhs, hat, vee_skew, expm_so3)

RTOL, ATOL = 1e-10, 1e-12
CHUNK = 100          # trajectories per batched solve_ivp call
ROOMY_PCT = 10.0     # "roomy": every margin >= 10 % of its bound


# ----------------------------------------------------------------------------- scenario

def rotation(tab):
    """A rotation table of docs/scenario-format.md section 3 as a matrix (body -> inertial)."""
    if "matrix" in tab:
        return np.array(tab["matrix"], dtype=float)
    if "quaternion" in tab:
        w, x, y, z = tab["quaternion"]
        return Rotation.from_quat([x, y, z, w]).as_matrix()
    if "rotation_vector" in tab:
        return rc.expm_so3(np.array(tab["rotation_vector"], dtype=float))
    axis = rc.unit(tab["axis"])
    ang = math.radians(tab["angle_deg"]) if "angle_deg" in tab else float(tab["angle"])
    return rc.expm_so3(ang * axis)


def inertia(v):
    j = np.array(v, dtype=float)
    return np.diag(j) if j.ndim == 1 else j


def read_loop(path):
    """A reach scenario as the dict of reach_corpus.make_rhs plus the initial set, horizon and
    the list of safety functionals."""
    with open(path, "rb") as f:
        d = tomllib.load(f)
    if d.get("kind") != "reach":
        raise ValueError("%s: not a reach scenario" % path)
    s, ini = d["system"], d.get("initial", {})
    loop = dict(name=d.get("name", os.path.splitext(os.path.basename(path))[0]),
                file=os.path.basename(path), model=s["model"])
    if loop["model"] == "linear_omega":
        loop["matrix"] = np.array(s["matrix"], dtype=float)
    else:
        loop["J"] = inertia(s["inertia"])
    if loop["model"] == "pd":
        loop.update(kp=float(s["kp"]), kd=float(s["kd"]), Rg=rotation(s["reference"]))
    loop["torque"] = (np.array(s["torque_b"], dtype=float) if loop["model"] == "constant_torque"
                      else np.zeros(3))
    loop["R0"] = rotation(ini.get("attitude", {"matrix": np.eye(3).tolist()}))
    loop["a"] = float(ini["attitude_radius"])
    loop["w0"] = np.array(ini["omega_b"], dtype=float)
    loop["b"] = float(ini["omega_radius"])
    loop["horizon"] = float(d["reach"]["horizon"])
    funcs = []
    saf = d.get("safety", {})
    for k, c in enumerate(saf.get("cones", [])):
        half = (float(c["half_angle_deg"]) if "half_angle_deg" in c
                else math.degrees(float(c["half_angle"])))
        typ = c.get("type", "keep_in")
        funcs.append(dict(name="%s cone %s" % (typ.replace("_", "-"), c.get("name", "cone%d" % k)),
                          kind=typ, axis_b=rc.unit(c["axis_b"]), direction_i=rc.unit(c["direction_i"]),
                          bound=half, unit="deg"))
    if "omega_norm_max" in saf:
        funcs.append(dict(name="omega_norm_max", kind="omega_norm",
                          bound=float(saf["omega_norm_max"]), unit="rad/s"))
    if "omega_abs_max" in saf:
        for k, v in enumerate(saf["omega_abs_max"]):
            funcs.append(dict(name="omega_abs_max[%d]" % k, kind="omega_abs", k=k,
                              bound=float(v), unit="rad/s"))
    loop["functionals"] = funcs
    return loop


def single_rhs(loop):
    """reach_corpus.make_rhs, plus the constant torque it does not model."""
    f = rc.make_rhs(loop)
    if loop["model"] != "constant_torque":
        return f
    extra = np.concatenate([np.zeros(9), np.linalg.solve(loop["J"], loop["torque"])])
    return lambda t, x: f(t, x) + extra


def batch_rhs(loop, n):
    """Vectorised right-hand side of n stacked 12-states (R row-major, w), same dynamics."""
    model = loop["model"]
    if model == "linear_omega":
        mt = loop["matrix"].T
    else:
        j = loop["J"]
        jinv_t = np.linalg.inv(j).T
        kp, kd, rg = loop.get("kp", 0.0), loop.get("kd", 0.0), loop.get("Rg")
        tq = loop["torque"]

    def f(t, y):
        x = y.reshape(n, 12)
        r = x[:, :9].reshape(n, 3, 3)
        w = x[:, 9:]
        out = np.empty_like(x)
        # R w^: column j of R w^ is R (w x e_j)
        rd = out[:, :9].reshape(n, 3, 3)
        rd[:, :, 0] = r[:, :, 1] * w[:, 2:3] - r[:, :, 2] * w[:, 1:2]
        rd[:, :, 1] = r[:, :, 2] * w[:, 0:1] - r[:, :, 0] * w[:, 2:3]
        rd[:, :, 2] = r[:, :, 0] * w[:, 1:2] - r[:, :, 1] * w[:, 0:1]
        out[:, :9] = rd.reshape(n, 9)
        if model == "linear_omega":
            out[:, 9:] = w @ mt
        else:
            tau = -np.cross(w, w @ j.T) + tq
            if model == "pd":
                e = np.einsum("nki,kj->nij", r, rg)  # R^T R_g
                sk = 0.5 * np.stack([e[:, 2, 1] - e[:, 1, 2], e[:, 0, 2] - e[:, 2, 0],
                                     e[:, 1, 0] - e[:, 0, 1]], axis=1)
                tau = tau + kp * sk - kd * w
            out[:, 9:] = tau @ jinv_t
        return out.reshape(-1)
    return f


def check_batch_rhs(loop, rng):
    """The batched right-hand side agrees with the single one at random states."""
    n = 5
    xs = []
    for _ in range(n):
        r = Rotation.random(random_state=rng.integers(1 << 31)).as_matrix()
        xs.append(np.concatenate([r.ravel(), rng.normal(size=3)]))
    y = np.concatenate(xs)
    fb = batch_rhs(loop, n)(0.0, y).reshape(n, 12)
    fs = single_rhs(loop)
    for k in range(n):
        ref = fs(0.0, xs[k])
        if not np.allclose(fb[k], ref, rtol=1e-12, atol=1e-12 * (1.0 + np.max(np.abs(ref)))):
            raise AssertionError("batched right-hand side differs from reach_corpus.make_rhs on "
                                 + loop["name"])


# ----------------------------------------------------------------------------- functionals

def margin(func, r, w):
    """Signed margin of one functional at states r (..., 3, 3), w (..., 3)."""
    kind = func["kind"]
    if kind in ("keep_in", "keep_out"):
        p = r @ func["axis_b"]
        d = func["direction_i"]
        ang = np.degrees(np.arctan2(np.linalg.norm(np.cross(p, d), axis=-1), p @ d))
        return ang - func["bound"] if kind == "keep_out" else func["bound"] - ang
    if kind == "omega_norm":
        return func["bound"] - np.linalg.norm(w, axis=-1)
    return func["bound"] - np.abs(w[..., func["k"]])


def initial_state(loop, eta, dw):
    return loop["R0"] @ rc.expm_so3(eta), loop["w0"] + dw


def refine_time(fun, ts, k):
    """min of fun(t) near the grid minimum ts[k]: bounded scalar minimisation on
    [ts[k-1], ts[k+1]]; returns (value, t), never worse than the grid value."""
    best = (float(fun(ts[k])), float(ts[k]))
    lo, hi = ts[max(k - 1, 0)], ts[min(k + 1, len(ts) - 1)]
    if hi > lo:
        res = minimize_scalar(fun, bounds=(lo, hi), method="bounded",
                              options=dict(xatol=1e-9 * max(1.0, ts[-1])))
        if res.fun < best[0]:
            best = (float(res.fun), float(res.x))
    return best


# ----------------------------------------------------------------------------- sampling

def sample_set(loop, rng, n_uniform, n_boundary):
    """(eta, dw) pairs: the centre, n_uniform uniform in the balls, n_boundary on both spheres."""
    def ball(n, rad):
        v = rng.normal(size=(n, 3))
        v /= np.linalg.norm(v, axis=1, keepdims=True)
        return v * (rad * rng.uniform(size=(n, 1)) ** (1.0 / 3.0))

    def sphere(n, rad):
        v = rng.normal(size=(n, 3))
        return rad * v / np.linalg.norm(v, axis=1, keepdims=True)
    etas = np.concatenate([np.zeros((1, 3)), ball(n_uniform, loop["a"]), sphere(n_boundary, loop["a"])])
    dws = np.concatenate([np.zeros((1, 3)), ball(n_uniform, loop["b"]), sphere(n_boundary, loop["b"])])
    return etas, dws


def sample_margins(loop, etas, dws, n_times):
    """Per functional, per sample: the worst margin over [0, T] (grid min refined in time) and
    its time."""
    T = loop["horizon"]
    ts = np.linspace(0.0, T, n_times)
    nf = len(loop["functionals"])
    n = len(etas)
    worst = np.full((nf, n), np.inf)
    when = np.zeros((nf, n))
    for c0 in range(0, n, CHUNK):
        idx = range(c0, min(c0 + CHUNK, n))
        m = len(idx)
        y0 = np.concatenate([np.concatenate([r.ravel(), w]) for (r, w) in
                             (initial_state(loop, etas[i], dws[i]) for i in idx)])
        sol = solve_ivp(batch_rhs(loop, m), (0.0, T), y0, method="DOP853", t_eval=ts,
                        dense_output=True, rtol=RTOL, atol=ATOL)
        if sol.status != 0:
            raise RuntimeError("%s: solve_ivp failed: %s" % (loop["name"], sol.message))
        y = sol.y.reshape(m, 12, len(ts))
        rs = np.transpose(y[:, :9, :], (0, 2, 1)).reshape(m, len(ts), 3, 3)
        ws = np.transpose(y[:, 9:, :], (0, 2, 1))
        for fi, func in enumerate(loop["functionals"]):
            g = margin(func, rs, ws)  # (m, nt)
            ks = np.argmin(g, axis=1)
            for jj, i in enumerate(idx):
                def fun(t, jj=jj):
                    x = sol.sol(t)[12 * jj:12 * jj + 12]
                    return float(margin(func, x[:9].reshape(3, 3), x[9:]))
                worst[fi, i], when[fi, i] = refine_time(fun, ts, int(ks[jj]))
    return worst, when


# ----------------------------------------------------------------------------- ascent

def to_params(eta, dw, a, b):
    """(u, v) with eta = a tanh(|u|) u/|u| (and the same for dw, b); only the non-degenerate
    radii have parameters."""
    out = []
    for x, rad in ((eta, a), (dw, b)):
        if rad <= 0.0:
            continue
        nx = float(np.linalg.norm(x))
        s = min(nx / rad, 0.995)
        out.append(np.zeros(3) if nx == 0.0 else math.atanh(s) * x / nx)
    return np.concatenate(out)


def from_params(p, a, b):
    def squash(u, rad):
        nu = float(np.linalg.norm(u))
        return np.zeros(3) if nu == 0.0 else rad * math.tanh(nu) * u / nu
    k = 0
    eta = dw = np.zeros(3)
    if a > 0.0:
        eta, k = squash(p[0:3], a), 3
    if b > 0.0:
        dw = squash(p[k:k + 3], b)
    return eta, dw


def trajectory_worst(loop, func, eta, dw, n_times, rhs=None):
    """The worst margin of one functional along one trajectory (integrated alone) and its time."""
    T = loop["horizon"]
    r0, w0 = initial_state(loop, eta, dw)
    sol = solve_ivp(rhs or single_rhs(loop), (0.0, T), np.concatenate([r0.ravel(), w0]),
                    method="DOP853", dense_output=True, rtol=RTOL, atol=ATOL)
    ts = np.linspace(0.0, T, n_times)
    y = sol.sol(ts)
    g = margin(func, y[:9].T.reshape(-1, 3, 3), y[9:].T)
    k = int(np.argmin(g))

    def fun(t):
        x = sol.sol(t)
        return float(margin(func, x[:9].reshape(3, 3), x[9:]))
    return refine_time(fun, ts, k)


def ascent(loop, func, starts, n_times, maxfev):
    """Nelder-Mead on the worst-over-time margin from each start (eta, dw); returns the best
    (value, eta, dw) and the number of evaluations."""
    a, b = loop["a"], loop["b"]
    rhs = single_rhs(loop)
    nev = [0]
    best = [np.inf, None, None]

    def obj(p):
        eta, dw = from_params(p, a, b)
        v, _ = trajectory_worst(loop, func, eta, dw, n_times, rhs)
        nev[0] += 1
        if v < best[0]:
            best[:] = [v, eta, dw]
        return v
    for eta, dw in starts:
        x0 = to_params(eta, dw, a, b)
        dim = len(x0)
        simplex = np.vstack([x0] + [x0 + 0.3 * np.eye(dim)[i] for i in range(dim)])
        minimize(obj, x0, method="Nelder-Mead",
                 options=dict(initial_simplex=simplex, maxfev=maxfev, xatol=1e-4, fatol=1e-9))
    return best[0], best[1], best[2], nev[0]


# ----------------------------------------------------------------------------- measure

def measure_loop(loop, args, rng):
    t0 = time.monotonic()
    check_batch_rhs(loop, rng)
    etas, dws = sample_set(loop, rng, args.samples, args.boundary)
    worst, when = sample_margins(loop, etas, dws, args.times)
    out = []
    for fi, func in enumerate(loop["functionals"]):
        order = np.argsort(worst[fi])
        starts, seen = [], []
        for i in order:  # the worst samples, at least 1e-3 of the set's size apart
            z = np.concatenate([etas[i] / max(loop["a"], 1e-300), dws[i] / max(loop["b"], 1e-300)])
            if all(np.linalg.norm(z - s) > 1e-3 for s in seen):
                seen.append(z)
                starts.append((etas[i], dws[i]))
            if len(starts) >= args.starts:
                break
        s_best = int(order[0])
        val, eta, dw, nev = ascent(loop, func, starts, args.times, args.maxfev)
        if not (val < worst[fi, s_best]):
            eta, dw = etas[s_best], dws[s_best]
        # the reported state, re-integrated alone
        v, t = trajectory_worst(loop, func, eta, dw, args.times)
        r0, w0 = initial_state(loop, eta, dw)
        bound = func["bound"]
        out.append(dict(
            name=func["name"], kind=func["kind"], unit=func["unit"], bound=bound,
            worst_margin=v, margin_pct=100.0 * v / bound,
            sampling_worst_margin=float(worst[fi, s_best]),
            sampling_worst_time=float(when[fi, s_best]),
            ascent_evaluations=nev, time=t,
            eta=eta.tolist(), eta_norm_over_a=(float(np.linalg.norm(eta)) / loop["a"]
                                               if loop["a"] > 0 else 0.0),
            domega=dw.tolist(), domega_norm_over_b=(float(np.linalg.norm(dw)) / loop["b"]
                                                    if loop["b"] > 0 else 0.0),
            R0_rotvec=Rotation.from_matrix(r0).as_rotvec().tolist(), omega0=w0.tolist()))
    pcts = [f["margin_pct"] for f in out]
    if any(f["worst_margin"] < 0.0 for f in out):
        cls = "violates"
    elif all(p >= ROOMY_PCT for p in pcts):
        cls = "roomy"
    else:
        cls = "tight"
    return dict(name=loop["name"], file=loop["file"], model=loop["model"], horizon=loop["horizon"],
                a=loop["a"], b=loop["b"], samples=len(etas), cls=cls,
                worst_margin_pct=min(pcts) if pcts else None, functionals=out,
                wall_s=round(time.monotonic() - t0, 2))


def measure(args):
    if args.times < 400 and not args.allow_few_times:
        raise SystemExit("--times must be >= 400")
    files = sorted(f for f in os.listdir(args.dir) if f.endswith(".toml"))
    if args.only:
        files = [f for f in files if os.path.splitext(f)[0] in args.only or f in args.only]
    recs = []
    t0 = time.monotonic()
    for f in files:
        loop = read_loop(os.path.join(args.dir, f))
        # one generator per loop (seed, index in the sorted list): a loop's figures do not depend
        # on which others are measured with it
        rng = np.random.default_rng([args.seed, sorted(os.listdir(args.dir)).index(f)])
        if not loop["functionals"]:
            print("%-26s no safety functional, skipped" % loop["name"], flush=True)
            continue
        rec = measure_loop(loop, args, rng)
        recs.append(rec)
        fs = rec["functionals"]
        print("%-26s %-8s worst %7.2f %% (%s; sampling %.4g, ascent %.4g %s, %d evals)  %6.1f s"
              % (rec["name"], rec["cls"], rec["worst_margin_pct"], fs[0]["name"],
                 fs[0]["sampling_worst_margin"], fs[0]["worst_margin"], fs[0]["unit"],
                 fs[0]["ascent_evaluations"], rec["wall_s"]), flush=True)
    counts = {}
    for r in recs:
        counts[r["cls"]] = counts.get(r["cls"], 0) + 1
    doc = dict(generator="scripts/reach_truth.py measure", dir=args.dir,
               settings=dict(samples_uniform=args.samples, samples_boundary=args.boundary,
                             starts=args.starts, maxfev_per_start=args.maxfev, times=args.times,
                             seed=args.seed, rtol=RTOL, atol=ATOL, method="DOP853",
                             roomy_pct=ROOMY_PCT),
               counts=counts, wall_s=round(time.monotonic() - t0, 1), loops=recs)
    with open(args.out, "w") as fo:
        json.dump(doc, fo, indent=1)
        fo.write("\n")
    print("classes: " + ", ".join("%s %d" % kv for kv in sorted(counts.items()))
          + "; %.0f s" % doc["wall_s"])
    return 0


# ----------------------------------------------------------------------------- join

fmt = rc.fmt  # one number formatter for both tables


def why_kind(run, outcome):
    """The reason a run is not `safe`, in a few words."""
    if run is None:
        return "not run"
    if outcome == "safe":
        return ""
    if outcome == "timeout":
        return "timeout"
    err = run.get("stderr") or ""
    if "no a priori enclosure" in err:
        return "the a priori enclosure diverges (the set does not contract)"
    if "cannot be proved on" in err:
        return "an enclosure too loose for the bound"
    return outcome


def join(args):
    with open(args.truth) as f:
        truth = json.load(f)
    with open(args.results) as f:
        res = json.load(f)
    runs = {r["name"]: r for r in res["runs"]}
    rows, L = [], []
    L.append("| loop | class | worst margin % (functional) | at t [s] | outcome | tightness "
             "| why not `safe` (first line of stderr) |")
    L.append("| --- | --- | --- | --- | --- | --- | --- |")
    for t in truth["loops"]:
        r = runs.get(t["name"])
        outcome = r["outcome"] if r else "not run"
        tight = r.get("attitude_tightness") if r else None
        why = ""
        if outcome != "safe":
            why = (r.get("stderr") or "") if r else "no result"
            for prefix in ("attiguard: error: ", "reach: ", "safety cannot be proved: "):
                if why.startswith(prefix):
                    why = why[len(prefix):]
            why = why.replace("; use more sub-steps, a smaller initial set or a shorter horizon", "")
            why = why.replace("|", "\\|")[:150]
        worst_f = min(t["functionals"], key=lambda f: f["margin_pct"])
        L.append("| %s | %s | %.1f (%s) | %s | %s | %s | %s |" % (
            t["name"], t["cls"], t["worst_margin_pct"], worst_f["name"], fmt(worst_f["time"]),
            outcome, fmt(tight), why))
        rows.append(dict(name=t["name"], cls=t["cls"], outcome=outcome, tight=tight,
                         why=why_kind(r, outcome)))

    def sel(cls):
        return [x for x in rows if x["cls"] == cls]
    roomy, viol, tightc = sel("roomy"), sel("violates"), sel("tight")
    safe_of = lambda xs: [x for x in xs if x["outcome"] == "safe"]  # noqa: E731
    rs, vs, ts_ = safe_of(roomy), safe_of(viol), safe_of(tightc)
    tights = sorted(x["tight"] for x in rows if x["outcome"] == "safe" and x["tight"] is not None)
    S = []
    S.append("Roomy loops (every margin >= %g %% of its bound): %d, proved `safe`: %d (%.0f %%)%s."
             % (truth["settings"]["roomy_pct"], len(roomy), len(rs),
                100.0 * len(rs) / len(roomy) if roomy else 0.0,
                (": " + ", ".join(x["name"] for x in rs)) if rs else ""))
    S.append("Violating loops (truth < 0 somewhere): %d (%s); `safe` among them: %d%s."
             % (len(viol), ", ".join(x["name"] for x in viol) or "none", len(vs),
                " (" + ", ".join(x["name"] for x in vs) + ") !!!" if vs else " (none, as required)"))
    S.append("Tight loops (0 <= margin < %g %%): %d, proved `safe`: %d%s."
             % (truth["settings"]["roomy_pct"], len(tightc), len(ts_),
                (" (" + ", ".join(x["name"] for x in ts_) + ")") if ts_ else ""))
    unproved = [x for x in roomy if x["outcome"] != "safe"]
    if unproved:
        kinds = {}
        for x in unproved:
            kinds.setdefault(x["why"], []).append(x["name"])
        S.append("Roomy loops not proved, why: " + "; ".join(
            "%s: %d (%s)" % (k, len(v), ", ".join(v)) for k, v in sorted(kinds.items())) + ".")
    if tights:
        S.append("Attitude tightness over the %d `safe` loops: median %.3g, worst %.3g."
                 % (len(tights), float(np.median(tights)), tights[-1]))
    else:
        S.append("Attitude tightness: no `safe` loop.")
    S.append("Results: %s (binary %s); truth: %s (seed %d, %d + %d samples, %d starts)."
             % (os.path.basename(args.results), res.get("binary"), os.path.basename(args.truth),
                truth["settings"]["seed"], truth["settings"]["samples_uniform"],
                truth["settings"]["samples_boundary"], truth["settings"]["starts"]))
    text = "\n".join(L) + "\n\n" + "\n".join("- " + s for s in S) + "\n"
    with open(args.out, "w") as fo:
        fo.write(text)
    print("\n".join(S))
    return 1 if vs else 0


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    sub = ap.add_subparsers(dest="cmd", required=True)
    m = sub.add_parser("measure", help="the worst margin of every safety functional of each loop")
    m.add_argument("--dir", required=True, help="directory of kind = \"reach\" scenarios")
    m.add_argument("--out", required=True, help="TRUTH.json")
    m.add_argument("--samples", type=int, default=2000, help="uniform samples of the set (2000)")
    m.add_argument("--boundary", type=int, default=1000, help="samples on its boundary (1000)")
    m.add_argument("--starts", type=int, default=8, help="starts of the local ascent (8)")
    m.add_argument("--maxfev", type=int, default=120, help="evaluations per start (120)")
    m.add_argument("--times", type=int, default=400, help="time grid per trajectory (>= 400)")
    m.add_argument("--allow-few-times", action="store_true", help=argparse.SUPPRESS)
    m.add_argument("--seed", type=int, default=47)
    m.add_argument("--only", nargs="*", help="loop names (file stems) to measure")
    j = sub.add_parser("join", help="the truth joined with reach_corpus.py run's results")
    j.add_argument("--truth", required=True)
    j.add_argument("--results", required=True)
    j.add_argument("--out", required=True, help="TABLE.md")
    args = ap.parse_args()
    return measure(args) if args.cmd == "measure" else join(args)


if __name__ == "__main__":
    sys.exit(main())
